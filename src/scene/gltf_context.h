// What every glTF conversion step shares: the parsed model and the one-line error format.
#pragma once

#include <cstddef>
#include <string>

#include <tiny_gltf.h>

namespace wp::gltf {

struct Context {
  std::string file;  // the path as the user gave it; every message starts with it
  const tinygltf::Model& model;
  int variant = -1;  // KHR_materials_variants: the variant shown (gltf_variants.h); -1: none
};

// "mesh 3 'Cube'", or "mesh 3" when the name is empty. Names are made printable and
// shortened so that a message stays on one readable line.
std::string describe(const char* kind, size_t index, const std::string& name);

// Throws wp::Error("<file>: <where>: <message>"); `where` may be empty. The message should
// say what is wrong and, after a semicolon, what to do.
[[noreturn]] void fail(const Context& ctx, const std::string& where, const std::string& message);

// Prints "<file>: <where>: <message>" as a wp::warn.
void warnAt(const Context& ctx, const std::string& where, const std::string& message);

// Joins the lines of a library's multi-line message with "; " and shortens very long parts
// (tinygltf quotes whole data: URIs).
std::string oneLine(const std::string& text);

// "7 does not exist (the file has 3 materials)"
std::string missingIndex(long long index, size_t count, const char* plural);

}  // namespace wp::gltf
