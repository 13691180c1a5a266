// tiny_gltf.h as gltf_container.cpp compiles it (TINYGLTF_IMPLEMENTATION there): images decoded
// by texture_image.cpp, never written, external files opened by the reader's callbacks, no
// wordexp() path expansion. The other glTF files include this for the declarations, so every
// translation unit sees the same configuration.
#pragma once
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <tiny_gltf.h>
