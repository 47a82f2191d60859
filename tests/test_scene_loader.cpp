// Scene loading: every error class of docs/scene-format.md pinned to its exact message, and the
// values that each accepted form of the format turns into.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "scene/read/did_you_mean.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela {
namespace {

using test::TempDir;
using test::writeTestPng;

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// The message of the SceneError that `load` throws, or a note that it threw none.
std::string errorOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no SceneError)";
}

class SceneLoader : public ::testing::Test {
 protected:
  SceneDesc parse(const std::string& json) const {
    return parseSceneText(json, "s.json", dir.path());
  }
  std::string error(const std::string& json) const {
    return errorOf([&] { parse(json); });
  }
  // A scene whose only content besides a default camera is `rest` (keys of the top level).
  std::string errorWith(const std::string& rest) const {
    return error(R"({"camera": {}, )" + rest + "}");
  }
  std::string cameraError(const std::string& camera) const {
    return error(R"({"camera": )" + camera + "}");
  }
  CameraDesc camera(const std::string& camera) const {
    return parse(R"({"camera": )" + camera + "}").camera;
  }

  TempDir dir;
};

void expectVec3(const Vec3& actual, float x, float y, float z) {
  EXPECT_FLOAT_EQ(actual.x, x);
  EXPECT_FLOAT_EQ(actual.y, y);
  EXPECT_FLOAT_EQ(actual.z, z);
}

// ---------------------------------------------------------------------------------------------
// Errors, one test per class, each pinning the whole message.

TEST_F(SceneLoader, TypoKeySuggestsTheKnownKey) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "raduis": 1}])"),
            "s.json: spheres[0].raduis: unknown key, did you mean \"radius\"?");
  EXPECT_EQ(cameraError(R"({"Width": 64})"),
            "s.json: camera.Width: unknown key, did you mean \"width\"?");
}

TEST_F(SceneLoader, UnknownTopLevelKey) {
  EXPECT_EQ(errorWith(R"("lihgts": [])"), "s.json: lihgts: unknown key, did you mean \"lights\"?");
  EXPECT_EQ(errorWith(R"("sky": {})"),
            "s.json: sky: unknown key, expected one of \"camera\", \"render\", \"materials\", "
            "\"spheres\", \"objects\", \"lights\", \"environment\", \"animation\"");
}

TEST_F(SceneLoader, CommentKeysAreIgnoredEverywhere) {
  const SceneDesc scene = parse(R"({
    "_comment": "a scene", "_version": 2,
    "camera": {"_note": "pinhole", "width": 8},
    "render": {"_why": "fast"},
    "materials": {"_unused": {"type": "nonsense"}, "red": {"type": "diffuse", "_c": 1}},
    "spheres": [{"_": 0, "position": [0, 0, 0], "radius": 1, "material": "red"}],
    "lights": [{"_off": true, "position": [0, 5, 0], "intensity": 1}],
    "environment": {"_": [], "color": 0}
  })");
  EXPECT_EQ(scene.camera.width, 8u);
  ASSERT_EQ(scene.spheres.size(), 1u);
  ASSERT_EQ(scene.lights.size(), 1u);
}

TEST_F(SceneLoader, JsonSyntaxErrorHasLineAndColumn) {
  EXPECT_EQ(error("{\n  \"camera\": {\n    \"width\": 10,\n  }\n}"),
            "s.json:4:3: invalid JSON: syntax error while parsing object key - unexpected '}'; "
            "expected string literal");
  EXPECT_EQ(error("{\"camera\": {} // comment\n}"),
            "s.json:1:15: invalid JSON: syntax error while parsing object - invalid literal; last "
            "read: '\"camera\": {} /'; expected '}'");
  // A long token in nlohmann's "last read" is cut to its end, where the fault is.
  EXPECT_EQ(error("{\"camera\": {}, \"abcdefghijklmnopqrstuvwxyz"),
            "s.json:1:43: invalid JSON: syntax error while parsing object key - invalid string: "
            "missing closing quote; last read: '...ghijklmnopqrstuvwxyz'; expected string literal");
  EXPECT_EQ(error(""),
            "s.json:1:1: invalid JSON: syntax error while parsing value - unexpected end of "
            "input; expected '[', '{', or a literal");
}

TEST_F(SceneLoader, DuplicateJsonKeyIsAnError) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1, "radius": 2}])"),
            "s.json: spheres[0].radius: duplicate key, each key may appear once per object");
  EXPECT_EQ(errorWith(R"("_c": 1, "_c": 2)"), "(no SceneError)");
}

TEST_F(SceneLoader, TopLevelMustBeAnObject) {
  EXPECT_EQ(error("[1, 2]"), "s.json: expected an object at the top level, got an array [1,2]");
}

TEST_F(SceneLoader, WrongType) {
  EXPECT_EQ(cameraError(R"({"position": ["abc", 0, 0]})"),
            "s.json: camera.position[0]: expected a number, got a string \"abc\"");
  EXPECT_EQ(cameraError(R"({"position": [0, 0]})"),
            "s.json: camera.position: expected an array of 3 numbers, got an array [0,0]");
  EXPECT_EQ(errorWith(R"("spheres": {"position": [0, 0, 0]})"),
            "s.json: spheres: expected an array, got an object {\"position\":[0,0,0]}");
  EXPECT_EQ(errorWith(R"("render": {"antialiasing": 1})"),
            "s.json: render.antialiasing: expected true or false, got 1");
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1, "color": "red"}])"),
            "s.json: spheres[0].color: expected a colour (a number or an array of 3 numbers), got "
            "a string \"red\"");
}

TEST_F(SceneLoader, MissingRequiredKey) {
  EXPECT_EQ(error("{}"), "s.json: missing required key \"camera\"");
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0]}])"),
            "s.json: spheres[0]: missing required key \"radius\"");
  EXPECT_EQ(errorWith(R"("spheres": [{"radius": 1}])"),
            "s.json: spheres[0]: missing required key \"position\"");
  EXPECT_EQ(errorWith(R"("objects": [{"position": [0, 0, 0]}])"),
            "s.json: objects[0]: missing required key \"file\" (an OBJ, PLY or glTF file) or "
            "\"shape\" (\"rectangle\", \"disk\", \"cube\" or \"cylinder\")");
  EXPECT_EQ(errorWith(R"("lights": [{"position": [0, 0, 0]}])"),
            "s.json: lights[0]: missing required key \"intensity\"");
  EXPECT_EQ(errorWith(R"("materials": {"lamp": {"type": "emissive"}})"),
            "s.json: materials.lamp: missing required key \"radiance\"");
}

TEST_F(SceneLoader, NumberThatOverflowsIsNotFinite) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1e400}])"),
            "s.json: spheres[0].radius: expected a finite number, got 1e400");
  EXPECT_EQ(cameraError(R"({"position": [0, -1e400, 0]})"),
            "s.json: camera.position[1]: expected a finite number, got -1e400");
  // Finite as a double, infinite as the float it is stored in.
  EXPECT_EQ(cameraError(R"({"position": [1e39, 0, 0]})"),
            "s.json: camera.position[0]: expected a finite number within single precision, got "
            "1e+39");
}

TEST_F(SceneLoader, NegativeRadius) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1},)"
                      R"(           {"position": [0, 0, 0], "radius": -1}])"),
            "s.json: spheres[1].radius: expected a positive number, got -1");
  EXPECT_EQ(
      errorWith(
          R"("lights": [{"type": "sphere", "position": [0, 0, 0], "intensity": 1, "radius": 0}])"),
      "s.json: lights[0].radius: expected a positive number, got 0");
}

TEST_F(SceneLoader, ZeroSizedImage) {
  EXPECT_EQ(cameraError(R"({"width": 0})"),
            "s.json: camera.width: expected a positive integer, got 0");
  EXPECT_EQ(cameraError(R"({"height": 2.5})"),
            "s.json: camera.height: expected a positive integer, got 2.5");
  EXPECT_EQ(cameraError(R"({"width": 5000000000})"),
            "s.json: camera.width: expected a positive integer of at most 4294967295, got "
            "5000000000");
}

TEST_F(SceneLoader, ZeroSamplesPerPixel) {
  EXPECT_EQ(cameraError(R"({"spp": 0})"), "s.json: camera.spp: expected a positive integer, got 0");
  EXPECT_EQ(cameraError(R"({"rays": -4})"),
            "s.json: camera.rays: expected a positive integer, got -4");
  EXPECT_EQ(cameraError(R"({"spp": 4, "rays": 4})"),
            "s.json: camera: expected either \"spp\" or \"rays\", got both");
}

TEST_F(SceneLoader, UnknownMaterialType) {
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "metal"}})"),
            "s.json: materials.m.type: expected one of \"diffuse\", \"mirror\", \"glass\", "
            "\"emissive\", \"conductor\", \"plastic\", \"thin_glass\", \"mix\", got a string "
            "\"metal\"");
  EXPECT_EQ(
      errorWith(
          R"("spheres": [{"position": [0, 0, 0], "radius": 1, "material": {"type": "glas"}}])"),
      "s.json: spheres[0].material.type: expected one of \"diffuse\", \"mirror\", \"glass\", "
      "\"emissive\", \"conductor\", \"plastic\", \"thin_glass\", \"mix\", got a string \"glas\", "
      "did you mean \"glass\"?");
}

TEST_F(SceneLoader, RoughMaterialsAreRead) {
  const SceneDesc scene = parse(R"({"camera": {"width": 4, "height": 4, "fov": 60, "spp": 1},
    "materials": {"gold": {"type": "conductor", "metal": "Au", "roughness": 0.3},
                  "steel": {"type": "conductor", "color": [0.6, 0.6, 0.65]},
                  "frosted": {"type": "glass", "ior": 1.45, "roughness": 0.2},
                  "red": {"type": "plastic", "color": [0.8, 0.1, 0.1], "roughness": 0.4}},
    "spheres": [{"position": [0, 0, -5], "radius": 1, "material": "gold"},
                {"position": [2, 0, -5], "radius": 1, "material": "steel"},
                {"position": [4, 0, -5], "radius": 1, "material": "frosted"},
                {"position": [6, 0, -5], "radius": 1, "material": "red"},
                {"position": [8, 0, -5], "radius": 1, "material": {"type": "plastic"}}]})");
  const Material& gold = scene.spheres[0].material;
  EXPECT_EQ(gold.type, MaterialType::Conductor);
  EXPECT_TRUE(gold.metal);
  EXPECT_FLOAT_EQ(gold.roughness, 0.3f);
  EXPECT_NEAR(gold.metalK.x, 3.98f, 0.01f);
  const Material& steel = scene.spheres[1].material;
  EXPECT_FALSE(steel.metal);
  EXPECT_EQ(steel.roughness, 0.0f);
  expectVec3(steel.color, 0.6f, 0.6f, 0.65f);
  EXPECT_EQ(scene.spheres[2].material.type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(scene.spheres[2].material.roughness, 0.2f);
  EXPECT_FLOAT_EQ(scene.spheres[2].material.ior, 1.45f);
  const Material& red = scene.spheres[3].material;
  EXPECT_EQ(red.type, MaterialType::Plastic);
  // Its derived values are filled in: the coat transmits most light at normal incidence.
  EXPECT_GT(red.plasticTransmittance[kPlasticTableSize - 1], 0.9f);
  EXPECT_GT(red.plasticInternalReflectance, 0.3f);
  // Plastic's defaults are Mitsuba's: base 0.5, ior 1.5, smooth.
  expectVec3(scene.spheres[4].material.color, 0.5f, 0.5f, 0.5f);
  EXPECT_FLOAT_EQ(scene.spheres[4].material.ior, 1.5f);
}

TEST_F(SceneLoader, BadRoughMaterialsAreRefused) {
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "conductor", "roughness": 1.5}})"),
            "s.json: materials.m.roughness: expected a roughness in [0, 1], got 1.5");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "glass", "roughness": -0.1}})"),
            "s.json: materials.m.roughness: expected a roughness in [0, 1], got -0.1");
  EXPECT_EQ(
      errorWith(R"("materials": {"m": {"type": "plastic", "roughness": "rough"}})"),
      "s.json: materials.m.roughness: expected a roughness in [0, 1] or a texture object, got a "
      "string "
      "\"rough\"");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "conductor", "metal": "Gold"}})"),
            "s.json: materials.m.metal: expected one of \"Ag\", \"Al\", \"Au\", \"Cr\", "
            "\"Cu\", got a string \"Gold\"");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "conductor", "metal": "Au", "color": 1}})"),
            "s.json: materials.m: give a conductor either \"color\" or \"metal\", not both");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "plastic", "metal": "Au"}})"),
            "s.json: materials.m.metal: not used by a \"plastic\" material");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "conductor", "ior": 1.5}})"),
            "s.json: materials.m.ior: not used by a \"conductor\" material");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "diffuse", "roughness": 0.5}})"),
            "s.json: materials.m.roughness: not used by a \"diffuse\" material");
  EXPECT_EQ(errorWith(R"("materials": {"m": {"type": "mirror", "roughness": 0.5}})"),
            "s.json: materials.m.roughness: not used by a \"mirror\" material");
}

TEST_F(SceneLoader, UnknownLightType) {
  EXPECT_EQ(errorWith(R"("lights": [{"type": "area", "position": [0, 0, 0], "intensity": 1}])"),
            "s.json: lights[0].type: expected one of \"point\", \"sphere\", \"spot\", "
            "\"directional\", \"rectangle\", got a string \"area\"");
}

TEST_F(SceneLoader, UnknownNamedMaterial) {
  const std::string materials =
      R"("materials": {"red": {"type": "diffuse", "color": [1, 0, 0]}}, )";
  EXPECT_EQ(errorWith(materials +
                      R"("spheres": [{"position": [0, 0, 0], "radius": 1, "material": "rde"}])"),
            "s.json: spheres[0].material: unknown material \"rde\", did you mean \"red\"?");
  EXPECT_EQ(errorWith(materials +
                      R"("spheres": [{"position": [0, 0, 0], "radius": 1, "material": "chrome"}])"),
            "s.json: spheres[0].material: unknown material \"chrome\", expected \"diffuse\", "
            "\"mirror\", \"glass\" or a name defined under \"materials\"");
  EXPECT_EQ(
      errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1, "material": "emissive"}])"),
      "s.json: spheres[0].material: unknown material \"emissive\", expected \"diffuse\", "
      "\"mirror\", \"glass\" or a name defined under \"materials\"; an emissive material is "
      "written as an object: {\"type\": \"emissive\", \"radiance\": ...}");
}

TEST_F(SceneLoader, UnusedMaterialFields) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1,)"
                      R"(             "material": "diffuse", "ior": 1.5}])"),
            "s.json: spheres[0].ior: not used by a \"diffuse\" material");
  EXPECT_EQ(
      errorWith(
          R"("materials": {"r": {"type": "diffuse"}},)"
          R"("spheres": [{"position": [0, 0, 0], "radius": 1, "material": "r", "color": 1}])"),
      "s.json: spheres[0].color: not used with the named material \"r\"");
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1,)"
                      R"(             "material": {"type": "glass"}, "ior": 1.3}])"),
            "s.json: spheres[0].ior: not used beside an inline material (put it inside "
            "\"material\")");
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1, "ior": 1.3}])"),
            "s.json: spheres[0].ior: not used without a \"glass\" material");
  EXPECT_EQ(errorWith(R"("materials": {"l": {"type": "emissive", "radiance": 1, "color": 1}})"),
            "s.json: materials.l.color: not used by an \"emissive\" material");
  EXPECT_EQ(errorWith(R"("lights": [{"position": [0, 0, 0], "intensity": 1, "radius": 1}])"),
            "s.json: lights[0].radius: not used by a point light (only \"sphere\" lights have a "
            "radius)");
}

TEST_F(SceneLoader, InvalidColourAndIor) {
  EXPECT_EQ(
      errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1, "color": [1, -0.5, 0]}])"),
      "s.json: spheres[0].color[1]: expected a non-negative number, got -0.5");
  EXPECT_EQ(errorWith(R"("materials": {"g": {"type": "glass", "ior": 0}})"),
            "s.json: materials.g.ior: expected a positive number, got 0");
  EXPECT_EQ(errorWith(R"("lights": [{"position": [0, 0, 0], "intensity": -1}])"),
            "s.json: lights[0].intensity: expected a non-negative number, got -1");
}

TEST_F(SceneLoader, LightsBeyondSinglePrecision) {
  // Each number fits a float; the power or the radiance they make does not.
  EXPECT_EQ(errorWith(R"("lights": [{"position": [0, 0, 0], "intensity": 1e30,
                                     "color": [1e20, 1, 1]}])"),
            "s.json: lights[0]: its power, intensity 1e+30 times color [1e+20, 1, 1], is beyond "
            "single precision; expected a smaller intensity or color");
  EXPECT_EQ(errorWith(R"("lights": [{"type": "sphere", "position": [0, 0, 0], "intensity": 1e30,
                                     "radius": 1e-10}])"),
            "s.json: lights[0]: its surface's radiance, intensity 1e+30 times color [1, 1, 1] "
            "over a sphere of radius 1e-10, is beyond single precision; expected a larger radius "
            "or a smaller intensity");
  EXPECT_EQ(parse(R"({"camera": {}, "lights": [{"type": "sphere", "position": [0, 0, 0],
                       "intensity": 1e30, "radius": 1e-3}]})")
                .lights.size(),
            1u);
}

TEST_F(SceneLoader, GeometryBeyondSinglePrecisionsReach) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [2e18, 0, 0], "radius": 1}])"),
            "s.json: spheres[0]: the sphere reaches 2e+18 from the origin; expected geometry "
            "within 1e+18 (single precision cannot intersect it further out)");
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1e20}])"),
            "s.json: spheres[0]: the sphere reaches 1e+20 from the origin; expected geometry "
            "within 1e+18 (single precision cannot intersect it further out)");
  dir.write("tri.obj", kTriangleObj);  // its farthest vertex 1 from the mesh's origin
  EXPECT_EQ(errorWith(R"("objects": [{"file": "tri.obj", "scale": [1, 3e18, 1]}])"),
            "s.json: objects[0]: its mesh, scaled and placed, reaches 3e+18 from the origin; "
            "expected geometry within 1e+18 (single precision cannot intersect it further out)");
  EXPECT_EQ(errorWith(R"("objects": [{"file": "tri.obj", "position": [0, 0, -2e18]}])"),
            "s.json: objects[0]: its mesh, scaled and placed, reaches 2e+18 from the origin; "
            "expected geometry within 1e+18 (single precision cannot intersect it further out)");
  EXPECT_EQ(parse(R"({"camera": {}, "objects": [{"file": "tri.obj", "scale": 1e17,
                      "position": [5e17, 0, 0]}], "spheres": [{"position": [0, -1e17, 0],
                      "radius": 8e17}]})")
                .objects.size(),
            1u);
}

TEST_F(SceneLoader, MissingObjFile) {
  EXPECT_EQ(errorWith(R"("objects": [{"file": "meshes/x.obj"}])"),
            "s.json: objects[0].file: cannot open \"meshes/x.obj\" (No such file or directory)");
}

TEST_F(SceneLoader, MalformedObjFileNamesItsLine) {
  dir.write("meshes/bad.obj", "# four vertices\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 99\n");
  EXPECT_EQ(errorWith(R"("objects": [{"file": "meshes/bad.obj"}])"),
            "s.json: objects[0].file: meshes/bad.obj:6: face index 99 out of range (4 vertices)");
}

// What an OBJ file leaves to the default material is a warning, not an error: given once per
// file, at the first object that takes its materials from it, prefixed like an error.
TEST_F(SceneLoader, ObjMaterialWarningsNameTheObjectThatUsesTheFile) {
  dir.write("meshes/m.obj", std::string("mtllib gone.mtl\nusemtl a\n") + kTriangleObj);
  dir.write("meshes/plain.obj", kTriangleObj);
  const SceneDesc scene = parse(R"({"camera": {}, "objects": [
      {"file": "meshes/plain.obj"},
      {"file": "meshes/m.obj", "color": [1, 0, 0]},
      {"file": "meshes/m.obj"}, {"file": "meshes/m.obj"}]})");
  EXPECT_EQ(scene.warnings,
            std::vector<std::string>{
                "s.json: objects[2].file: meshes/m.obj:1: cannot read the material library "
                "\"gone.mtl\" (No such file or directory); the materials it would define are "
                "diffuse 0.8"});
  // Where every object sets its own material, the file's materials do not matter.
  EXPECT_TRUE(parse(R"({"camera": {}, "objects": [{"file": "meshes/m.obj", "color": 0.5}]})")
                  .warnings.empty());
}

// A texture on a mesh without texture coordinates would read one texel everywhere: a warning,
// per object for a material the scene gives, once per file for the file's own (MTL map_Kd).
TEST_F(SceneLoader, ATextureOnAMeshWithoutUvsIsAWarning) {
  ASSERT_TRUE(writeTestPng(dir.file("t.png"), 2, 2, 3, std::vector<uint8_t>(12, 200)));
  dir.write("meshes/plain.obj", kTriangleObj);
  dir.write("meshes/uv.obj",
            std::string("vt 0 0\nvt 1 0\nvt 0 1\n") + "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/2 3/3\n");
  dir.write("meshes/mapped.mtl", "newmtl m\nKd 1 1 1\nmap_Kd ../t.png\n");
  dir.write("meshes/mapped.obj", std::string("mtllib mapped.mtl\nusemtl m\n") + kTriangleObj);
  const SceneDesc scene = parse(R"({"camera": {}, "objects": [
      {"file": "meshes/plain.obj", "color": {"texture": "t.png"}},
      {"file": "meshes/uv.obj", "color": {"texture": "t.png"}},
      {"file": "meshes/plain.obj", "color": 0.5},
      {"file": "meshes/mapped.obj"}, {"file": "meshes/mapped.obj"},
      {"file": "meshes/mapped.obj", "color": 0.5}]})");
  EXPECT_EQ(scene.warnings,
            (std::vector<std::string>{
                "s.json: objects[0]: its material has a texture, but meshes/plain.obj has no "
                "texture coordinates (\"vt\"): the texel at uv (0, 0) covers the whole surface",
                "s.json: objects[3]: a material of meshes/mapped.obj has a texture, but "
                "meshes/mapped.obj has no texture coordinates (\"vt\"): the texel at uv (0, 0) "
                "covers the whole surface"}));
}

// A colour above 1 on a surface that reflects light (an 8-bit colour, most often) is a warning:
// named for the first four spheres or objects, then counted. Emitters' radiance is no
// reflectance, nor is a colour of 1.
TEST_F(SceneLoader, AReflectanceAboveOneIsAWarning) {
  dir.write("m.obj", kTriangleObj);
  const SceneDesc scene = parse(R"({"camera": {},
      "materials": {"hot": {"type": "emissive", "radiance": 5}, "white": {"type": "diffuse", "color": 1}},
      "spheres": [{"position": [0, 0, 0], "radius": 1, "color": [255, 128, 0]},
                  {"position": [0, 0, 0], "radius": 1, "material": "hot"},
                  {"position": [0, 0, 0], "radius": 1, "material": "white"},
                  {"position": [0, 0, 0], "radius": 1, "material": {"type": "glass", "color": 1.5}},
                  {"position": [0, 0, 0], "radius": 1, "material": "mirror"}],
      "objects": [{"file": "m.obj", "color": [0.5, 2, 0.5]}, {"file": "m.obj"},
                  {"file": "m.obj", "material": {"type": "conductor", "color": 3}},
                  {"file": "m.obj", "material": {"type": "plastic", "color": 4}},
                  {"file": "m.obj", "color": 5}]})");
  const std::string tail =
      " is above 1, a surface that reflects more light than it receives; colours are linear "
      "reflectances in [0, 1] (8-bit values divided by 255)";
  EXPECT_EQ(scene.warnings,
            (std::vector<std::string>{
                "s.json: spheres[0]: its material's color [255, 128, 0]" + tail,
                "s.json: spheres[3]: its material's color [1.5, 1.5, 1.5]" + tail,
                "s.json: objects[0]: its material's color [0.5, 2, 0.5]" + tail,
                "s.json: objects[2]: its material's color [3, 3, 3]" + tail,
                "s.json: 2 more spheres or objects whose material's color is above 1"}));
}

TEST_F(SceneLoader, JsonIsValidatedBeforeMeshesLoad) {
  EXPECT_EQ(
      errorWith(R"("objects": [{"file": "missing.obj"}], "lights": [{"positon": [0, 0, 0]}])"),
      "s.json: lights[0].positon: unknown key, did you mean \"position\"?");
}

TEST_F(SceneLoader, DuplicateId) {
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "radius": 1},
                                    {"id": "lamp", "position": [0, 0, 0], "radius": 1}],
                         "lights": [{"id": "lamp", "position": [0, 0, 0], "intensity": 1}])"),
            "s.json: lights[0].id: duplicate id \"lamp\", already used by spheres[1]");
  EXPECT_EQ(errorWith(R"("lights": [{"id": "camera", "position": [0, 0, 0], "intensity": 1}])"),
            "s.json: lights[0].id: expected an id other than \"camera\", which names the camera, "
            "got a string \"camera\"");
}

TEST_F(SceneLoader, ConflictingCameraKeys) {
  EXPECT_EQ(cameraError(R"({"fov": 40, "intrinsics": {"fx": 1, "fy": 1, "cx": 0, "cy": 0}})"),
            "s.json: camera: expected either \"fov\" or \"intrinsics\", got both");
  EXPECT_EQ(cameraError(R"({"rotation": [0, 0, 0], "look_at": [0, 0, -1]})"),
            "s.json: camera: expected either \"rotation\" or \"look_at\", got both");
  EXPECT_EQ(
      cameraError(R"({"position": [0, 0, 0],)"
                  R"( "extrinsics": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"),
      "s.json: camera: expected either \"extrinsics\" or \"position\", got both");
  EXPECT_EQ(cameraError(R"({"up": [0, 0, 1]})"), "s.json: camera.up: not used without \"look_at\"");
}

TEST_F(SceneLoader, InvalidCameraGeometry) {
  EXPECT_EQ(cameraError(R"({"position": [1, 2, 3], "look_at": [1, 2, 3]})"),
            "s.json: camera.look_at: expected a point other than the camera position, got an "
            "array [1,2,3]");
  EXPECT_EQ(cameraError(R"({"look_at": [0, 0, -5], "up": [0, 0, 2]})"),
            "s.json: camera.up: expected a direction that is not parallel to the viewing "
            "direction, got an array [0,0,2]");
  EXPECT_EQ(cameraError(R"({"look_at": [0, -5, 0]})"),
            "s.json: camera: missing required key \"up\" (the view is parallel to the default up "
            "[0, 1, 0])");
  EXPECT_EQ(cameraError(R"({"fov": 180})"),
            "s.json: camera.fov: expected a number between 0 and 180 (exclusive), got 180");
  EXPECT_EQ(cameraError(R"({"aperture_radius": 0.1})"),
            "s.json: camera: missing required key \"focus_distance\" (an open aperture without "
            "\"look_at\" has nothing else to focus on)");
  EXPECT_EQ(cameraError(R"({"aperture_radius": -0.1})"),
            "s.json: camera.aperture_radius: expected a non-negative number, got -0.1");
}

TEST_F(SceneLoader, InvalidCameraMatrices) {
  EXPECT_EQ(
      cameraError(R"({"extrinsics": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]})"),
      "s.json: camera.extrinsics[3]: expected [0, 0, 0, 1], got an array [0,0,1,1]");
  EXPECT_EQ(
      cameraError(R"({"extrinsics": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]})"),
      "s.json: camera.extrinsics: expected a rotation (orthonormal, determinant +1) in the "
      "upper-left 3x3 block, got an array [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]");
  EXPECT_EQ(cameraError(R"({"extrinsics": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})"),
            "s.json: camera.extrinsics: expected a 4x4 matrix (an array of 4 rows of 4 numbers), "
            "got an array [[1,0,0],[0,1,0],[0,0,1]]");
  EXPECT_EQ(cameraError(R"({"intrinsics": [[100, 0, 32], [0, 100, 24], [0, 0, 2]]})"),
            "s.json: camera.intrinsics[2]: expected [0, 0, 1], got an array [0,0,2]");
  EXPECT_EQ(cameraError(R"({"intrinsics": {"fx": 100, "fy": 100, "cx": 32}})"),
            "s.json: camera.intrinsics: missing required key \"cy\"");
}

TEST_F(SceneLoader, InvalidRenderSettings) {
  EXPECT_EQ(errorWith(R"("render": {"max_depth": 0})"),
            "s.json: render.max_depth: expected a positive integer, got 0");
  EXPECT_EQ(errorWith(R"("render": {"integrator": "pth"})"),
            "s.json: render.integrator: expected \"path\" or \"direct\", got a string \"pth\", did "
            "you mean \"path\"?");
  EXPECT_EQ(errorWith(R"("render": {"light_paths": "sometimes"})"),
            "s.json: render.light_paths: expected one of \"auto\", \"on\", \"off\", got a "
            "string \"sometimes\"");
  EXPECT_EQ(errorWith(R"("render": {"seed": -1})"),
            "s.json: render.seed: expected a non-negative integer, got -1");
  EXPECT_EQ(errorWith(R"("render": {"gamma": "sRGB"})"),
            "s.json: render.gamma: expected a positive number or \"srgb\", got a string \"sRGB\", "
            "did you mean \"srgb\"?");
  EXPECT_EQ(errorWith(R"("render": {"gamma": 0})"),
            "s.json: render.gamma: expected a positive number or \"srgb\", got 0");
  EXPECT_EQ(errorWith(R"("render": {"tone_map": "filmic"})"),
            "s.json: render.tone_map: expected one of \"clamp\", \"reinhard\", \"aces\", got a "
            "string \"filmic\"");
}

TEST_F(SceneLoader, InvalidObjectKeys) {
  EXPECT_EQ(errorWith(R"("objects": [{"file": "a.obj", "scale": [1, 0, 1]}])"),
            "s.json: objects[0].scale[1]: expected a non-zero number, got 0");
  EXPECT_EQ(
      errorWith(R"("objects": [{"file": "a.obj", "smooth": "yes"}])"),
      "s.json: objects[0].smooth: expected true, false or a crease angle in degrees (above 0, "
      "up to 180), got a string \"yes\"");
  EXPECT_EQ(errorWith(R"("spheres": [{"position": [0, 0, 0], "center": [0, 0, 0], "radius": 1}])"),
            "s.json: spheres[0]: expected either \"position\" or \"center\", got both");
}

TEST_F(SceneLoader, AnimationBlockIsRead) {
  // The animation errors are pinned in test_animation.cpp; here only that the block is accepted.
  const SceneDesc scene = parse(R"({"camera": {}, "animation": {"frames": 2}})");
  ASSERT_TRUE(scene.animation);
  EXPECT_EQ(scene.animation->frames, 2u);
  EXPECT_FLOAT_EQ(scene.animation->fps, 24);
  EXPECT_TRUE(scene.animation->tracks.empty());
}

TEST_F(SceneLoader, SceneFileThatCannotBeOpened) {
  const std::string missing = dir.path() + "/nothing.json";
  EXPECT_EQ(errorOf([&] { loadSceneFile(missing); }),
            missing + ": cannot open scene file (No such file or directory)");
  EXPECT_EQ(errorOf([&] { loadSceneFile(dir.path()); }),
            dir.path() + ": cannot open scene file (Is a directory)");
}

// ---------------------------------------------------------------------------------------------
// Accepted scenes.

TEST_F(SceneLoader, DefaultsFollowTheContract) {
  const SceneDesc scene = parse(R"({"camera": {},
      "spheres": [{"position": [1, 2, 3], "radius": 2}],
      "lights": [{"position": [0, 9, 0], "intensity": 100}]})");
  EXPECT_EQ(scene.file, "s.json");
  const CameraDesc& c = scene.camera;
  EXPECT_EQ(c.width, 512u);
  EXPECT_EQ(c.height, 512u);
  EXPECT_FLOAT_EQ(c.fov, 60);
  EXPECT_FALSE(c.intrinsics);
  expectVec3(c.position, 0, 0, 0);
  expectVec3(c.rotation, 0, 0, 0);
  EXPECT_FALSE(c.lookAt);
  expectVec3(c.up, 0, 1, 0);
  EXPECT_FALSE(c.extrinsicsR);
  EXPECT_FALSE(c.extrinsicsT);
  EXPECT_FLOAT_EQ(c.apertureRadius, 0);
  EXPECT_FALSE(c.focusDistance);

  EXPECT_EQ(scene.render.spp, 64u);
  EXPECT_EQ(scene.render.maxDepth, 8u);
  EXPECT_EQ(scene.render.integrator, IntegratorType::Path);
  EXPECT_TRUE(scene.render.antialiasing);
  EXPECT_EQ(scene.render.lightPaths, LightPaths::Auto);
  EXPECT_EQ(scene.render.seed, 0u);
  EXPECT_EQ(scene.output.curve, GammaCurve::Power);
  EXPECT_FLOAT_EQ(scene.output.gamma, 2.2f);
  EXPECT_FLOAT_EQ(scene.output.exposure, 0);

  ASSERT_EQ(scene.spheres.size(), 1u);
  EXPECT_EQ(scene.spheres[0].where, "spheres[0]");
  EXPECT_EQ(scene.spheres[0].id, "");
  expectVec3(scene.spheres[0].position, 1, 2, 3);
  EXPECT_EQ(scene.spheres[0].material.type, MaterialType::Diffuse);
  expectVec3(scene.spheres[0].material.color, 0.8f, 0.8f, 0.8f);

  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_FLOAT_EQ(scene.lights[0].intensity, 100);
  expectVec3(scene.lights[0].color, 1, 1, 1);
  expectVec3(scene.environment.color, 0, 0, 0);
}

TEST_F(SceneLoader, RenderSettings) {
  const SceneDesc scene = parse(R"({"camera": {"rays": 16},
      "render": {"max_depth": 3, "integrator": "direct", "antialiasing": false,
                 "seed": 18446744073709551615, "gamma": "srgb", "exposure": -17.59}})");
  EXPECT_EQ(scene.render.spp, 16u);
  EXPECT_EQ(scene.render.maxDepth, 3u);
  EXPECT_EQ(scene.render.integrator, IntegratorType::Direct);
  EXPECT_FALSE(scene.render.antialiasing);
  EXPECT_EQ(scene.render.seed, UINT64_MAX);
  EXPECT_EQ(scene.output.curve, GammaCurve::Srgb);
  EXPECT_FLOAT_EQ(scene.output.exposure, -17.59f);
  EXPECT_FLOAT_EQ(parse(R"({"camera": {}, "render": {"gamma": 1.8}})").output.gamma, 1.8f);
  EXPECT_EQ(scene.output.toneMap, ToneMap::Clamp);
  EXPECT_EQ(parse(R"({"camera": {}, "render": {"tone_map": "reinhard"}})").output.toneMap,
            ToneMap::Reinhard);
  EXPECT_EQ(parse(R"({"camera": {}, "render": {"tone_map": "aces"}})").output.toneMap,
            ToneMap::Aces);
  EXPECT_EQ(parse(R"({"camera": {}, "render": {"light_paths": "on"}})").render.lightPaths,
            LightPaths::On);
  EXPECT_EQ(parse(R"({"camera": {}, "render": {"light_paths": "off"}})").render.lightPaths,
            LightPaths::Off);
}

// Cameras whose rays would not be finite are refused at load, naming the key that causes it
// (regression: each of these crashed in traversal, which followed empty BVH slots on NaN rays).
// Input that would hang or exhaust memory ends in one short message, quickly.
TEST_F(SceneLoader, PipesDevicesDeepNestingAndHugeKeysAreRefusedQuickly) {
  const std::string fifo = dir.path() + "/scene.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(errorOf([&] { loadSceneFile(fifo); }),
            fifo + ": cannot open scene file (not a regular file: a pipe, socket or device cannot "
                   "be read as one)");
  EXPECT_EQ(error(R"({"camera": {}, "objects": [{"file": "/dev/zero"}]})"),
            "s.json: objects[0].file: cannot open \"/dev/zero\" (not a regular file: a pipe, "
            "socket or device cannot be read as one)");
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string nested = error(R"({"camera": {}, "spheres": )" + deep + "}");
  EXPECT_EQ(nested.rfind("s.json: spheres[0][0][0]", 0), 0u) << nested.substr(0, 200);
  EXPECT_NE(nested.find(": nested deeper than 64 levels; a scene never needs that"),
            std::string::npos);
  EXPECT_LT(nested.size(), 250u);
  const std::string longKey(1 << 20, 'x');
  const std::string unknown = error(R"({"camera": {}, ")" + longKey + R"(": 1})");
  EXPECT_LT(unknown.size(), 400u);
  EXPECT_EQ(unknown.rfind("s.json: [\"xxxxxxxx", 0), 0u) << unknown.substr(0, 200);
}

TEST_F(SceneLoader, CameraWithNonFiniteRaysIsRefused) {
  EXPECT_EQ(cameraError(R"({"width": 8, "height": 8,
                           "intrinsics": {"fx": 1e-45, "fy": 1e-45, "cx": 1, "cy": 1}})"),
            "s.json: camera.intrinsics: gives rays that are not finite (at pixel (0, 0)); "
            "expected intrinsics whose inverse maps every pixel to a finite direction");
  EXPECT_EQ(cameraError(R"({"intrinsics": [[1, 3e38, 2], [0, 1, 2], [0, 0, 1]]})"),
            "s.json: camera.intrinsics: gives rays that are not finite (at pixel (0, 0)); "
            "expected intrinsics whose inverse maps every pixel to a finite direction");
  EXPECT_EQ(cameraError(R"({"aperture_radius": 1e-45, "focus_distance": 1e-40})"),
            "s.json: camera.focus_distance: with aperture_radius 1.4013e-45 and focus distance "
            "9.99995e-41 the lens gives rays that are not finite; expected a larger aperture or "
            "focus distance");
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "look_at": [1e-45, 0, 0]})"),
            "s.json: camera.look_at: gives the camera no valid orientation (its rays would not be "
            "finite)");
  EXPECT_EQ(cameraError(R"({"fov": 1e-38})"),  // a field of view is not blamed as intrinsics
            "s.json: camera.fov: expected an invertible matrix K (the field of view gives none)");
}

// The image must fit in memory; width x height used to wrap in size_t and uint32 arithmetic.
TEST_F(SceneLoader, ImageTooLargeForMemoryIsRefused) {
  EXPECT_EQ(cameraError(R"({"width": 4294901790, "height": 1431677601})"),
            "s.json: camera.width: an image of 4294901790 x 1431677601 pixels would need "
            "6.87e+10 GiB; expected at most 268435456 pixels (16384 x 16384)");
  EXPECT_EQ(cameraError(R"({"width": 16384, "height": 16385})"),
            "s.json: camera.height: an image of 16384 x 16385 pixels would need 3 GiB; expected "
            "at most 268435456 pixels (16384 x 16384)");
  EXPECT_EQ(parse(R"({"camera": {"width": 16384, "height": 16384}})").camera.width, 16384u);
}

TEST_F(SceneLoader, CameraWithFovAndEulerRotation) {
  const CameraDesc c = camera(R"({"width": 640, "height": 480.0, "fov": 45, "position": [0, 0, 55],
                                  "rotation": [10, 20, 30], "spp": 4})");
  EXPECT_EQ(c.width, 640u);
  EXPECT_EQ(c.height, 480u);
  EXPECT_FLOAT_EQ(c.fov, 45);
  expectVec3(c.position, 0, 0, 55);
  expectVec3(c.rotation, 10, 20, 30);
  EXPECT_EQ(parse(R"({"camera": {"spp": 4}})").render.spp, 4u);  // the camera's spp is render.spp
}

TEST_F(SceneLoader, CameraWithIntrinsicsObject) {
  const CameraDesc c =
      camera(R"({"intrinsics": {"fx": 500, "fy": 400, "cx": 320.5, "cy": 240.5}})");
  ASSERT_TRUE(c.intrinsics);
  const float expected[3][3] = {{500, 0, 320.5f}, {0, 400, 240.5f}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(c.intrinsics->m[i][j], expected[i][j]);
}

TEST_F(SceneLoader, CameraWithIntrinsicsMatrix) {
  const CameraDesc c = camera(R"({"intrinsics": [[500, 0.5, 320], [0, 400, 240], [0, 0, 1]]})");
  ASSERT_TRUE(c.intrinsics);
  const float expected[3][3] = {{500, 0.5f, 320}, {0, 400, 240}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(c.intrinsics->m[i][j], expected[i][j]);
}

TEST_F(SceneLoader, CameraWithLookAt) {
  const CameraDesc c = camera(R"({"position": [1, 2, 3], "look_at": [0, 0, 0], "up": [0, 0, 1],
                                  "aperture_radius": 0.5})");
  expectVec3(c.position, 1, 2, 3);
  ASSERT_TRUE(c.lookAt);
  expectVec3(*c.lookAt, 0, 0, 0);
  expectVec3(c.up, 0, 0, 1);
  EXPECT_FLOAT_EQ(c.apertureRadius, 0.5f);
  EXPECT_FALSE(c.focusDistance);  // the distance to look_at, resolved later
}

TEST_F(SceneLoader, CameraWithExtrinsics) {
  // A half turn about x (OpenCV looking down -z of the world from [0, 0, 55]) and t = -R c.
  const CameraDesc c = camera(R"({"extrinsics": [[1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -1, 55],
                                                 [0, 0, 0, 1]],
                                  "aperture_radius": 1, "focus_distance": 50})");
  ASSERT_TRUE(c.extrinsicsR);
  ASSERT_TRUE(c.extrinsicsT);
  const float expected[3][3] = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(c.extrinsicsR->m[i][j], expected[i][j]);
  expectVec3(*c.extrinsicsT, 0, 0, 55);
  ASSERT_TRUE(c.focusDistance);
  EXPECT_FLOAT_EQ(*c.focusDistance, 50);
}

TEST_F(SceneLoader, MaterialForms) {
  const SceneDesc scene = parse(R"({"camera": {},
      "materials": {"red": {"type": "diffuse", "color": [0.9, 0.1, 0.1]},
                    "glass": {"type": "mirror"},
                    "lamp": {"type": "emissive", "radiance": [4, 3, 2]}},
      "spheres": [
        {"position": [0, 0, 0], "radius": 1, "material": "red"},
        {"position": [0, 0, 0], "radius": 1,
         "material": {"type": "glass", "ior": 1.33, "color": 0.9}},
        {"position": [0, 0, 0], "radius": 1, "material": "mirror", "color": [0.5, 0.6, 0.7]},
        {"position": [0, 0, 0], "radius": 1, "material": "diffuse"},
        {"position": [0, 0, 0], "radius": 1, "color": 0.25},
        {"position": [0, 0, 0], "radius": 1, "material": "glass"},
        {"position": [0, 0, 0], "radius": 1, "material": "lamp"}]})");
  ASSERT_EQ(scene.spheres.size(), 7u);
  const Material& named = scene.spheres[0].material;
  EXPECT_EQ(named.type, MaterialType::Diffuse);
  expectVec3(named.color, 0.9f, 0.1f, 0.1f);

  const Material& inlined = scene.spheres[1].material;
  EXPECT_EQ(inlined.type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(inlined.ior, 1.33f);
  expectVec3(inlined.color, 0.9f, 0.9f, 0.9f);

  const Material& shorthand = scene.spheres[2].material;
  EXPECT_EQ(shorthand.type, MaterialType::Conductor);  // a mirror: roughness 0, no Fresnel
  EXPECT_EQ(shorthand.roughness, 0.0f);
  EXPECT_FALSE(shorthand.metal);
  expectVec3(shorthand.color, 0.5f, 0.6f, 0.7f);

  EXPECT_EQ(scene.spheres[3].material.type, MaterialType::Diffuse);
  expectVec3(scene.spheres[3].material.color, 0.8f, 0.8f, 0.8f);

  EXPECT_EQ(scene.spheres[4].material.type, MaterialType::Diffuse);
  expectVec3(scene.spheres[4].material.color, 0.25f, 0.25f, 0.25f);

  // The library's "glass" (a mirror) wins over the shorthand of the same name.
  EXPECT_EQ(scene.spheres[5].material.type, MaterialType::Conductor);

  EXPECT_EQ(scene.spheres[6].material.type, MaterialType::Emissive);
  expectVec3(scene.spheres[6].material.radiance, 4, 3, 2);
}

TEST_F(SceneLoader, ShorthandDefaults) {
  const SceneDesc scene = parse(R"({"camera": {}, "spheres": [
      {"center": [0, 0, 0], "radius": 1, "material": "glass"},
      {"center": [0, 0, 0], "radius": 1, "material": "glass", "ior": 0.75},
      {"center": [0, 0, 0], "radius": 1, "material": "mirror"}]})");
  EXPECT_EQ(scene.spheres[0].material.type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(scene.spheres[0].material.ior, 1.5f);
  expectVec3(scene.spheres[0].material.color, 1, 1, 1);
  EXPECT_FLOAT_EQ(scene.spheres[1].material.ior, 0.75f);
  expectVec3(scene.spheres[2].material.color, 1, 1, 1);
}

TEST_F(SceneLoader, LightsAndEnvironment) {
  const SceneDesc scene = parse(R"({"camera": {},
      "lights": [{"id": "key", "type": "sphere", "position": [1, 2, 3], "radius": 0.5,
                  "intensity": 1e10, "color": [1, 0.5, 0.25]},
                 {"type": "point", "position": [0, 0, 0], "intensity": 0, "color": 2}],
      "environment": {"color": [0.1, 0.2, 0.3]}})");
  ASSERT_EQ(scene.lights.size(), 2u);
  const LightDesc& sphere = scene.lights[0];
  EXPECT_EQ(sphere.id, "key");
  EXPECT_EQ(sphere.where, "lights[0]");
  EXPECT_EQ(sphere.type, LightType::Sphere);
  expectVec3(sphere.position, 1, 2, 3);
  EXPECT_FLOAT_EQ(sphere.radius, 0.5f);
  EXPECT_FLOAT_EQ(sphere.intensity, 1e10f);
  expectVec3(sphere.color, 1, 0.5f, 0.25f);
  EXPECT_EQ(scene.lights[1].type, LightType::Point);
  expectVec3(scene.lights[1].color, 2, 2, 2);
  expectVec3(scene.environment.color, 0.1f, 0.2f, 0.3f);
}

TEST_F(SceneLoader, ObjectsResolveFilesAndKeepTheirOwnMaterials) {
  dir.write("meshes/tri.obj", kTriangleObj);
  const SceneDesc scene = parse(R"({"camera": {}, "objects": [
      {"id": "a", "file": "meshes/tri.obj", "position": [1, 2, 3], "rotation": [0, 90, 0],
       "scale": [2, -1, 3], "smooth": false},
      {"file": "meshes/tri.obj", "scale": 0.5, "color": [0.2, 0.3, 0.4]},
      {"file": "meshes/tri.obj", "material": "glass", "ior": 1.2}]})");
  ASSERT_EQ(scene.objects.size(), 3u);
  const ObjectDesc& a = scene.objects[0];
  EXPECT_EQ(a.id, "a");
  EXPECT_EQ(a.where, "objects[0]");
  EXPECT_EQ(a.file, (std::filesystem::path(dir.path()) / "meshes/tri.obj").string());
  expectVec3(a.position, 1, 2, 3);
  expectVec3(a.rotation, 0, 90, 0);
  expectVec3(a.scale, 2, -1, 3);
  EXPECT_FALSE(a.smooth);
  EXPECT_FALSE(a.material);  // the mesh's own (here the default) materials apply
  EXPECT_EQ(a.mesh->triangles.size(), 1u);
  // One file, read once: its objects share the mesh.
  EXPECT_EQ(scene.objects[1].mesh, a.mesh);
  EXPECT_EQ(scene.objects[2].mesh, a.mesh);

  expectVec3(scene.objects[1].scale, 0.5f, 0.5f, 0.5f);
  EXPECT_TRUE(scene.objects[1].smooth);
  ASSERT_TRUE(scene.objects[1].material);
  EXPECT_EQ(scene.objects[1].material->type, MaterialType::Diffuse);
  expectVec3(scene.objects[1].material->color, 0.2f, 0.3f, 0.4f);

  ASSERT_TRUE(scene.objects[2].material);
  EXPECT_EQ(scene.objects[2].material->type, MaterialType::Glass);
  EXPECT_FLOAT_EQ(scene.objects[2].material->ior, 1.2f);
}

TEST_F(SceneLoader, LoadSceneFileResolvesObjFilesNextToTheScene) {
  dir.write("scenes/meshes/tri.obj", kTriangleObj);
  const std::string path = dir.write(
      "scenes/one.json", R"({"camera": {"width": 32}, "objects": [{"file": "meshes/tri.obj"}]})");
  const SceneDesc scene = loadSceneFile(path);
  EXPECT_EQ(scene.file, path);
  EXPECT_EQ(scene.camera.width, 32u);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].mesh->positions.size(), 3u);

  const std::string bad = dir.write("scenes/bad.json", R"({"camera": {"width": -3}})");
  EXPECT_EQ(errorOf([&] { loadSceneFile(bad); }),
            bad + ": camera.width: expected a positive integer, got -3");
}

TEST_F(SceneLoader, KeysThatAreNotIdentifiersAreQuotedInPaths) {
  EXPECT_EQ(errorWith(R"("materials": {"red wall": {"type": "diffuse", "color": -1}})"),
            "s.json: materials[\"red wall\"].color: expected a non-negative number, got -1");
}

TEST(DidYouMean, EditDistanceCountsTranspositionsOnce) {
  EXPECT_EQ(editDistance("radius", "radius"), 0u);
  EXPECT_EQ(editDistance("raduis", "radius"), 1u);
  EXPECT_EQ(editDistance("colour", "color"), 1u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
}

TEST(DidYouMean, SuggestsOnlyCloseCandidates) {
  const std::vector<std::string> keys = {"position", "radius", "fov", "id"};
  EXPECT_EQ(closestMatch("raduis", keys), "radius");
  EXPECT_EQ(closestMatch("RADIUS", keys), "radius");
  EXPECT_EQ(closestMatch("postion", keys), "position");
  EXPECT_EQ(closestMatch("fvo", keys), "fov");
  EXPECT_EQ(closestMatch("size", keys), "");
  EXPECT_EQ(closestMatch("colour", keys), "");
}

}  // namespace
}  // namespace candela
