// Bounds-checked reading of glTF accessors (sparse ones included): vertex attributes and indices.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/gltf_context.h"

namespace wp::gltf {

// Reads a VEC3 accessor (POSITION, NORMAL, morph target deltas), honouring the accessor's
// and buffer view's byteOffset, the view's byteStride and sparse substitution. FLOAT, or
// (KHR_mesh_quantization) BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT, normalized or not,
// decoded as glTF says. Throws, naming `where` and the accessor, when the index does not
// exist, the type is wrong, the accessor has neither a buffer view nor sparse values, any
// element or sparse index lies outside its buffer view or buffer, or a value is not finite.
// `attribute` names the primitive attribute in messages.
std::vector<glm::vec3> readVec3Attribute(const Context& ctx, int accessor, const std::string& where,
                                         const char* attribute);

// Reads a VEC2 accessor (`attribute`: TEXCOORD_n) of any type readVec3Attribute takes,
// with the same checks.
std::vector<glm::vec2> readTexCoords(const Context& ctx, int accessor, const std::string& where,
                                     const char* attribute);

// Reads a VEC4 accessor (TANGENT) as stored: FLOAT, or normalized BYTE or SHORT
// (KHR_mesh_quantization), with the same checks as readVec3Attribute.
std::vector<glm::vec4> readTangents(const Context& ctx, int accessor, const std::string& where);

// Reads COLOR_0 (VEC3 or VEC4; FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT) as
// RGBA in [0, 1], alpha 1 for VEC3, with the same checks as readVec3Attribute.
std::vector<glm::vec4> readColors(const Context& ctx, int accessor, const std::string& where);

// The floats of an accessor, `components` per element (1 for SCALAR to 16 for MAT4).
struct FloatElements {
  std::vector<float> values;
  size_t components = 0;
};

// Reads a FLOAT accessor of any type (animation keyframes, skin matrices, weights), or
// with `allowNormalized` also a normalized BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT
// vector decoded as glTF says; same checks as readVec3Attribute. `role` names it in messages.
FloatElements readFloats(const Context& ctx, int accessor, const std::string& where, const char* role,
                         bool allowNormalized);

// Reads JOINTS_0 (VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT), with the same checks.
std::vector<glm::uvec4> readJoints(const Context& ctx, int accessor, const std::string& where);

// Reads a SCALAR accessor of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, with the same
// checks as readVec3Attribute (the values themselves are checked by the caller).
std::vector<uint32_t> readIndices(const Context& ctx, int accessor, const std::string& where);

}  // namespace wp::gltf
