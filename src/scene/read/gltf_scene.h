// A glTF file given where a scene file is expected (`candela render model.glb`; docs/scene-
// format.md, *A glTF file as the scene*): the scene text that renders it as its author staged it,
// as far as the file says. The object is the whole file; the camera its first camera, or else one
// that frames the file's bounds from the front, right and above; the lights its lights
// (KHR_lights_punctual), or else a soft sun under a pale sky. Throws SceneError "<label>: <reason>"
// for a file that cannot be read.
#pragma once

#include <string>

namespace candela {

std::string gltfSceneText(const std::string& path, const std::string& label);

}  // namespace candela
