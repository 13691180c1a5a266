// A member of a glTF JSON object as tinygltf holds it (tinygltf::Value), or a null Value when the
// object lacks the key or is not an object: the VRM readers walk optional, nested extension
// fields with it and test the result's type, so a missing or mistyped field reads as absent.
#pragma once
#include <fstream>  // as in gltf_reader.cpp: tiny_gltf.h needs it with TINYGLTF_NO_FS

#include "io/tiny_gltf_config.hpp"

namespace inkshade::io {

inline const tinygltf::Value& member(const tinygltf::Value& object, const char* key) {
    static const tinygltf::Value none;
    return object.IsObject() && object.Has(key) ? object.Get(key) : none;
}

}  // namespace inkshade::io
