// Scene file -> validated SceneDesc, with its OBJ meshes loaded.
//
// Implements the format of docs/scene-format.md in three steps: JSON text -> document
// (json_parse.h), document -> validated descriptions (scene_*_reader.h, every key accounted for),
// then the OBJ files (obj_loader.h). A scene that cannot be rendered throws exactly one SceneError,
// whose message names the file as the caller gave it and the JSON path of the fault:
//   "scene.json: spheres[2].radius: expected a positive number, got -1"
//   "scene.json:3:14: invalid JSON: syntax error while parsing object key - ..."
//   "scene.json: objects[0].file: meshes/bad.obj:12: face index 99 out of range (4 vertices)"
// Nothing is printed.
#pragma once

#include <string>

#include "scene/scene_desc.h"

namespace candela {

// Reads, parses and validates a scene file; loads its OBJ files. Throws SceneError. A glTF file
// (.gltf, .glb) is a scene of its own (scene/read/gltf_scene.h).
SceneDesc loadSceneFile(const std::string& path);

// Same from JSON text; `fileLabel` prefixes messages, `baseDir` resolves OBJ paths.
SceneDesc parseSceneText(const std::string& text, const std::string& fileLabel,
                         const std::string& baseDir);

}  // namespace candela
