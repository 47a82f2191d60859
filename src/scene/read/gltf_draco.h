// KHR_draco_mesh_compression: the primitives whose geometry a Draco stream holds, decoded into
// plain buffers, so that the accessors the rest of the reader takes name decoded data: each
// attribute's accessor becomes floats (Draco's dequantized values) and the indices' unsigned ints
// of its triangles. Built with Draco (CANDELA_HAS_DRACO) only: without it nothing is decoded, a
// file that requires the extension is refused (gltf_file.cpp) and one that merely uses it is read
// by the uncompressed geometry it must then carry as well.
#pragma once

#include <string>

#include "scene/read/tiny_gltf_config.h"

namespace candela {

// Whether this build decodes Draco streams.
bool gltfDracoDecoding();

// Leaves the "indices" of *file's compressed primitives (a .gltf's text or a .glb's bytes) out,
// for tinygltf, which refuses an indices accessor without a buffer view (where Draco's encoders
// leave it); decodeDracoPrimitives makes their indices from the stream. Nothing changes without
// Draco, without such primitives, or where the JSON cannot be read (the parser then says why).
void leaveOutDracoIndices(std::string* file);

// Decodes every compressed primitive of `model` in place (where this build decodes Draco). Throws
// SceneError "<label>: <JSON path>: <reason>" for a stream Draco cannot decode or one that does not
// hold what the primitive names (its attributes, their component counts, triangles).
void decodeDracoPrimitives(tinygltf::Model& model, const std::string& label);

}  // namespace candela
