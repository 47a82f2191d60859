// Animation: every error class of the animation block pinned to its exact message, and the
// values sceneAtFrame interpolates at keys, between keys and outside the keyed range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>
#include <random>
#include <string>

#include "backends/cpu/cpu_renderer.h"
#include "geometry/bvh_traverse.h"
#include "scene/animation.h"
#include "scene/content_hash.h"
#include "scene/flatten.h"
#include "scene/frame_scene.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// A camera, a sphere "ball", an object-free scene with a point light "lamp" and a sphere light
// "bulb"; `animation` is the text of the animation block.
std::string sceneWith(const std::string& animation, const std::string& camera = "{}") {
  return R"({"camera": )" + camera + R"(,
    "spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "color": 0.5},
                {"id": "sun", "position": [0, 9, 0], "radius": 1,
                 "material": {"type": "emissive", "radiance": 1}}],
    "lights": [{"id": "lamp", "position": [0, 5, 0], "intensity": 10},
               {"id": "bulb", "type": "sphere", "position": [3, 5, 0], "radius": 0.5,
                "intensity": 10}],
    "animation": )" + animation + "}";
}

SceneDesc parse(const std::string& json) { return parseSceneText(json, "s.json", "."); }

std::string error(const std::string& animation, const std::string& camera = "{}") {
  try {
    parse(sceneWith(animation, camera));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no SceneError)";
}

std::string trackError(const std::string& track, const std::string& camera = "{}") {
  return error(R"({"frames": 10, "tracks": [)" + track + "]}", camera);
}

TEST(AnimationErrors, Frames) {
  EXPECT_EQ(error(R"({"frames": 0})"),
            "s.json: animation.frames: expected a positive integer, got 0");
  EXPECT_EQ(error(R"({"frames": 2.5})"),
            "s.json: animation.frames: expected a positive integer, got 2.5");
  EXPECT_EQ(error(R"({"fps": 24})"), "s.json: animation: missing required key \"frames\"");
  EXPECT_EQ(error(R"({"frames": 2, "fps": 0})"),
            "s.json: animation.fps: expected a positive number, got 0");
}

// Every frame's camera is checked at load, so a sequence never writes frames before a bad one:
// here the field of view shrinks to 1e-38 at the last frame.
TEST(AnimationErrors, CameraThatBecomesUnusableAtSomeFrame) {
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "fov", "keys": [[0, 60], [9, 1e-38]]})"),
            "s.json: animation: at frame 9 camera.fov expected an invertible matrix K (the field "
            "of view gives none)");
  // An animation as long as the limit with a camera track is checked in bounded time.
  EXPECT_EQ(error(R"({"frames": 1000001})"),
            "s.json: animation.frames: expected a positive integer of at most 1000000, got 1000001");
}

TEST(AnimationErrors, UnknownKeys) {
  EXPECT_EQ(error(R"({"frames": 2, "trakcs": []})"),
            "s.json: animation.trakcs: unknown key, did you mean \"tracks\"?");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "key": [[0, 1]]})"),
            "s.json: animation.tracks[0].key: unknown key, did you mean \"keys\"?");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius"})"),
            "s.json: animation.tracks[0]: missing required key \"keys\"");
}

TEST(AnimationErrors, UnknownTarget) {
  EXPECT_EQ(trackError(R"({"target": "bal", "property": "radius", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].target: no sphere, object or light has id \"bal\" "
            "(did you mean \"ball\"?)");
  EXPECT_EQ(trackError(R"({"target": "nothing", "property": "radius", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].target: no sphere, object or light has id "
            "\"nothing\"");
}

TEST(AnimationErrors, UnknownProperty) {
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "raduis", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].property: sphere \"ball\" has no animatable property "
            "\"raduis\", did you mean \"radius\"?");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "width", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].property: the camera has no animatable property "
            "\"width\", expected one of \"position\", \"rotation\", \"look_at\", \"up\", "
            "\"fov\", \"aperture_radius\", \"focus_distance\"");
  EXPECT_EQ(trackError(R"({"target": "lamp", "property": "scale", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].property: light \"lamp\" has no animatable property "
            "\"scale\", expected one of \"position\", \"intensity\", \"color\", "
            "\"radius\", \"direction\", \"look_at\", \"angle\", \"size\", \"up\"");
}

TEST(AnimationErrors, PropertyTheTargetDoesNotUse) {
  EXPECT_EQ(trackError(R"({"target": "lamp", "property": "radius", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].property: \"radius\" is not used by a point light "
            "(only \"sphere\" lights have a radius)");
  EXPECT_EQ(trackError(R"({"target": "sun", "property": "color", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].property: \"color\" is not used by an emissive "
            "material");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "fov", "keys": [[0, 30]]})",
                       R"({"intrinsics": {"fx": 100, "fy": 100, "cx": 50, "cy": 50}})"),
            "s.json: animation.tracks[0].property: \"fov\" is not used by a camera given by "
            "\"intrinsics\"");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "look_at", "keys": [[0, [0, 0, 0]]]})"),
            "s.json: animation.tracks[0].property: \"look_at\" is not used by a camera without "
            "\"look_at\"");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "rotation", "keys": [[0, [0, 0, 0]]]})",
                       R"({"position": [0, 0, 5], "look_at": [0, 0, 0]})"),
            "s.json: animation.tracks[0].property: \"rotation\" is not used by a camera aimed "
            "with \"look_at\"");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "focus_distance", "keys": [[0, 5]]})"),
            "s.json: animation.tracks[0].property: \"focus_distance\" is not used by a pinhole "
            "camera (aperture_radius 0)");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "aperture_radius", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].property: an animated \"aperture_radius\" needs "
            "\"focus_distance\" or \"look_at\" on the camera, or a focus_distance track");
}

TEST(AnimationErrors, WrongValueShape) {
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "position", "keys": [[0, 1]]})"),
            "s.json: animation.tracks[0].keys[0][1]: expected an array of 3 numbers, got 1");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": [[0, [1, 1, 1]]]})"),
            "s.json: animation.tracks[0].keys[0][1]: expected a positive number, got an array "
            "[1,1,1]");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": [[0, 1], [5, -1]]})"),
            "s.json: animation.tracks[0].keys[1][1]: expected a positive number, got -1");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "fov", "keys": [[0, 180]]})"),
            "s.json: animation.tracks[0].keys[0][1]: expected a number between 0 and 180 "
            "(exclusive), got 180");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "color", "keys": [[0, [1, 2]]]})"),
            "s.json: animation.tracks[0].keys[0][1]: expected a colour (a number or an array of 3 "
            "numbers), got an array [1,2]");
}

TEST(AnimationErrors, Keys) {
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": []})"),
            "s.json: animation.tracks[0].keys: expected a non-empty array of [frame, value] keys, "
            "got an array []");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": [1, 2]})"),
            "s.json: animation.tracks[0].keys[0]: expected a key [frame, value], got 1");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": [[-1, 2]]})"),
            "s.json: animation.tracks[0].keys[0][0]: expected a non-negative integer frame, got "
            "-1");
  EXPECT_EQ(
      trackError(
          R"({"target": "ball", "property": "radius", "keys": [[0, 1], [12, 2], [10, 3]]})"),
      "s.json: animation.tracks[0].keys[2]: frames must increase, got 10 after 12");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": [[3, 1], [3, 2]]})"),
            "s.json: animation.tracks[0].keys[1]: frames must increase, got 3 after 3");
}

TEST(AnimationErrors, DuplicateTrack) {
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "radius", "keys": [[0, 1]]},
                          {"target": "ball", "property": "radius", "keys": [[0, 2]]})"),
            "s.json: animation.tracks[1]: sphere \"ball\"'s radius is already animated by "
            "animation.tracks[0]");
}

TEST(AnimationErrors, LookAtCameraDegenerateAtSomeFrame) {
  // The camera moves from z=5 to z=-5 through the point it looks at, reached at frame 5.
  EXPECT_EQ(
      trackError(R"({"target": "camera", "property": "position",
                     "keys": [[0, [0, 0, 5]], [10, [0, 0, -5]]]})",
                 R"({"position": [0, 0, 5], "look_at": [0, 0, 0]})"),
      "s.json: animation: at frame 5 the camera looks at its own position");
  EXPECT_EQ(trackError(R"({"target": "camera", "property": "up",
                           "keys": [[0, [0, 1, 0]], [9, [0, 0, 1]]]})",
                       R"({"position": [0, 0, 5], "look_at": [0, 0, 0]})"),
            "s.json: animation: at frame 9 the camera looks along its up direction");
}

TEST(AnimationErrors, SphereLightBeyondSinglePrecisionAtSomeFrame) {
  // The bulb (intensity 10) shrinks to a radius whose square underflows at the last key.
  EXPECT_EQ(error(R"({"frames": 12, "tracks": [
                {"target": "bulb", "property": "radius", "keys": [[0, 0.5], [10, 1e-25]]}]})"),
            "s.json: lights[1]: at frame 10, its surface's radiance, intensity 10 times color "
            "[1, 1, 1] over a sphere of radius 1e-25, is beyond single precision; expected a "
            "larger radius or a smaller intensity");
  // A still light's own values are not checked where a track replaces them at every frame.
  EXPECT_EQ(parseSceneText(R"({"camera": {}, "lights": [{"id": "b", "type": "sphere",
                "position": [0, 0, 0], "intensity": 10, "radius": 1e-25}],
                "animation": {"frames": 2, "tracks": [
                {"target": "b", "property": "radius", "keys": [[0, 1]]}]}})",
                           "s.json", ".")
                .lights.size(),
            1u);
}

TEST(AnimationErrors, SphereBeyondSinglePrecisionsReachAtSomeFrame) {
  EXPECT_EQ(error(R"({"frames": 12, "tracks": [{"target": "ball", "property": "position",
                      "keys": [[0, [0, 0, 0]], [10, [0, 4e18, 0]]]}]})"),
            "s.json: spheres[0]: at frame 3, the sphere reaches 1.2e+18 from the origin; expected "
            "geometry within 1e+18 (single precision cannot intersect it further out)");
}

TEST(AnimationErrors, ScaleMayNotChangeSign) {
  // Objects need an OBJ file; the check is on the keys, so an object scene is built here.
  try {
    parseSceneText(R"({"camera": {}, "objects": [{"id": "m", "file": "none.obj"}],
        "animation": {"frames": 2, "tracks": [
          {"target": "m", "property": "scale", "keys": [[0, 1], [1, [1, -1, 1]]]}]}})",
                   "s.json", ".");
    FAIL() << "no SceneError";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "s.json: animation.tracks[0].keys[1][1]: scale changes sign between keys, so "
                 "the mesh would pass through zero size");
  }
}

// ---------------------------------------------------------------------------------------------
// Interpolation.

TEST(SceneAtFrame, InterpolatesAtKeysBetweenKeysAndHoldsOutside) {
  const SceneDesc scene = parse(sceneWith(R"({"frames": 20, "fps": 12, "tracks": [
      {"target": "ball", "property": "position", "keys": [[2, [0, 0, 0]], [6, [4, -8, 2]],
                                                          [10, [4, 0, 2]]]},
      {"target": "ball", "property": "radius", "keys": [[0, 1], [4, 3]]},
      {"target": "lamp", "property": "color", "keys": [[0, 0], [2, [1, 0.5, 2]]]},
      {"target": "camera", "property": "fov", "keys": [[5, 90]]}]})"));
  ASSERT_TRUE(scene.animation);
  EXPECT_FLOAT_EQ(scene.animation->fps, 12);
  const auto ball = [&](uint32_t frame) { return sceneAtFrame(scene, frame).spheres[0]; };
  // Held before the first key, exact at keys, linear between, held after the last.
  EXPECT_EQ(ball(0).position.x, 0);
  EXPECT_EQ(ball(2).position.y, 0);
  EXPECT_EQ(ball(6).position.y, -8);
  EXPECT_EQ(ball(4).position.x, 2);
  EXPECT_EQ(ball(4).position.y, -4);
  EXPECT_EQ(ball(4).position.z, 1);
  EXPECT_EQ(ball(7).position.y, -6);
  EXPECT_EQ(ball(8).position.y, -4);
  EXPECT_EQ(ball(19).position.y, 0);
  EXPECT_EQ(ball(19).position.x, 4);
  EXPECT_EQ(ball(1).radius, 1.5f);
  EXPECT_EQ(ball(3).radius, 2.5f);
  EXPECT_EQ(ball(100).radius, 3);
  // A colour given as a number is grey; a single key holds everywhere.
  EXPECT_EQ(sceneAtFrame(scene, 0).lights[0].color.y, 0);
  EXPECT_EQ(sceneAtFrame(scene, 1).lights[0].color.z, 1);
  EXPECT_EQ(sceneAtFrame(scene, 1).lights[0].color.y, 0.25f);
  EXPECT_EQ(sceneAtFrame(scene, 0).camera.fov, 90);
  EXPECT_EQ(sceneAtFrame(scene, 19).camera.fov, 90);
  // Untouched values stay; the still has no animation block.
  EXPECT_EQ(sceneAtFrame(scene, 3).spheres[0].material.color.x, 0.5f);
  EXPECT_FALSE(sceneAtFrame(scene, 3).animation);
}

TEST(SceneAtFrame, SeedAdvancesWithTheFrame) {
  SceneDesc scene = parse(sceneWith(R"({"frames": 3})"));
  scene.render.seed = 40;
  EXPECT_EQ(sceneAtFrame(scene, 0).render.seed, 40u);
  EXPECT_EQ(sceneAtFrame(scene, 2).render.seed, 42u);
  scene.animation.reset();  // a still scene in a sequence of files gets the same seeds
  EXPECT_EQ(sceneAtFrame(scene, 5).render.seed, 45u);
}

TEST(SceneAtFrame, ColourTrackOnAnObjectWithoutMaterialMakesItDiffuse) {
  SceneDesc scene;
  scene.objects.resize(1);
  AnimTrack track;
  track.target = AnimTarget::Object;
  track.property = AnimProperty::Color;
  track.keys = {{0, Vec3(0.25f)}};
  scene.animation = AnimationDesc{};
  scene.animation->tracks.push_back(track);
  const SceneDesc still = sceneAtFrame(scene, 0);
  ASSERT_TRUE(still.objects[0].material);
  EXPECT_EQ(still.objects[0].material->type, MaterialType::Diffuse);
  EXPECT_EQ(still.objects[0].material->color.x, 0.25f);
}

// Renders a frame of an animation and the still scene it should equal, and expects them equal to
// the bit; returns the still's image.
ImageRGB expectSameRender(const SceneDesc& frame, const SceneDesc& still) {
  const SceneData frameData = flattenScene(frame), stillData = flattenScene(still);
  const RenderResult a = renderCpu(frameData.view(), RenderOptions{});
  const RenderResult b = renderCpu(stillData.view(), RenderOptions{});
  for (uint32_t y = 0; y < b.image.height; ++y)
    for (uint32_t x = 0; x < b.image.width; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(a.image.at(x, y)[c], b.image.at(x, y)[c]);
  return b.image;
}

// A roughness track sets the material's roughness at each frame and what the material derives
// from it: a plastic's coat tables are those of a plastic of that roughness; an anisotropy track
// likewise. Frame 2 of the animation renders, to the bit, as the still scene with those values
// and the frame's seed.
TEST(SceneAtFrame, RoughnessTrackRendersAsTheStillOfThatRoughness) {
  const auto shells = [](const std::string& plastic, const std::string& animation,
                         const std::string& anisotropy = "0.5") {
    return R"({"camera": {"width": 12, "height": 8, "position": [0, 0, 5], "spp": 4},
      "spheres": [{"id": "shell", "position": [0, 0, 0], "radius": 1,
                   "material": {"type": "plastic", "color": 0.4, "roughness": )" +
           plastic + R"(}},
                  {"id": "metal", "position": [2.5, 0, 0], "radius": 1,
                   "material": {"type": "conductor", "metal": "Au", "roughness": )" +
           plastic + R"(, "anisotropy": )" + anisotropy + R"(}}],
      "lights": [{"position": [0, 5, 5], "intensity": 100}])" +
           animation + "}";
  };
  const SceneDesc animated = parse(shells("0.25", R"(, "animation": {"frames": 5, "tracks": [
      {"target": "shell", "property": "roughness", "keys": [[0, 0.25], [4, 0.75]]},
      {"target": "metal", "property": "roughness", "keys": [[0, 0.25], [4, 0.75]]},
      {"target": "metal", "property": "anisotropy", "keys": [[0, 0.25], [4, 0.75]]}]})",
                                          "0.25"));
  SceneDesc still = parse(shells("0.5", ""));
  still.render.seed += 2;
  const SceneDesc frame = sceneAtFrame(animated, 2);
  const Material& shell = frame.spheres[0].material;
  EXPECT_EQ(shell.roughness, 0.5f);
  EXPECT_EQ(frame.spheres[1].material.roughness, 0.5f);
  EXPECT_EQ(frame.spheres[1].material.anisotropy, 0.5f);
  const Material& reference = still.spheres[0].material;
  EXPECT_EQ(shell.plasticInternalReflectance, reference.plasticInternalReflectance);
  for (uint32_t i = 0; i < kPlasticTableSize; ++i)
    EXPECT_EQ(shell.plasticTransmittance[i], reference.plasticTransmittance[i]) << i;
  expectSameRender(frame, still);
}

// A scattering track on glass (fog that thickens, milk that thins) renders frame 2 to the bit as
// the still scene of that scattering and the frame's seed; glass without a static "scattering"
// may be given one by a track.
TEST(SceneAtFrame, ScatteringTrackRendersAsTheStillOfThatScattering) {
  const auto fog = [](const std::string& scattering, const std::string& animation) {
    return R"({"camera": {"width": 12, "height": 8, "position": [0, 0, 5], "spp": 4},
      "render": {"max_depth": 16},
      "environment": {"color": 0.5},
      "spheres": [{"id": "fog", "position": [0, 0, 0], "radius": 1,
                   "material": {"type": "glass", "ior": 1.2)" +
           scattering + R"(}}])" + animation + "}";
  };
  const SceneDesc animated = parse(fog("", R"(, "animation": {"frames": 5, "tracks": [
      {"target": "fog", "property": "scattering", "keys": [[0, [0, 1, 2]], [4, [2, 3, 6]]]}]})"));
  SceneDesc still = parse(fog(R"(, "scattering": [1, 2, 4])", ""));
  still.render.seed += 2;
  const SceneDesc frame = sceneAtFrame(animated, 2);
  const Vec3 scattering = frame.spheres[0].material.scattering;
  EXPECT_EQ(scattering.x, 1.0f);
  EXPECT_EQ(scattering.y, 2.0f);
  EXPECT_EQ(scattering.z, 4.0f);
  const ImageRGB stillImage = expectSameRender(frame, still);
  // Frame 0's clear glass is not the still's scattering glass.
  const SceneData clearData = flattenScene(sceneAtFrame(animated, 0));
  EXPECT_NE(renderCpu(clearData.view(), RenderOptions{}).image.at(6, 4)[2], stillImage.at(6, 4)[2]);
}

TEST(AnimationErrors, ScatteringOfWhatIsNotGlass) {
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "scattering", "keys": [[0, 2]]})"),
            "s.json: animation.tracks[0].property: \"scattering\" is not used by a material "
            "other than \"glass\"");
}

TEST(AnimationErrors, RoughnessOfWhatHasNone) {
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "roughness", "keys": [[0, 0.5]]})"),
            "s.json: animation.tracks[0].property: \"roughness\" is not used by a \"diffuse\" "
            "material");
  EXPECT_EQ(trackError(R"({"target": "sun", "property": "roughness", "keys": [[0, 0.5]]})"),
            "s.json: animation.tracks[0].property: \"roughness\" is not used by an emissive "
            "material");
  EXPECT_EQ(trackError(R"({"target": "ball", "property": "anisotropy", "keys": [[0, 0.5]]})"),
            "s.json: animation.tracks[0].property: \"anisotropy\" is not used by a \"diffuse\" "
            "material");
  const std::string metal = R"({"camera": {},
    "spheres": [{"id": "ball", "radius": 1, "position": [0, 0, 0],
                 "material": {"type": "conductor", "roughness": 0.3}}],
    "animation": {"frames": 3, "tracks": [
      {"target": "ball", "property": "roughness", "keys": [[0, 0.3], [2, 1.5]]}]}})";
  try {
    parse(metal);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "s.json: animation.tracks[0].keys[1][1]: expected a roughness in [0, 1], got 1.5");
  }
}

TEST(SceneAtFrame, OrbitExampleLoopsSeamlessly) {
  const SceneDesc scene = loadSceneFile(std::string(CANDELA_SOURCE_DIR) + "/scenes/orbit.json");
  ASSERT_TRUE(scene.animation);
  EXPECT_EQ(scene.animation->frames, 48u);
  // Frame 48, one past the last, would repeat frame 0: the camera is back, the knot turned 360.
  const SceneDesc first = sceneAtFrame(scene, 0), next = sceneAtFrame(scene, 48);
  EXPECT_EQ(first.camera.position.x, 0);
  EXPECT_EQ(next.camera.position.z, first.camera.position.z);
  EXPECT_FLOAT_EQ(next.objects[0].rotation.y - first.objects[0].rotation.y, 360);
}

// ---------------------------------------------------------------------------------------------
// Reuse of geometry and BVH between frames.

template <typename T, class Allocator>
bool sameBytes(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// The triangles in a canonical order: flattenScene numbers them in its tree's leaf order, and a
// refitted tree keeps the order of the tree it was built as.
std::vector<Triangle> sortedTriangles(std::vector<Triangle> t) {
  std::sort(t.begin(), t.end(), [](const Triangle& x, const Triangle& y) {
    return std::memcmp(&x, &y, sizeof(Triangle)) < 0;
  });
  return t;
}

// Everything the renderer sees of `a` and `b` but the BVH (and so the triangles' order) is the
// same, byte for byte.
void expectSameContents(const SceneData& a, const SceneData& b) {
  EXPECT_TRUE(sameBytes(a.materials, b.materials));
  EXPECT_TRUE(sameBytes(a.spheres, b.spheres));
  EXPECT_TRUE(sameBytes(a.lights, b.lights));
  EXPECT_TRUE(sameBytes(a.positions, b.positions));
  EXPECT_TRUE(sameBytes(sortedTriangles(a.triangles), sortedTriangles(b.triangles)));
  EXPECT_EQ(std::memcmp(&a.camera, &b.camera, sizeof(Camera)), 0);
  EXPECT_EQ(a.settings.seed, b.settings.seed);
}

// The environments are the same, field by field (the struct has padding bytes).
void expectSameEnvironment(const Environment& a, const Environment& b) {
  EXPECT_EQ(std::memcmp(&a.radiance, &b.radiance, sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(&a.toWorld, &b.toWorld, sizeof(Mat3)), 0);
  EXPECT_EQ(std::memcmp(&a.fromWorld, &b.fromWorld, sizeof(Mat3)), 0);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.grid.columns, b.grid.columns);
  EXPECT_EQ(a.grid.rows, b.grid.rows);
  EXPECT_EQ(a.grid.shifted, b.grid.shifted);
  EXPECT_EQ(a.light, b.light);
}

// ... and so is every array, the BVH included.
void expectSameScene(const SceneData& a, const SceneData& b) {
  expectSameContents(a, b);
#define CANDELA_EXPECT_SAME_ARRAY(Type, name, count, rewrittenBy) \
  EXPECT_TRUE(sameBytes(a.name, b.name)) << #name;
  CANDELA_SCENE_ARRAYS(CANDELA_EXPECT_SAME_ARRAY)
#undef CANDELA_EXPECT_SAME_ARRAY
}

// A refitted BVH is another tree over the same primitives: it must find exactly the nearest hit
// that testing every primitive finds, for rays through the whole scene.
void expectBvhFindsNearestHits(const SceneData& scene) {
  const SceneView view = scene.view();
  Vec3 lo, hi;
  scene.bounds(&lo, &hi);
  std::mt19937 gen(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 a(lo.x + u(gen) * (hi.x - lo.x), lo.y + u(gen) * (hi.y - lo.y),
                 lo.z + u(gen) * (hi.z - lo.z));
    const Vec3 b(lo.x + u(gen) * (hi.x - lo.x), lo.y + u(gen) * (hi.y - lo.y),
                 lo.z + u(gen) * (hi.z - lo.z));
    Ray ray;
    ray.origin = a + (a - b) * 2.0f;  // from outside the scene, through two random points
    ray.direction = normalize(b - a);
    Hit viaBvh, bruteForce;
    const bool hitBvh = intersectClosest(view, ray, &viaBvh);
    ASSERT_EQ(hitBvh, intersectClosestBruteForce(view, ray, &bruteForce)) << "ray " << i;
    if (hitBvh) {
      EXPECT_EQ(viaBvh.prim, bruteForce.prim) << "ray " << i;
      EXPECT_EQ(viaBvh.t, bruteForce.t) << "ray " << i;
    }
  }
}

TEST(FrameScene, CameraAndLightChangesReuseTheBvhAndARadiusChangeRefitsIt) {
  const SceneDesc scene = parse(sceneWith(R"({"frames": 6, "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [0, 0, 9]], [2, [1, 0, 9]]]},
      {"target": "lamp", "property": "intensity", "keys": [[0, 10], [3, 40]]},
      {"target": "ball", "property": "color", "keys": [[0, 0.5], [3, 0.9]]},
      {"target": "ball", "property": "radius", "keys": [[3, 1], [5, 1.3]]}]})"));
  FrameScene frames;
  using P = SceneChange;
  const P expected[6] = {P::Structure, P::Values, P::Values, P::Values, P::Motion, P::Motion};
  for (uint32_t f = 0; f < 6; ++f) {
    const SceneDesc still = sceneAtFrame(scene, f);
    const SceneData& data = frames.prepare(still);
    EXPECT_EQ(frames.change(), expected[f]) << "frame " << f;
    if (expected[f] == P::Motion) {
      expectSameContents(data, flattenScene(still));
      expectBvhFindsNearestHits(data);
    } else {
      expectSameScene(data, flattenScene(still));
    }
  }
}

TEST(FrameScene, ObjectTransformChangeRefitsAndMeshChangeRebuilds) {
  SceneDesc scene;
  ObjectDesc object;
  auto mesh = std::make_shared<MeshDesc>();
  mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  mesh->triangles = {MeshTriangle{{0, 1, 2}, {-1, -1, -1}, 0}};
  mesh->materials = {Material{}};
  object.mesh = mesh;
  scene.objects.push_back(object);
  FrameScene frames;
  frames.prepare(scene);
  scene.camera.fov = 30;
  frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Values);
  scene.objects[0].rotation = Vec3(0, 10, 0);
  expectSameContents(frames.prepare(scene), flattenScene(scene));
  EXPECT_EQ(frames.change(), SceneChange::Motion);
  auto other = std::make_shared<MeshDesc>(*mesh);
  other->triangles[0].v[2] = 1;  // same transform, other triangles
  other->positions.push_back(Vec3(0, 2, 0));
  other->triangles.push_back(MeshTriangle{{0, 2, 3}, {-1, -1, -1}, 0});
  scene.objects[0].mesh = other;
  expectSameScene(frames.prepare(scene), flattenScene(scene));
  EXPECT_EQ(frames.change(), SceneChange::Structure);
}

// A mesh whose vertices move (a glTF animation's pose) over the same triangles is a motion, as a
// transform is: refitted, with the moved normals; a mesh with other texture coordinates is a new
// structure (they decide its vertices' layout).
TEST(FrameScene, AMeshPosedAnewRefitsAndOtherUvsRebuild) {
  SceneDesc scene;
  auto mesh = std::make_shared<MeshDesc>();
  for (int i = 0; i < 8; ++i)
    mesh->positions.push_back(Vec3(float(i & 1), float((i >> 1) & 1), float(i >> 2)));
  mesh->normals = {Vec3(0, 0, 1)};
  for (uint32_t i = 0; i < 6; ++i)
    mesh->triangles.push_back(MeshTriangle{{i, i + 1, i + 2}, {0, 0, 0}, 0});
  mesh->materials = {Material{}};
  ObjectDesc object;
  object.mesh = mesh;
  object.smooth = true;
  scene.objects.push_back(object);
  for (OwnBvh kind : {OwnBvh::Sah, OwnBvh::None}) {
    SCOPED_TRACE(kind == OwnBvh::None ? "no own BVH" : "own BVH");
    scene.ownBvh = kind;
    scene.objects[0].mesh = mesh;
    FrameScene frames;
    frames.prepare(scene);
    auto posed = std::make_shared<MeshDesc>(*mesh);
    for (Vec3& p : posed->positions) p = Vec3(p.x + 0.3f * p.z, p.y * 1.5f, p.z);
    posed->normals = {normalize(Vec3(0.2f, 0, 1))};
    scene.objects[0].mesh = posed;
    const SceneData& moved = frames.prepare(scene);
    EXPECT_EQ(frames.change(), SceneChange::Motion);
    expectSameContents(moved, flattenScene(scene));
    if (kind != OwnBvh::None) expectBvhFindsNearestHits(moved);

    auto unwrapped = std::make_shared<MeshDesc>(*posed);
    unwrapped->uvs = {Vec2(0.5f, 0.5f)};
    scene.objects[0].mesh = unwrapped;
    expectSameScene(frames.prepare(scene), flattenScene(scene));
    EXPECT_EQ(frames.change(), SceneChange::Structure);
  }
}

// A frame whose object's material begins to read the mesh's uvs lays the mesh out anew (its seams
// now split vertices: scene/mesh_layout.h), so it is a new structure, not new values.
TEST(FrameScene, AMaterialThatBeginsToReadUvsIsANewStructure) {
  SceneDesc scene;
  auto mesh = std::make_shared<MeshDesc>();
  mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  mesh->uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(0.5f, 0.5f)};
  mesh->triangles = {MeshTriangle{{0, 1, 2}, {-1, -1, -1}, 0},
                     MeshTriangle{{1, 3, 2}, {-1, -1, -1}, 0}};
  mesh->triangles[0].t[0] = 0, mesh->triangles[0].t[1] = 1, mesh->triangles[0].t[2] = 2;
  mesh->triangles[1].t[0] = 3, mesh->triangles[1].t[1] = 0, mesh->triangles[1].t[2] = 2;  // a seam
  mesh->materials = {Material{}};
  ObjectDesc object;
  object.mesh = mesh;
  object.material = Material{};
  scene.objects.push_back(object);
  auto texture = std::make_shared<TextureDesc>();
  texture->width = 2;
  texture->height = 1;
  texture->texels8.assign(8, 100);
  scene.textures = {texture};
  FrameScene frames;
  EXPECT_EQ(frames.prepare(scene).positions.size(), 4u);
  scene.objects[0].material->colorTexture.index = 0;
  const SceneData& textured = frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Structure);
  expectSameScene(textured, flattenScene(scene));
  EXPECT_EQ(textured.positions.size(), 5u);  // vertex 1 with uv 1 and with uv 3
  EXPECT_EQ(textured.uvs.size(), 5u);
}

// Frames that change only values or move primitives keep the texture pool (the GPU backend then
// uploads it once: render/scene_change.h), and a frame with another texture is a new structure.
TEST(FrameScene, TexturePoolStaysUntilTheTexturesChange) {
  const auto texture = [](uint8_t value) {
    auto t = std::make_shared<TextureDesc>();
    t->width = 2;
    t->height = 1;
    t->texels8.assign(8, value);
    t->contentHash = value;  // as the reader's hash of the texels would differ
    return t;
  };
  SceneDesc scene;
  ObjectDesc object;
  auto mesh = std::make_shared<MeshDesc>();
  mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  mesh->triangles = {MeshTriangle{{0, 1, 2}, {-1, -1, -1}, 0}};
  Material textured;
  textured.colorTexture.index = 0;
  mesh->materials = {textured};
  object.mesh = mesh;
  scene.objects.push_back(object);
  scene.textures = {texture(100)};
  auto map = std::make_shared<ImageRGB>(4, 2);
  map->set(1, 0, Vec3(9, 8, 7));
  scene.environment.image = map;
  FrameScene frames;
  // A mark in the pool survives a frame that keeps the pool; a copy would put back 100.
  const_cast<uint8_t*>(frames.prepare(scene).texels8.data())[0] = 77;
  scene.camera.fov = 30;
  EXPECT_EQ(frames.prepare(scene).texels8[0], 77) << "the pool was copied again";
  EXPECT_EQ(frames.change(), SceneChange::Values);
  SceneData fresh = flattenScene(scene);  // all else as a fresh flattening has it
  fresh.texels8[0] = 77;
  const SceneData& kept = frames.prepare(scene);
  expectSameScene(kept, fresh);
  // Likewise a mark in the environment's distribution, which a refit frame keeps.
  const_cast<float*>(kept.envConditionalCdf.data())[0] = -1.0f;
  scene.objects[0].rotation = Vec3(0, 10, 0);  // a refit moves the pool over too
  const SceneData& moved = frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Motion);
  EXPECT_EQ(moved.texels8[0], 77) << "the pool was copied again";
  EXPECT_EQ(moved.envConditionalCdf[0], -1.0f) << "the environment was built again";
  SceneData movedFresh = flattenScene(scene);
  movedFresh.envConditionalCdf[0] = -1.0f;
  expectSameEnvironment(moved.environment, movedFresh.environment);
  EXPECT_TRUE(sameBytes(moved.envTexels, movedFresh.envTexels));
  EXPECT_TRUE(sameBytes(moved.envConditionalCdf, movedFresh.envConditionalCdf));
  EXPECT_TRUE(sameBytes(moved.envMarginalGuide, movedFresh.envMarginalGuide));
  // A new structure with the same textures keeps the pool.
  scene.spheres.push_back(SphereDesc{});
  EXPECT_EQ(frames.prepare(scene).texels8[0], 77) << "the pool was copied again";
  EXPECT_EQ(frames.change(), SceneChange::Structure);
  // Other textures are a new structure: a new pool, but the same map keeps its arrays.
  scene.textures = {texture(200)};
  const SceneData& rebuilt = frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Structure);
  SceneData rebuiltFresh = flattenScene(scene);
  rebuiltFresh.envConditionalCdf[0] = -1.0f;
  expectSameScene(rebuilt, rebuiltFresh);
  EXPECT_EQ(rebuilt.texels8[0], 200);
}

// The frames of a sequence of scene files each read the map anew: equal texels keep the arrays,
// other texels make them again.
TEST(FrameScene, EnvironmentArraysStayWhileTheMapsTexelsDo) {
  const auto map = [](float texel) {
    auto image = std::make_shared<ImageRGB>(4, 2);
    image->set(1, 0, Vec3(texel, 8, 7));
    return image;
  };
  SceneDesc scene;
  scene.environment.image = map(9);
  scene.environment.mapHash = hashImage(*scene.environment.image);
  FrameScene frames;
  const_cast<float*>(frames.prepare(scene).envConditionalCdf.data())[0] = -1.0f;
  scene.environment.image = map(9);  // another copy of the same map
  scene.environment.mapHash = hashImage(*scene.environment.image);
  scene.spheres.push_back(SphereDesc{});  // and a new structure
  EXPECT_EQ(frames.prepare(scene).envConditionalCdf[0], -1.0f) << "the arrays were made again";
  EXPECT_EQ(frames.change(), SceneChange::Structure);
  scene.environment.image = map(5);
  scene.environment.mapHash = 0;  // made in memory: flattening hashes it
  expectSameScene(frames.prepare(scene), flattenScene(scene));
  EXPECT_EQ(frames.change(), SceneChange::Values);
}

// What a resident scene (the GPU's) moves: the frame's change rewrites the arrays at or below it,
// the keyed groups only their own keys do.
TEST(SceneUpdate, KeyedGroupsAreRewrittenByTheirOwnChangesOnly) {
  using R = RewrittenBy;
  const SceneUpdate structure{SceneChange::Structure, false, false, false};
  EXPECT_TRUE(mayRewrite(structure, R::Structure));
  EXPECT_TRUE(mayRewrite(structure, R::Values));
  EXPECT_FALSE(mayRewrite(structure, R::EnvironmentMap));
  EXPECT_FALSE(mayRewrite(structure, R::LightTree));
  EXPECT_FALSE(mayRewrite(structure, R::TexturePool));
  const SceneUpdate values{SceneChange::Values, true, false, false};
  EXPECT_TRUE(mayRewrite(values, R::Values));
  EXPECT_FALSE(mayRewrite(values, R::Motion));
  EXPECT_TRUE(mayRewrite(values, R::EnvironmentMap));
  EXPECT_FALSE(mayRewrite(values, R::LightTree));
  EXPECT_FALSE(mayRewrite(values, R::TexturePool));
  EXPECT_TRUE(mayRewrite(SceneUpdate{SceneChange::Motion, false, true, false}, R::LightTree));
  EXPECT_TRUE(mayRewrite(SceneUpdate{SceneChange::Values, false, false, true}, R::TexturePool));
  EXPECT_TRUE(mayRewrite(SceneUpdate{}, R::EnvironmentMap));  // a first upload moves everything
  EXPECT_TRUE(mayRewrite(SceneUpdate{}, R::TexturePool));
}

// A 10 x 10 grid of unit squares in the plane z = 0, two triangles each.
std::shared_ptr<const MeshDesc> gridOfTriangles() {
  auto grid = std::make_shared<MeshDesc>();
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 10; ++j) grid->positions.push_back(Vec3(float(i), float(j), 0.0f));
  for (uint32_t i = 0; i < 10; ++i)
    for (uint32_t j = 0; j < 10; ++j) {
      const uint32_t a = i * 11 + j, b = a + 11;
      grid->triangles.push_back(MeshTriangle{{a, b, a + 1}, {-1, -1, -1}, 0});
      grid->triangles.push_back(MeshTriangle{{b, b + 1, a + 1}, {-1, -1, -1}, 0});
    }
  grid->materials = {Material{}};
  return grid;
}

// Two of gridOfTriangles's grids, at x = -60 and x = 50.
void addTwoGridsApart(SceneDesc& scene) {
  const std::shared_ptr<const MeshDesc> grid = gridOfTriangles();
  for (float x : {-60.0f, 50.0f}) {
    ObjectDesc object;
    object.mesh = grid;
    object.position = Vec3(x, 0, 0);
    scene.objects.push_back(object);
  }
}

// Two grids of triangles far apart, then moved into each other: refitting would leave boxes that
// overlap almost entirely, so the SAH cost says rebuild; a small move is refitted.
TEST(FrameScene, RefitUnlessTheTreeDegradesThenRebuild) {
  SceneDesc scene;
  auto map = std::make_shared<ImageRGB>(4, 2);
  map->set(2, 1, Vec3(1, 2, 3));
  scene.environment.image = map;
  addTwoGridsApart(scene);
  FrameScene frames;
  frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Structure);

  scene.objects[0].position.x += 0.5f;
  const SceneData& nudged = frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Motion);
  expectSameContents(nudged, flattenScene(scene));
  expectBvhFindsNearestHits(nudged);

  // The refit is rejected and a new tree built, keeping the map's arrays (marked).
  const_cast<float*>(nudged.envConditionalCdf.data())[0] = -1.0f;
  scene.objects[0].position = Vec3(0, 0, 0);
  scene.objects[1].position = Vec3(5, 0, -5);
  scene.objects[1].rotation = Vec3(0, 90, 0);
  SceneData fresh = flattenScene(scene);
  fresh.envConditionalCdf[0] = -1.0f;
  expectSameScene(frames.prepare(scene), fresh);
  EXPECT_EQ(frames.change(), SceneChange::Structure);
}

// The same move under a ground sphere of radius 1000, whose box dwarfs the grids': the root's
// cost barely moves, but that of the grids' part of the tree grows, and the refit is rejected.
TEST(FrameScene, ADegradedSubtreeIsRebuiltUnderAHugeSphere) {
  SceneDesc scene;
  SphereDesc ground;
  ground.position = Vec3(0, -1000, 0);
  ground.radius = 1000;
  scene.spheres.push_back(ground);
  addTwoGridsApart(scene);
  FrameScene frames;
  const std::vector<BvhNode> built = frames.prepare(scene).nodes;
  const BvhCostProfile profile = bvhCostProfile(built);
  ASSERT_GT(profile.parts.size(), 1u);

  scene.objects[0].position = Vec3(0, 0, 0);
  scene.objects[1].position = Vec3(5, 0, -5);
  scene.objects[1].rotation = Vec3(0, 90, 0);
  const SceneData& moved = frames.prepare(scene);
  EXPECT_EQ(frames.change(), SceneChange::Structure);
  expectSameScene(moved, flattenScene(scene));
  // The tree refitted over the grids' new places: the root's cost alone would have let it stand.
  SceneData refitted = flattenSceneContents(scene);
  std::vector<BvhNode> nodes = built;
  const SceneData first = [&] {
    SceneDesc before = scene;
    before.objects[0].position = Vec3(-60, 0, 0);
    before.objects[1].position = Vec3(50, 0, 0);
    before.objects[1].rotation = Vec3(0, 0, 0);
    return flattenScene(before);
  }();
  refitBvh(nodes, first.primIndices, refitted.spheres.data(), uint32_t(refitted.spheres.size()),
           refitted.positions.data(), first.triangles.data());
  const BvhCostProfile rootOnly{{profile.parts[0]}};
  EXPECT_LT(bvhCostGrowth(nodes, rootOnly), 1.01);
  EXPECT_GT(bvhCostGrowth(nodes, profile), kRefitCostLimit);
}

}  // namespace
}  // namespace candela
