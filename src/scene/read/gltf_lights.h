// The lights of a glTF file (KHR_lights_punctual; docs/scene-format.md, *Lights from a glTF
// file*): every light that the file's scene places, in the order its nodes are visited, in the
// file's coordinates, as candela's point, spot and directional lights. glTF's photometric units
// become candela's radiometric ones at 683 lumens per watt, as Blender's importer reads them in
// its default (Standard) lighting mode: a point or spot light of I candela emits the power
// 4 pi I / 683, a directional light of E lux gives the irradiance E / 683. A spot's cone angles
// (radians from its axis) become its cutoff_angle and beam_width. Each light's `where` is
// "<label>: nodes[i]". Throws SceneError "<label>: <reason>" for a file that cannot be read, a
// light that is not well formed, or a scene that places no lights.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace candela {

std::vector<LightDesc> readGltfLights(const std::string& path, const std::string& label);

}  // namespace candela
