// The --stats JSON of `candela render` (see stats_writer.h).
#include "apps/cli/stats_writer.h"

#include <sys/resource.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace candela::cli {

namespace {

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += char(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += char(c);
    }
  }
  return out + "\"";
}

// JSON has no inf or nan; a rate over a zero time is written as 0.
std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "0";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string jsonCount(uint64_t v) { return std::to_string(v); }

template <class T>
uint64_t bytesOf(const std::vector<T>& v) {
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
  const double samples = double(result.image.width) * double(result.image.height) * double(s.spp);

  std::ostringstream o;
  o << "{\n";
  o << "  \"scene\": " << jsonString(info.scene) << ",\n";
  o << "  \"backend\": " << jsonString(info.backend) << ",\n";
  o << "  \"threads\": " << info.threads << ",\n";
  o << "  \"width\": " << result.image.width << ",\n";
  o << "  \"height\": " << result.image.height << ",\n";
  o << "  \"spp\": " << s.spp << ",\n";
  o << "  \"max_depth\": " << s.maxDepth << ",\n";
  o << "  \"integrator\": " << (s.integrator == IntegratorType::Direct ? "\"direct\"" : "\"path\"")
    << ",\n";
  o << "  \"antialiasing\": " << (s.antialiasing ? "true" : "false") << ",\n";
  o << "  \"use_bvh\": " << (info.useBvh ? "true" : "false") << ",\n";
  o << "  \"load_seconds\": " << jsonNumber(info.loadSeconds) << ",\n";
  o << "  \"flatten_seconds\": " << jsonNumber(info.flattenSeconds) << ",\n";
  o << "  \"engine\": " << jsonString(info.acceleration.engine) << ",\n";
  o << "  \"bvh_build_seconds\": " << jsonNumber(buildSeconds) << ",\n";
  o << "  \"bvh_mtris_per_second\": " << jsonNumber(rate(double(triangles), buildSeconds) / 1e6)
    << ",\n";
  o << "  \"triangles\": " << jsonCount(triangles) << ",\n";
  o << "  \"spheres\": " << jsonCount(scene.spheres.size()) << ",\n";
  o << "  \"bvh_nodes\": " << scene.bvh.nodeCount << ",\n";
  o << "  \"bvh_leaves\": " << scene.bvh.leafCount << ",\n";
  o << "  \"bvh_max_depth\": " << scene.bvh.maxDepth << ",\n";
  o << "  \"memory_bytes\": {\"nodes\": " << nodes << ", \"prim_indices\": " << prims
    << ", \"positions\": " << positions << ", \"normals\": " << normals
    << ", \"triangles\": " << tris << ", \"engine\": " << engine << ", \"total\": " << total
    << "},\n";
  o << "  \"bytes_per_triangle\": " << jsonNumber(triangles ? double(total) / double(triangles) : 0)
    << ",\n";
  o << "  \"render_seconds\": " << jsonNumber(result.seconds) << ",\n";
  o << "  \"samples\": " << jsonNumber(samples) << ",\n";
  o << "  \"samples_per_second\": " << jsonNumber(rate(samples, result.seconds)) << ",\n";
  o << "  \"rays\": {\"camera\": " << jsonCount(result.rays.camera)
    << ", \"bounce\": " << jsonCount(result.rays.bounce)
    << ", \"shadow\": " << jsonCount(result.rays.shadow)
    << ", \"total\": " << jsonCount(result.rays.total()) << "},\n";
  o << "  \"rays_per_second\": " << jsonNumber(rate(double(result.rays.total()), result.seconds))
    << ",\n";
  o << "  \"peak_rss_bytes\": " << peakRssBytes() << "\n";
  o << "}\n";
  return o.str();
}

}  // namespace candela::cli
