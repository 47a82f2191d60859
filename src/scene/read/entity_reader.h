// Spheres, objects and lights of a scene file -> their descriptions.
//
// Each reader validates one array element; `where` in the result is its JSON path. Objects come
// back with `file` resolved against the scene file's folder and an empty mesh: the loader reads
// the OBJ files once the whole scene text has been validated.
#pragma once

#include <string>
#include <vector>

#include "scene/read/json_reader.h"
#include "scene/read/material_reader.h"
#include "scene/scene_desc.h"

namespace candela {

SphereDesc readSphere(const JsonValue& value, const MaterialLibrary& library,
                      TextureLoader& textures);
ObjectDesc readObject(const JsonValue& value, const MaterialLibrary& library,
                      const std::string& baseDir, TextureLoader& textures);
LightDesc readLight(const JsonValue& value, TextureLoader& textures);

// Whether an element of "lights" names a glTF file's lights ({"gltf": "scene.glb"}) rather than
// being one light.
bool namesGltfLights(const JsonValue& value);
// Those lights (scene/read/gltf_lights.h), each with the file as resolved and its `where`
// "lights[i].gltf: <file as written>: nodes[n]".
std::vector<LightDesc> readGltfLightEntry(const JsonValue& value, const std::string& baseDir);

// An object's scale: a number or [sx, sy, sz], every factor non-zero (zero would flatten the
// mesh; a negative factor mirrors it). Also read by animation tracks on "scale".
Vec3 readScale(const JsonValue& value);

// A light's "direction": any vector but zero, as its unit vector.
Vec3 readDirection(const JsonValue& value);

// A rectangle light's "size": a positive number (a square's side) or [width, height], each
// positive. Also read by animation tracks on "size".
Vec2 readRectangleSize(const JsonValue& value);

// A directional light's "angle": the apparent diameter of its disc, 0 up to 180 degrees.
float readSunAngle(const JsonValue& value);

}  // namespace candela
