// Render passes by name and as images; see aov_layers.h and docs/aovs.md.
#include "render/aov_layers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace candela {

namespace {

struct AovInfo {
  Aov aov;
  const char* name;
  std::vector<std::string> channels;
  bool integer;  // an id pass: the sample nearest the pixel centre, not a mean
};

const std::vector<AovInfo>& aovTable() {
  static const std::vector<AovInfo> table = {
      {Aov::Depth, "depth", {"Z"}, false},
      {Aov::Distance, "distance", {"Z"}, false},
      {Aov::Normal, "normal", {"X", "Y", "Z"}, false},
      {Aov::NormalCamera, "normal_camera", {"X", "Y", "Z"}, false},
      {Aov::Albedo, "albedo", {"R", "G", "B"}, false},
      {Aov::Position, "position", {"X", "Y", "Z"}, false},
      {Aov::Instance, "instance", {"id"}, true},
      {Aov::Material, "material", {"id"}, true},
      {Aov::Flow, "flow", {"X", "Y"}, false},
      {Aov::BackwardFlow, "backward_flow", {"X", "Y"}, false},
      {Aov::Direct, "direct", {"R", "G", "B"}, false},
      {Aov::Emission, "emission", {"R", "G", "B"}, false},
      {Aov::Alpha, "alpha", {"A"}, false},
      {Aov::Uv, "uv", {"U", "V"}, false},
      {Aov::ObjectCoordinates, "object_coordinates", {"X", "Y", "Z"}, false},
  };
  return table;
}

const AovInfo& infoOf(Aov aov) { return aovTable()[size_t(aov)]; }

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// A flow pass's mean over the samples where it is defined; undefined (no sample's point in front
// of both cameras): NaN, not a made-up motion.
void putFlow(const Vec2& sum, uint32_t samples, float* out) {
  if (samples == 0) {
    out[0] = out[1] = std::nanf("");
    return;
  }
  out[0] = sum.x / float(samples);
  out[1] = sum.y / float(samples);
}

// The value of pass `aov` at one pixel, into `out` (its channel count of floats).
void resolvePixel(Aov aov, const SceneData& scene, const AovPixel& p, float* out) {
  const Camera& cam = scene.camera;
  const float inf = std::numeric_limits<float>::infinity();
  const float invHits = p.hits > 0 ? 1.0f / float(p.hits) : 0.0f;
  const Vec3 position = p.positionSum * invHits;
  Vec3 normal = p.normalSum;
  if (lengthSquared(normal) > 0.0f) normal = normalize(normal);
  const auto put = [out](const Vec3& v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
  };
  switch (aov) {
    case Aov::Depth:
      // A panorama's depth is the distance: its camera space has no one forward axis.
      if (cam.projection == CameraProjection::Equirectangular) {
        out[0] = p.hits > 0 ? p.distanceSum * invHits : inf;
        return;
      }
      out[0] = p.hits > 0 ? dot(position - cam.position, cam.cameraToWorld * Vec3(0, 0, 1)) : inf;
      return;
    case Aov::Distance:
      out[0] = p.hits > 0 ? p.distanceSum * invHits : inf;
      return;
    case Aov::Normal:
      return put(normal);
    case Aov::NormalCamera:
      return put(cam.cameraToWorld.transposed() * normal);
    case Aov::Albedo:
      return put(meanOverSamples(p, p.albedoSum));
    case Aov::Position:
      return put(position);
    case Aov::Instance: {
      const size_t m = size_t(p.nearestMaterial);
      out[0] = p.nearestMaterial < 0 || m >= scene.materialInstances.size()
                   ? 0.0f
                   : float(scene.materialInstances[m]);
      return;
    }
    case Aov::Material:
      out[0] = float(p.nearestMaterial + 1);
      return;
    case Aov::Flow:
      return putFlow(p.flowSum, p.flowSamples, out);
    case Aov::BackwardFlow:
      return putFlow(p.backwardFlowSum, p.backwardFlowSamples, out);
    case Aov::Direct:
      return put(meanOverSamples(p, p.directSum));
    case Aov::Emission:
      return put(meanOverSamples(p, p.emissionSum));
    case Aov::Alpha:
      out[0] = p.samples > 0 ? float(p.covered) / float(p.samples) : 0.0f;
      return;
    case Aov::Uv:
      out[0] = p.uvSum.x * invHits;
      out[1] = p.uvSum.y * invHits;
      return;
    case Aov::ObjectCoordinates:
      return put(p.objectCoordinatesSum * invHits);
  }
}

}  // namespace

const char* aovName(Aov aov) { return infoOf(aov).name; }

std::string knownAovNames() {
  std::string list;
  for (const AovInfo& info : aovTable()) list += (list.empty() ? "" : ", ") + std::string(info.name);
  return list;
}

std::vector<Aov> aovsFromNames(const std::vector<std::string>& names) {
  std::vector<Aov> aovs;
  for (const std::string& raw : names) {
    const std::string name = trimmed(raw);
    const auto it = std::find_if(aovTable().begin(), aovTable().end(),
                                 [&](const AovInfo& info) { return name == info.name; });
    if (it == aovTable().end())
      throw std::invalid_argument("unknown render pass \"" + name +
                                  "\"; the passes are: " + knownAovNames());
    if (!hasAov(aovs, it->aov)) aovs.push_back(it->aov);
  }
  return aovs;
}

std::vector<std::string> splitPassList(const std::string& list) {
  std::vector<std::string> names;
  size_t start = 0;
  for (;;) {
    const size_t comma = list.find(',', start);
    names.push_back(trimmed(list.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

std::vector<Aov> parseAovList(const std::string& list) {
  return aovsFromNames(splitPassList(list));
}

bool hasAov(const std::vector<Aov>& aovs, Aov aov) {
  return std::find(aovs.begin(), aovs.end(), aov) != aovs.end();
}

std::vector<ImageLayer> makeAovLayers(const SceneData& scene, const std::vector<Aov>& aovs,
                                      const std::vector<AovPixel>& pixels) {
  const uint32_t width = scene.camera.width, height = scene.camera.height;
  if (pixels.size() != size_t(width) * height)
    throw std::invalid_argument("the render holds no passes for this image size");
  std::vector<ImageLayer> layers;
  for (Aov aov : aovs) {
    const AovInfo& info = infoOf(aov);
    ImageLayer layer(info.name, info.channels, info.integer, width, height);
    layer.ofImage = aov == Aov::Alpha;
    const size_t n = info.channels.size();
    for (size_t i = 0; i < pixels.size(); ++i)
      resolvePixel(aov, scene, pixels[i], layer.pixels.data() + n * i);
    layers.push_back(std::move(layer));
  }
  return layers;
}

}  // namespace candela
