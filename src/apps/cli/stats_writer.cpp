// The --stats JSON of `candela render` (see stats_writer.h).
#include "apps/cli/stats_writer.h"

#include <sys/resource.h>

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

namespace candela::cli {

namespace {

// JSON has no inf or nan; a rate over a zero time is written as 0.
double finiteOrZero(double v) { return std::isfinite(v) ? v : 0.0; }

// A light path depth as the scene file spells it: "auto" (0), "all" or the interaction.
nlohmann::ordered_json depthName(uint32_t depth) {
  if (depth == 0) return "auto";
  if (depth == kEveryInteraction) return "all";
  return depth;
}

template <class T, class Allocator>
uint64_t bytesOf(const std::vector<T, Allocator>& v) {
  return uint64_t(v.size()) * sizeof(T);
}

double rate(double count, double seconds) { return seconds > 0 ? count / seconds : 0; }

}  // namespace

long long peakRssBytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return (long long)usage.ru_maxrss * 1024;  // Linux reports kilobytes
}

std::string renderStatsJson(const RenderStats& info, const SceneData& scene,
                            const RenderResult& result) {
  const RenderSettings& s = scene.settings;
  const uint64_t triangles = scene.triangles.size();
  const uint64_t nodes = bytesOf(scene.nodes), prims = bytesOf(scene.primIndices),
                 positions = bytesOf(scene.positions), normals = bytesOf(scene.normals),
                 tris = bytesOf(scene.triangles);
  const uint64_t engine = info.acceleration.bytes;
  const uint64_t total = nodes + prims + positions + normals + tris + engine;
  const double buildSeconds = std::string(info.acceleration.engine) == "bvh"
                                  ? scene.bvh.buildSeconds
                                  : info.acceleration.buildSeconds;
  const uint64_t samples = uint64_t(result.image.width) * result.image.height * s.spp;

  nlohmann::ordered_json o;
  o["scene"] = info.scene;
  o["backend"] = info.backend;
  o["threads"] = info.threads;
  o["width"] = result.image.width;
  o["height"] = result.image.height;
  o["spp"] = s.spp;
  o["max_depth"] = s.maxDepth;
  o["integrator"] = s.integrator == IntegratorType::Direct ? "direct" : "path";
  o["antialiasing"] = s.antialiasing;
  o["filter"] = {{"type", filterName(s.filter.type)}};
  if (const char* width = filterWidthName(s.filter.type)) o["filter"][width] = s.filter.width;
  o["use_bvh"] = info.useBvh;
  o["load_seconds"] = finiteOrZero(info.loadSeconds);
  o["flatten_seconds"] = finiteOrZero(info.flattenSeconds);
  o["engine"] = info.acceleration.engine;
  o["cpu_isa"] = info.acceleration.isa;
  o["bvh_build_seconds"] = finiteOrZero(buildSeconds);
  o["bvh_mtris_per_second"] = finiteOrZero(rate(double(triangles), buildSeconds) / 1e6);
  o["triangles"] = triangles;
  o["spheres"] = uint64_t(scene.spheres.size());
  o["bvh_nodes"] = scene.bvh.nodeCount;
  o["bvh_leaves"] = scene.bvh.leafCount;
  o["bvh_max_depth"] = scene.bvh.maxDepth;
  o["memory_bytes"] = {{"nodes", nodes},     {"prim_indices", prims}, {"positions", positions},
                       {"normals", normals}, {"triangles", tris},     {"engine", engine},
                       {"total", total}};
  o["bytes_per_triangle"] = finiteOrZero(triangles ? double(total) / double(triangles) : 0);
  const PilotChoice& pilot = info.pilot;
  // The pilot's seconds and rays are those of all it rendered, for both choices.
  o["light_paths"] = {{"setting", lightPathsName(s.lightPaths)},
                      {"on", pilot.lightPaths},
                      {"piloted", pilot.piloted},
                      {"pilot_seconds", finiteOrZero(pilot.seconds)},
                      {"pilot_rays", pilot.rays.total()},
                      {"pilot_with", finiteOrZero(pilot.withLightPaths)},
                      {"pilot_without", finiteOrZero(pilot.withoutLightPaths)},
                      {"depth_setting", depthName(s.lightPathDepth)},
                      {"depth", depthName(pilot.lightPathDepth)},
                      {"depth_piloted", pilot.depthPiloted},
                      {"pilot_every_interaction", finiteOrZero(pilot.everyInteraction)},
                      {"pilot_first_interactions", finiteOrZero(pilot.firstInteractions)}};
  o["first_hit_light_samples"] = {
      {"setting", s.firstHitLightSamples == 0 ? nlohmann::ordered_json("auto")
                                              : nlohmann::ordered_json(s.firstHitLightSamples)},
      {"count", pilot.firstHitLightSamples},
      {"piloted", pilot.lightSamplesPiloted},
      {"pilot_one", finiteOrZero(pilot.oneLightSample)},
      {"pilot_two", finiteOrZero(pilot.twoLightSamples)}};
  o["render_seconds"] = finiteOrZero(result.seconds);
  o["samples"] = samples;
  o["samples_per_second"] = finiteOrZero(rate(double(samples), result.seconds));
  o["rays"] = {{"camera", result.rays.camera},
               {"bounce", result.rays.bounce},
               {"shadow", result.rays.shadow},
               {"total", result.rays.total()}};
  o["rays_per_second"] = finiteOrZero(rate(double(result.rays.total()), result.seconds));
  o["denoise_seconds"] = finiteOrZero(info.denoiseSeconds);
  o["peak_rss_bytes"] = peakRssBytes();
  // A scene path need not be UTF-8: its bad bytes become U+FFFD rather than an exception.
  return o.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace candela::cli
