// glTF 2.0 file (.gltf with its buffers and images beside it, or one binary .glb) -> MeshDesc, in
// the object's space: the triangles of every mesh that the file's default scene places (its
// first scene where it names none; where it has no scenes, every node that is no other's child),
// each placed by its node's transform and its parents' (and, with EXT_mesh_gpu_instancing, once
// per instance: gltf_instancing.h), as one mesh. Positions, normals, the first texture
// coordinates (v turned to candela's convention, v = 1 - glTF's v) and vertex colours (COLOR_0,
// linear, which tint the base colour as glTF says) are read, as floats or as the integers glTF
// and KHR_mesh_quantization allow, sparse or not (gltf_accessor.h), from buffers that Draco or
// meshopt may have compressed (gltf_draco.h, gltf_meshopt.h); each glTF material is mapped to
// candela's (gltf_materials.h), picked by a KHR_materials_variants variant where one is asked for
// (gltf_variants.h); a primitive without one takes glTF's default material. Triangles, strips and
// fans are read; points and lines are skipped with a warning. Morph targets (their positions and
// normals, at the node's or the mesh's weights) and skins (JOINTS_n and WEIGHTS_n, the joints at
// their nodes' transforms) pose the vertices as the file rests (gltf_rig.h); whether it holds
// cameras and lights is noted
// (MeshDesc::holdsCameras, holdsLights) for the scene to say where its camera or lights take none
// of them. A node whose transform mirrors keeps its faces' outsides (their winding is reversed, as
// glTF says).
//
// Errors throw SceneError "<label>: <reason>", the reason naming the JSON path of what is wrong
// ("meshes[0].primitives[1].indices: accessor 4 ...").
#pragma once

#include <memory>
#include <string>

#include "scene/read/gltf_rig.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_desc.h"

namespace candela {

// `variant`: a KHR_materials_variants variant's name that picks the primitives' materials ("":
// their own); one the file does not have throws GltfVariantError (gltf_variants.h). `node`: the
// name of the one node whose meshes (with its children's) make the mesh, in the node's own frame
// ("": the file's scene); one the file does not have throws GltfNodeError (gltf_nodes.h).
// With `rig`, *rig gets what poses the mesh's vertices, with its primitives and the file's
// animations, for an object that plays one of them (scene/read/gltf_mesh_motion.h); the mesh then
// warns of no animation. MeshDesc::animations lists the file's animations either way.
MeshDesc loadGltfFile(const std::string& path, const std::string& label, TextureLoader& textures,
                      const std::string& variant = "", const std::string& node = "",
                      std::shared_ptr<GltfRig>* rig = nullptr);

// Whether a mesh file is read as glTF: its name ends in ".gltf" or ".glb", in any case.
bool isGltfPath(const std::string& path);

}  // namespace candela
