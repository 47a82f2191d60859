// EXT_meshopt_compression (gltfpack's and gltf-transform's compression): the buffer views whose
// bytes a meshoptimizer stream holds, decoded into plain buffers by Debian's libmeshoptimizer
// (CANDELA_HAS_MESHOPT), filters (octahedral normals, quaternions, exponents) included, so that
// the accessors over them read as over any view. Without the library nothing is decoded: a file
// that requires the extension is refused (gltf_file.cpp) and one that merely uses it is read by
// the uncompressed fallback it must then carry.
#pragma once

#include <string>

#include "scene/read/tiny_gltf_config.h"

namespace candela {

// Whether this build decodes meshopt streams.
bool gltfMeshoptDecoding();

// Gives the placeholder buffers of *file's compressed views (a .gltf's text or a .glb's bytes;
// buffers without a URI that compressed views alone read, tagged "fallback" or not) a data URI of
// one byte, for tinygltf, which refuses a buffer without a URI that is not a .glb's own;
// decodeMeshoptViews gives the views that read them their decoded bytes. Nothing changes without
// the library or such buffers.
void giveMeshoptPlaceholdersAByte(std::string* file);

// Decodes every compressed buffer view of `model` in place (where this build decodes meshopt).
// Throws SceneError "<label>: bufferViews[i].extensions.EXT_meshopt_compression...: <reason>" for
// a stream that does not decode, or a mode, filter, stride or count the extension does not allow.
void decodeMeshoptViews(tinygltf::Model& model, const std::string& label);

}  // namespace candela
