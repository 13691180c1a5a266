// Instrumented copies of the parsers Inkshade takes from Debian shared libraries (tinyobjloader,
// toml++, stb_image), built from the same headers: linked into the fuzzers, they replace the
// libraries' uninstrumented code, so coverage guidance and AddressSanitizer reach inside them.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#define TOML_EXCEPTIONS 1  // as src/styles/style.cpp
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
