// `candela render --aov`: passes as layers of a multi-layer EXR, as sibling .pfm files beside a
// PNG, per frame of a sequence, and the usage errors, through the real binary (CANDELA_BINARY).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "image/atomic_file.h"
#include "image/image_io.h"
#include "image_difference.h"
#include "moving_sphere_scene.h"
#include "require_gpu.h"
#include "temp_dir.h"

namespace fs = std::filesystem;

namespace {

// A grey unit sphere 5 before the camera, on a 15x15 image whose centre pixel lies on its axis.
const char* kScene = R"({
  "camera": {"width": 15, "height": 15, "fov": 30, "spp": 4, "position": [0, 0, 5]},
  "render": {"antialiasing": false},
  "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
  "lights": [{"position": [0, 3, 3], "intensity": 100}]
})";

class CliAovTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_.write("s.json", kScene); }

  fs::path path(const std::string& name) const { return dir_.file(name); }

  // Exit code and stderr of `candela <args>` run in the test directory.
  int run(const std::string& args, std::string* err = nullptr) const {
    const std::string command = "cd '" + dir_.path() + "' && '" + CANDELA_BINARY + "' " + args +
                                " > /dev/null 2> stderr.txt < /dev/null";
    const int status = std::system(command.c_str());
    if (err) *err = candela::readFileBytes(path("stderr.txt").string());
    fs::remove(path("stderr.txt"));
    return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  candela::test::TempDir dir_;
};

const candela::ExrChannel* channel(const candela::ExrChannels& exr, const std::string& name) {
  for (const candela::ExrChannel& c : exr.channels)
    if (c.name == name) return &c;
  return nullptr;
}

TEST_F(CliAovTest, ExrHoldsThePassesAsLayersBesideTheImage) {
  ASSERT_EQ(run("render s.json -q -o plain.exr"), 0);
  ASSERT_EQ(run("render s.json -q -o out.exr --aov depth,normal,instance,material"), 0);
  const candela::ExrChannels exr = candela::readExrChannels(path("out.exr").string());
  std::vector<std::string> names;
  for (const candela::ExrChannel& c : exr.channels) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"B", "G", "R", "depth.Z", "instance.id",
                                             "material.id", "normal.X", "normal.Y",
                                             "normal.Z"}));
  EXPECT_TRUE(channel(exr, "instance.id")->isUint);
  EXPECT_FALSE(channel(exr, "depth.Z")->isUint);
  const size_t centre = 7 * 15 + 7;
  EXPECT_NEAR(channel(exr, "depth.Z")->pixels[centre], 4.0f, 1e-5f);
  EXPECT_NEAR(channel(exr, "normal.Z")->pixels[centre], 1.0f, 1e-6f);
  EXPECT_EQ(channel(exr, "instance.id")->pixels[centre], 1.0f);
  EXPECT_EQ(channel(exr, "material.id")->pixels[centre], 1.0f);
  EXPECT_TRUE(std::isinf(channel(exr, "depth.Z")->pixels[0]));  // the background
  EXPECT_EQ(channel(exr, "instance.id")->pixels[0], 0.0f);
  // The beauty channels are those of a render without passes.
  const candela::ExrChannels plain = candela::readExrChannels(path("plain.exr").string());
  for (const char* c : {"R", "G", "B"})
    EXPECT_EQ(channel(exr, c)->pixels, channel(plain, c)->pixels) << c;
}

// On the GPU (`--backend cuda`; skipped where there is none) the same layers hold what the CPU's
// do, up to rounding, and the beauty is that of the device's render without passes.
TEST_F(CliAovTest, PassesOnTheGpuAsOnTheCpu) {
  REQUIRE_GPU();
  const std::string passes = " -q --aov depth,normal,instance,material";
  ASSERT_EQ(run("render s.json --backend cpu -o cpu.exr" + passes), 0);
  ASSERT_EQ(run("render s.json --backend cuda -o gpu.exr" + passes), 0);
  ASSERT_EQ(run("render s.json --backend cuda -q -o plain.exr"), 0);
  const candela::ExrChannels cpu = candela::readExrChannels(path("cpu.exr").string());
  const candela::ExrChannels gpu = candela::readExrChannels(path("gpu.exr").string());
  const candela::ExrChannels plain = candela::readExrChannels(path("plain.exr").string());
  ASSERT_EQ(gpu.channels.size(), cpu.channels.size());
  for (const candela::ExrChannel& c : cpu.channels) {
    SCOPED_TRACE(c.name);
    const candela::ExrChannel* g = channel(gpu, c.name);
    ASSERT_NE(g, nullptr);
    if (c.isUint) {  // the same sample's id, but where rounding flips a hit on a silhouette
      ASSERT_EQ(g->pixels.size(), c.pixels.size());
      size_t differing = 0;
      for (size_t i = 0; i < c.pixels.size(); ++i) differing += g->pixels[i] != c.pixels[i];
      EXPECT_LE(differing, c.pixels.size() / 100);
    } else {
      std::vector<float> finite = c.pixels, gpuFinite = g->pixels;  // depth: inf on the background
      for (size_t i = 0; i < finite.size(); ++i)
        if (std::isinf(finite[i]) && finite[i] == gpuFinite[i]) finite[i] = gpuFinite[i] = 0;
      EXPECT_LT(candela::test::relMseAgainst(finite, gpuFinite), 1e-4);
    }
  }
  for (const char* c : {"R", "G", "B"})
    EXPECT_LT(candela::test::relMseAgainst(channel(plain, c)->pixels, channel(gpu, c)->pixels),
              1e-4)
        << c;
}

TEST_F(CliAovTest, PngGetsSiblingPfmFiles) {
  ASSERT_EQ(run("render s.json -q -o img/out.png --aov depth,albedo,instance"), 0);
  EXPECT_TRUE(fs::exists(path("img/out.png")));
  const candela::ImageRGB depth = candela::readImage(path("img/out.depth.pfm").string());
  EXPECT_NEAR(depth.at(7, 7).x, 4.0f, 1e-5f);
  const candela::ImageRGB albedo = candela::readImage(path("img/out.albedo.pfm").string());
  EXPECT_FLOAT_EQ(albedo.at(7, 7).y, 0.5f);
  const candela::ImageRGB ids = candela::readImage(path("img/out.instance.pfm").string());
  EXPECT_EQ(ids.at(7, 7).x, 1.0f);
  EXPECT_EQ(ids.at(0, 0).x, 0.0f);
  // Grey PFM for one channel: a header, then 4 bytes per pixel.
  EXPECT_EQ(fs::file_size(path("img/out.depth.pfm")), std::string("Pf\n15 15\n-1.0\n").size() + 4 * 225);
}

// The alpha pass is the image's own alpha: a PNG's fourth channel (no sibling file), an EXR's A;
// beside a PFM, which has none, a sibling file. The scene has no environment, so its background
// is transparent and its sphere opaque.
TEST_F(CliAovTest, AlphaIsThePngsAlphaChannelAndTheExrsA) {
  ASSERT_EQ(run("render s.json -q -o plain.png"), 0);
  ASSERT_EQ(run("render s.json -q -o out.png --aov alpha,depth"), 0);
  EXPECT_TRUE(fs::exists(path("out.depth.pfm")));
  EXPECT_FALSE(fs::exists(path("out.alpha.pfm")));
  const candela::ImageRgba png = candela::readImageRgba(path("out.png").string());
  ASSERT_EQ(png.channels, 4u);
  const size_t centre = 7 * 15 + 7;
  EXPECT_EQ(png.pixels8[4 * centre + 3], 255);
  EXPECT_EQ(png.pixels8[3], 0);
  // Where alpha is 1 the colour is the plain render's.
  const candela::ImageRgba plain = candela::readImageRgba(path("plain.png").string());
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(png.pixels8[4 * centre + c], plain.pixels8[4 * centre + c]) << c;

  ASSERT_EQ(run("render s.json -q -o out.exr --aov alpha"), 0);
  const candela::ExrChannels exr = candela::readExrChannels(path("out.exr").string());
  ASSERT_NE(channel(exr, "A"), nullptr);
  EXPECT_EQ(channel(exr, "alpha.A"), nullptr);
  EXPECT_EQ(channel(exr, "A")->pixels[centre], 1.0f);
  EXPECT_EQ(channel(exr, "A")->pixels[0], 0.0f);

  ASSERT_EQ(run("render s.json -q -o out.pfm --aov alpha"), 0);
  const candela::ImageRGB alpha = candela::readImage(path("out.alpha.pfm").string());
  EXPECT_EQ(alpha.at(7, 7).x, 1.0f);
  EXPECT_EQ(alpha.at(0, 0).x, 0.0f);
}

// The uv pass: an EXR's layer "uv" of channels U and V, a PNG's sibling .uv.pfm (U, V and a
// third channel of 0). The sphere's equator, seen at the centre pixel, has v = 0.5.
TEST_F(CliAovTest, UvIsALayerOfUAndVOrASiblingFile) {
  ASSERT_EQ(run("render s.json -q -o out.exr --aov uv"), 0);
  const candela::ExrChannels exr = candela::readExrChannels(path("out.exr").string());
  ASSERT_NE(channel(exr, "uv.U"), nullptr);
  ASSERT_NE(channel(exr, "uv.V"), nullptr);
  const size_t centre = 7 * 15 + 7;
  EXPECT_NEAR(channel(exr, "uv.V")->pixels[centre], 0.5f, 1e-4f);
  EXPECT_EQ(channel(exr, "uv.V")->pixels[0], 0.0f);

  ASSERT_EQ(run("render s.json -q -o out.png --aov uv"), 0);
  const candela::ImageRGB uv = candela::readImage(path("out.uv.pfm").string());
  EXPECT_EQ(uv.at(7, 7).x, channel(exr, "uv.U")->pixels[centre]);
  EXPECT_EQ(uv.at(7, 7).y, channel(exr, "uv.V")->pixels[centre]);
  EXPECT_EQ(uv.at(7, 7).z, 0.0f);
}

// The object coordinates pass: an EXR's layer "object_coordinates" of X, Y and Z. The sphere's
// point facing the camera, (0, 0, 1) on its unit sphere, is (0.5, 0.5, 1) over its box.
TEST_F(CliAovTest, ObjectCoordinatesAreALayerOfXYAndZ) {
  ASSERT_EQ(run("render s.json -q -o out.exr --aov object_coordinates"), 0);
  const candela::ExrChannels exr = candela::readExrChannels(path("out.exr").string());
  const size_t centre = 7 * 15 + 7;
  const char* names[] = {"object_coordinates.X", "object_coordinates.Y", "object_coordinates.Z"};
  const float expected[] = {0.5f, 0.5f, 1.0f};
  for (int k = 0; k < 3; ++k) {
    ASSERT_NE(channel(exr, names[k]), nullptr) << names[k];
    EXPECT_NEAR(channel(exr, names[k])->pixels[centre], expected[k], 1e-4f) << names[k];
    EXPECT_EQ(channel(exr, names[k])->pixels[0], 0.0f) << names[k];
  }
}

std::string fileText(const fs::path& file) { return candela::readFileBytes(file.string()); }

// --crop renders that part of the image, each pixel and pass as the whole image's render has
// it, and the camera file says which part; frames of a sequence likewise.
TEST_F(CliAovTest, CropWritesThatPartOfTheImageItsPassesAndCamera) {
  ASSERT_EQ(run("render s.json -q -o whole.exr --aov depth,instance --seed 3"), 0);
  ASSERT_EQ(run("render s.json -q -o crop.exr --aov depth,instance,camera --seed 3 --crop 4,6,9,5"),
            0);
  const candela::ExrChannels whole = candela::readExrChannels(path("whole.exr").string());
  const candela::ExrChannels crop = candela::readExrChannels(path("crop.exr").string());
  ASSERT_EQ(crop.width, 9u);
  ASSERT_EQ(crop.height, 5u);
  for (const char* name : {"R", "G", "B", "depth.Z", "instance.id"})
    for (uint32_t y = 0; y < 5; ++y)
      for (uint32_t x = 0; x < 9; ++x)
        ASSERT_EQ(channel(crop, name)->pixels[y * 9 + x],
                  channel(whole, name)->pixels[(y + 6) * 15 + x + 4])
            << name << " " << x << "," << y;
  const nlohmann::json camera = nlohmann::json::parse(fileText(path("crop.camera.json")));
  EXPECT_EQ(camera["width"], 15);
  EXPECT_EQ(camera["crop"], nlohmann::json::array({4, 6, 9, 5}));

  std::string err;
  EXPECT_EQ(run("render s.json -q -o bad.png --crop 10,0,6,15", &err), 2);
  EXPECT_NE(err.find("--crop: s.json: the crop [10, 0, 6, 15] reaches past the 15 x 15 image"),
            std::string::npos)
      << err;
  EXPECT_EQ(run("render s.json -q -o bad.png --crop 1,2,3", &err), 2);
  EXPECT_NE(err.find("--crop: expected X,Y,WIDTH,HEIGHT"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(path("bad.png")));

  // Every frame of a sequence is cropped.
  ASSERT_EQ(run("render s.json s.json -q -o frames --format pfm --crop 0,0,4,3"), 0);
  for (const char* frame : {"frames/frame_0000.pfm", "frames/frame_0001.pfm"}) {
    const candela::ImageRGB image = candela::readImage(path(frame).string());
    EXPECT_EQ(image.width, 4u) << frame;
    EXPECT_EQ(image.height, 3u) << frame;
  }
}

// The instance pass comes with the names of its numbers (as scene.instances in Python): by JSON
// id, else by place in the file; beside an .exr too, per frame of a sequence, and only with it.
TEST_F(CliAovTest, InstanceNamesAreWrittenBesideTheInstancePass) {
  dir_.write("named.json", R"({
    "camera": {"width": 8, "height": 8, "fov": 30, "spp": 1, "position": [0, 0, 5]},
    "spheres": [{"position": [-1, 0, 0], "radius": 0.5}, {"id": "ball", "position": [1, 0, 0], "radius": 0.5}],
    "lights": [{"id": "lamp", "position": [0, 3, 3], "intensity": 100}]})");
  const std::string expected =
      "{\n  \"1\": \"spheres[0]\",\n  \"2\": \"ball\",\n  \"3\": \"lamp\"\n}\n";
  ASSERT_EQ(run("render named.json -q -o a.png --aov instance"), 0);
  EXPECT_EQ(fileText(path("a.instances.json")), expected);
  ASSERT_EQ(run("render named.json -q -o b.exr --aov instance,depth"), 0);
  EXPECT_EQ(fileText(path("b.instances.json")), expected);
  ASSERT_EQ(run("render named.json named.json -q -o f/ --aov instance"), 0);
  EXPECT_EQ(fileText(path("f/frame_0001.instances.json")), expected);
  ASSERT_EQ(run("render named.json -q -o c.png --aov depth,material"), 0);
  EXPECT_FALSE(fs::exists(path("c.instances.json")));
  // A frame whose table is missing or cut short is rendered again; a whole one is kept
  // (regression: a table never counted as whole, so every frame was rendered again).
  const fs::path kept = path("f/frame_0001.png");
  const auto old = fs::last_write_time(kept) - std::chrono::hours(1);
  fs::last_write_time(kept, old);
  fs::remove(path("f/frame_0000.instances.json"));
  ASSERT_EQ(run("render named.json named.json -q -o f/ --aov instance"), 0);
  EXPECT_EQ(fileText(path("f/frame_0000.instances.json")), expected);
  EXPECT_EQ(fs::last_write_time(kept), old);
  dir_.write("f/frame_0001.instances.json", expected.substr(0, expected.size() / 2));
  ASSERT_EQ(run("render named.json named.json -q -o f/ --aov instance"), 0);
  EXPECT_EQ(fileText(path("f/frame_0001.instances.json")), expected);
  EXPECT_NE(fs::last_write_time(kept), old);
}

TEST_F(CliAovTest, UnknownPassIsAUsageErrorListingTheKnownOnes) {
  std::string err;
  EXPECT_EQ(run("render s.json -o out.png --aov depth,nromal", &err), 2);
  EXPECT_EQ(err,
            "candela: error: --aov: unknown render pass \"nromal\"; the passes are: depth, "
            "distance, normal, normal_camera, albedo, position, instance, material, flow, "
            "backward_flow, direct, emission, alpha, uv, object_coordinates; and beside the "
            "image camera (the camera's "
            "matrices) and poses (each instance's pose)\n");
  EXPECT_FALSE(fs::exists(path("out.png")));
}

// `--aov camera` writes the camera's K and [R|t] beside the image as a camera object of the scene
// format, which, put in place of the camera it came from, renders the same image to the bit.
TEST_F(CliAovTest, CameraFileIsACameraThatRendersTheSameImage) {
  dir_.write("look.json", R"({
    "camera": {"width": 12, "height": 9, "fov": 50, "position": [1, 2, 6], "look_at": [0, 0, 0]},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]})");
  ASSERT_EQ(run("render look.json -q --spp 2 -o a.pfm --aov camera"), 0);
  EXPECT_FALSE(fs::exists(path("a.camera.pfm")));
  const std::string camera = fileText(path("a.camera.json"));
  EXPECT_EQ(camera.rfind("{\n  \"width\": 12,\n  \"height\": 9,\n  \"intrinsics\": [", 0), 0u)
      << camera;
  EXPECT_NE(camera.find("\"extrinsics\": ["), std::string::npos) << camera;
  EXPECT_NE(camera.find("[0.0, 0.0, 0.0, 1.0]"), std::string::npos) << camera;
  EXPECT_EQ(camera.find("aperture_radius"), std::string::npos) << "a pinhole has no lens";
  dir_.write("given.json", R"({"camera": )" + camera + R"(,
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]})");
  ASSERT_EQ(run("render given.json -q --spp 2 -o b.pfm"), 0);
  // The camera's centre comes back as -R^T t, within rounding of where it was.
  const double difference = candela::test::relMseAgainst(
      candela::readImage(path("a.pfm").string()).pixels,
      candela::readImage(path("b.pfm").string()).pixels);
  EXPECT_LT(difference, 1e-9);

  // A lens distortion is written as OpenCV's coefficients, and renders the same image again.
  dir_.write("bent.json", R"({
    "camera": {"width": 12, "height": 9, "fov": 50, "position": [1, 2, 6], "look_at": [0, 0, 0],
               "distortion": [-0.2, 0.05, 0.001, 0, 0, 0.01, 0, 0]},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]})");
  ASSERT_EQ(run("render bent.json -q --spp 2 -o c.pfm --aov camera"), 0);
  const std::string bent = fileText(path("c.camera.json"));
  EXPECT_NE(bent.find("\"distortion\": [-0.2, 0.05, 0.001, 0.0, 0.0, 0.01, 0.0, 0.0]"),
            std::string::npos)
      << bent;
  dir_.write("given.json", R"({"camera": )" + bent + R"(,
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]})");
  ASSERT_EQ(run("render given.json -q --spp 2 -o d.pfm"), 0);
  const std::vector<float> bentImage = candela::readImage(path("c.pfm").string()).pixels;
  EXPECT_LT(
      candela::test::relMseAgainst(bentImage, candela::readImage(path("d.pfm").string()).pixels),
      1e-9);
  EXPECT_GT(
      candela::test::relMseAgainst(bentImage, candela::readImage(path("a.pfm").string()).pixels),
      1e-6);  // the lens shows
  // An equirectangular camera names its projection in place of K, and comes back the same.
  dir_.write("pano.json", R"({
    "camera": {"width": 16, "height": 8, "projection": "equirectangular", "position": [1, 2, 6],
               "look_at": [0, 0, 0]},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]})");
  ASSERT_EQ(run("render pano.json -q --spp 2 -o e.pfm --aov camera"), 0);
  const std::string pano = fileText(path("e.camera.json"));
  EXPECT_NE(pano.find("\"projection\": \"equirectangular\""), std::string::npos) << pano;
  EXPECT_EQ(pano.find("intrinsics"), std::string::npos) << pano;
  dir_.write("given.json", R"({"camera": )" + pano + R"(,
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]})");
  ASSERT_EQ(run("render given.json -q --spp 2 -o f.pfm"), 0);
  EXPECT_LT(candela::test::relMseAgainst(candela::readImage(path("e.pfm").string()).pixels,
                                         candela::readImage(path("f.pfm").string()).pixels),
            1e-9);

  // A thin lens keeps its lens; an .exr gets the file too, and so does each frame of a sequence,
  // with that frame's camera.
  dir_.write("lens.json", R"({
    "camera": {"width": 8, "height": 8, "fov": 40, "position": [0, 0, 5], "aperture_radius": 0.2,
               "focus_distance": 4.5},
    "spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1}],
    "animation": {"frames": 2, "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [0, 0, 5]], [1, [1, 0, 5]]]}]}})");
  ASSERT_EQ(run("render lens.json -q --spp 1 -o f/ --format exr --aov camera,depth"), 0);
  const std::string first = fileText(path("f/frame_0000.camera.json"));
  EXPECT_NE(first.find("\"aperture_radius\": 0.2,\n  \"focus_distance\": 4.5\n}\n"),
            std::string::npos) << first;
  EXPECT_NE(first.find("[1.0, 0.0, 0.0, 0.0]"), std::string::npos) << first;
  // Frame 1's camera is 1 to the right: t = -R C has -1 in x.
  const std::string second = fileText(path("f/frame_0001.camera.json"));
  EXPECT_NE(second.find("[1.0, 0.0, 0.0, -1.0]"), std::string::npos) << second;
}

// `--aov poses` writes each instance's placement, numbered as the instance pass: the model (the
// unit sphere; the OBJ's own coordinates) to the world, and to the camera as the camera file's
// extrinsics times that; and the box the model spans.
TEST_F(CliAovTest, PosesFileHoldsEachInstancesPlacementInTheWorldAndTheCamera) {
  dir_.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  dir_.write("posed.json", R"({
    "camera": {"width": 8, "height": 6, "fov": 50, "position": [1, 2, 6], "look_at": [0, 0, 0]},
    "spheres": [{"id": "ball", "position": [0.5, -1, 2], "radius": 2}],
    "objects": [{"file": "tri.obj", "position": [1, 2, 3], "rotation": [0, 90, 0], "scale": [2, 3, 4]}],
    "lights": [{"type": "sphere", "position": [0, 5, 0], "radius": 0.5, "intensity": 10}]})");
  ASSERT_EQ(run("render posed.json -q --spp 1 -o a.png --aov poses,camera"), 0);
  const nlohmann::json poses = nlohmann::json::parse(fileText(path("a.poses.json")));
  const nlohmann::json camera = nlohmann::json::parse(fileText(path("a.camera.json")));
  ASSERT_EQ(poses.size(), 3u);
  EXPECT_EQ(poses["1"]["name"], "ball");
  EXPECT_EQ(poses["2"]["name"], "objects[0]");
  EXPECT_EQ(poses["3"]["name"], "lights[0]");
  // R_y(90) takes x to -z and z to x, scaled first by (2, 3, 4).
  const double world[3][3][4] = {{{2, 0, 0, 0.5}, {0, 2, 0, -1}, {0, 0, 2, 2}},
                                 {{0, 0, 4, 1}, {0, 3, 0, 2}, {-2, 0, 0, 3}},
                                 {{0.5, 0, 0, 0}, {0, 0.5, 0, 5}, {0, 0, 0.5, 0}}};
  for (int n = 0; n < 3; ++n) {
    const nlohmann::json& pose = poses[std::to_string(n + 1)];
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double expected = i < 3 ? world[n][i][j] : (j == 3 ? 1 : 0);
        EXPECT_NEAR(pose["object_to_world"][i][j].get<double>(), expected, 1e-6)
            << n + 1 << " " << i << " " << j;
        double seen = 0;
        for (int k = 0; k < 4; ++k)
          seen += camera["extrinsics"][i][k].get<double>() *
                  pose["object_to_world"][k][j].get<double>();
        EXPECT_NEAR(pose["object_to_camera"][i][j].get<double>(), seen, 1e-5)
            << n + 1 << " " << i << " " << j;
      }
  }
  // Each model's box: the unit sphere's for the sphere and the sphere light, the triangle's
  // as its file has it (before the placement) for the object.
  const double boxes[3][2][3] = {
      {{-1, -1, -1}, {1, 1, 1}}, {{0, 0, 0}, {1, 1, 0}}, {{-1, -1, -1}, {1, 1, 1}}};
  for (int n = 0; n < 3; ++n)
    for (int corner = 0; corner < 2; ++corner)
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(poses[std::to_string(n + 1)]["model_box"][corner][k].get<double>(),
                  boxes[n][corner][k])
            << n + 1 << " " << corner << " " << k;
  // Per frame of a sequence too.
  ASSERT_EQ(run("render posed.json posed.json -q --spp 1 -o f/ --aov poses"), 0);
  EXPECT_EQ(fileText(path("f/frame_0001.poses.json")), fileText(path("a.poses.json")));
}

// A spot or directional light's pose is a rotation whose third column is where it shines.
TEST_F(CliAovTest, PosesOfAimedLightsTurnTheirModelsZToWhereTheyShine) {
  dir_.write("aimed.json", R"({
    "camera": {"width": 8, "height": 6, "fov": 50, "position": [0, 0, 6]},
    "lights": [{"type": "spot", "position": [1, 2, 3], "look_at": [1, -1, 7], "intensity": 10},
               {"type": "directional", "direction": [0, 0, -2], "intensity": 1}]})");
  ASSERT_EQ(run("render aimed.json -q --spp 1 -o a.png --aov poses"), 0);
  const nlohmann::json poses = nlohmann::json::parse(fileText(path("a.poses.json")));
  EXPECT_FALSE(poses["1"].contains("model_box"));  // lights without an extent have no box
  EXPECT_FALSE(poses["2"].contains("model_box"));
  const double axes[2][3] = {{0, -0.6, 0.8}, {0, 0, -1}};
  const double places[2][3] = {{1, 2, 3}, {0, 0, 0}};
  for (int n = 0; n < 2; ++n) {
    const nlohmann::json& m = poses[std::to_string(n + 1)]["object_to_world"];
    double a[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) a[i][j] = m[i][j].get<double>();
      EXPECT_NEAR(a[i][2], axes[n][i], 1e-6) << n;
      EXPECT_EQ(m[i][3].get<double>(), places[n][i]) << n;
    }
    const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                       a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                       a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    EXPECT_NEAR(det, 1.0, 1e-6) << n;  // a rotation, right-handed
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        double dotjk = 0;
        for (int i = 0; i < 3; ++i) dotjk += a[i][j] * a[i][k];
        EXPECT_NEAR(dotjk, j == k ? 1.0 : 0.0, 1e-6) << n;
      }
  }
}

TEST_F(CliAovTest, SiblingFilesNeverOverwriteAnInput) {
  std::ofstream(path("out.depth.pfm")) << kScene;  // a scene file named like a pass file
  std::string err;
  EXPECT_EQ(run("render out.depth.pfm -o out.png --aov depth", &err), 2);
  EXPECT_NE(err.find("out.depth.pfm: --aov would overwrite the scene file"), std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(CliAovTest, SequencesWritePassesPerFrame) {
  ASSERT_EQ(run("render s.json s.json -q -o f/ --aov depth"), 0);
  for (const char* name : {"f/frame_0000.png", "f/frame_0000.depth.pfm", "f/frame_0001.png",
                           "f/frame_0001.depth.pfm"})
    EXPECT_TRUE(fs::exists(path(name))) << name;
  // A frame whose pass file is missing is rendered again.
  fs::remove(path("f/frame_0001.depth.pfm"));
  ASSERT_EQ(run("render s.json s.json -q -o f/ --aov depth"), 0);
  EXPECT_TRUE(fs::exists(path("f/frame_0001.depth.pfm")));
  ASSERT_EQ(run("render s.json -q -o g/ --format exr --aov depth"), 0);
  const candela::ExrChannels exr = candela::readExrChannels(path("g/frame_0000.exr").string());
  EXPECT_NE(channel(exr, "depth.Z"), nullptr);
}

// The flow pass of an animation: the sphere moves right by 0.25 a frame, so its centre pixel's
// flow is f 0.25 / 4 (its nearest point is 4 from the camera) in every frame but the last, after
// which nothing moves; as a PFM it is three channels, the third 0, as flow datasets write it.
TEST_F(CliAovTest, AnimationsWriteTheirFlowPerFrame) {
  dir_.write("moving.json", candela::test::kMovingSphereScene);
  ASSERT_EQ(run("render moving.json -q -o f/ --format exr --aov flow"), 0);
  const float f = 7.5f / std::tan(15.0f * 3.14159265f / 180.0f);
  const candela::ExrChannels exr = candela::readExrChannels(path("f/frame_0000.exr").string());
  const candela::ExrChannel* x = channel(exr, "flow.X");
  ASSERT_NE(x, nullptr);
  ASSERT_NE(channel(exr, "flow.Y"), nullptr);
  EXPECT_NEAR(x->pixels[7 * 15 + 7], f * 0.25f / 4.0f, 1e-4f);
  const candela::ExrChannels last = candela::readExrChannels(path("f/frame_0002.exr").string());
  EXPECT_EQ(channel(last, "flow.X")->pixels[7 * 15 + 7], 0.0f);

  ASSERT_EQ(run("render moving.json -q -o g/ --aov flow"), 0);
  // In frame 1 the sphere is 0.25 off the axis: the centre pixel's point lies deeper.
  const candela::ImageRGB pfm = candela::readImage(path("g/frame_0001.flow.pfm").string());
  EXPECT_NEAR(pfm.at(7, 7).x, f * 0.25f / (5.0f - std::sqrt(1.0f - 0.0625f)), 1e-4f);
  EXPECT_EQ(pfm.at(7, 7).z, 0.0f);
}

// The backward flow of each frame of a sequence, and of one frame alone (--frame), is from the
// frame before; frame 0's, which has none, is 0.
TEST_F(CliAovTest, AnimationsWriteTheirBackwardFlowPerFrame) {
  dir_.write("moving.json", candela::test::kMovingSphereScene);
  ASSERT_EQ(run("render moving.json -q -o f/ --format exr --aov flow,backward_flow"), 0);
  const float f = 7.5f / std::tan(15.0f * 3.14159265f / 180.0f);
  const float depth = 5.0f - std::sqrt(1.0f - 0.0625f);  // of frame 1's centre pixel
  const candela::ExrChannels first = candela::readExrChannels(path("f/frame_0000.exr").string());
  EXPECT_EQ(channel(first, "backward_flow.X")->pixels[7 * 15 + 7], 0.0f);
  const candela::ExrChannels second = candela::readExrChannels(path("f/frame_0001.exr").string());
  EXPECT_NEAR(channel(second, "backward_flow.X")->pixels[7 * 15 + 7], -f * 0.25f / depth, 1e-4f);
  EXPECT_NEAR(channel(second, "flow.X")->pixels[7 * 15 + 7], f * 0.25f / depth, 1e-4f);

  ASSERT_EQ(run("render moving.json -q --frame 1 -o one.pfm --aov backward_flow"), 0);
  const candela::ImageRGB pfm = candela::readImage(path("one.backward_flow.pfm").string());
  EXPECT_EQ(pfm.at(7, 7).x, channel(second, "backward_flow.X")->pixels[7 * 15 + 7]);

  std::string err;
  EXPECT_EQ(run("render s.json s.json -q -o seq/ --aov backward_flow", &err), 2);
  EXPECT_NE(err.find("--aov backward_flow: the flow passes are the motion of one animated scene"),
            std::string::npos)
      << err;
}

TEST_F(CliAovTest, FlowOfSeveralSceneFilesIsAUsageError) {
  std::string err;
  EXPECT_EQ(run("render s.json s.json -o f/ --aov flow", &err), 2);
  EXPECT_NE(err.find("--aov flow: the flow passes are the motion of one animated scene"),
            std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(path("f/frame_0000.png")));
}

}  // namespace
