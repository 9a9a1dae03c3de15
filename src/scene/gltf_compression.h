// Compressed mesh data decoded at load (EXT_meshopt_compression, KHR_draco_mesh_compression)
// into plain buffers, so that everything after reads them as it reads uncompressed files.
#pragma once

#include "scene/gltf_context.h"

namespace wp::gltf {

// Replaces every buffer view that has EXT_meshopt_compression by its bytes decoded with
// meshoptimizer (filters included), and points the accessors of every primitive that has
// KHR_draco_mesh_compression at its attributes and indices decoded with Draco; the decoded
// bytes go into buffers appended to model.buffers. Requires ctx.model to be `model`. Throws
// one line naming the buffer view or primitive when data does not decode, when declared
// sizes, strides or modes are not what the extension allows, or when a Draco attribute
// does not match its accessor's type.
void decodeCompressedData(const Context& ctx, tinygltf::Model& model);

}  // namespace wp::gltf
