#include "scene/mesh_repeats.h"

#include <cstring>
#include <unordered_map>

#include "scene/content_hash.h"

namespace candela {

namespace {

bool samePositions(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// Whether objects a and b of `s` have the same triangles up to the shift of their vertex indices
// (materials aside: they need not agree).
bool sameTriangles(const SceneData& s, const MeshInstance& a, const MeshInstance& b) {
  if (a.triangleCount != b.triangleCount || a.vertexCount != b.vertexCount) return false;
  for (uint32_t i = 0; i < a.triangleCount; ++i) {
    const Triangle& ta = s.triangles[a.firstTriangle + i];
    const Triangle& tb = s.triangles[b.firstTriangle + i];
    for (int k = 0; k < 3; ++k)
      if (ta.v[k] - a.firstVertex != tb.v[k] - b.firstVertex) return false;
  }
  return true;
}

}  // namespace

void findRepeatedMeshes(SceneData& s, const std::vector<FlattenedObject>& objects) {
  std::vector<MeshInstance>& placed = s.meshInstances.objects;
  // Candidate groups, each named by its first object; only groups of two or more stay. An object
  // is compared only with the groups that share its key (what a repeat must share: the hash of
  // its mesh's positions, taken once per mesh, and its counts), not with every group.
  std::vector<uint32_t> firsts;
  std::vector<int32_t> group(objects.size(), -1);
  std::unordered_map<const MeshDesc*, uint64_t> positionHashes;
  std::unordered_map<uint64_t, std::vector<uint32_t>> groupsByKey;
  for (uint32_t i = 0; i < objects.size(); ++i) {
    if (placed[i].triangleCount == 0) continue;
    const auto [positionHash, fresh] = positionHashes.try_emplace(objects[i].mesh, 0);
    if (fresh) positionHash->second = hashVector(objects[i].mesh->positions);
    const uint64_t counts = uint64_t(placed[i].triangleCount) << 32 | placed[i].vertexCount;
    std::vector<uint32_t>& candidates =
        groupsByKey[hashBytes(&counts, sizeof counts, positionHash->second)];
    for (uint32_t g : candidates) {
      const uint32_t f = firsts[g];
      // Cheapest first; the triangles differ between repeats of one mesh that mirror it or not.
      if ((objects[f].mesh == objects[i].mesh ||  // one file's mesh, shared
           samePositions(objects[f].mesh->positions, objects[i].mesh->positions)) &&
          (objects[f].layout == objects[i].layout ||
           objects[f].layout->splitSources == objects[i].layout->splitSources) &&
          sameTriangles(s, placed[f], placed[i])) {
        group[i] = int32_t(g);
        break;
      }
    }
    if (group[i] < 0) {
      group[i] = int32_t(firsts.size());
      candidates.push_back(uint32_t(firsts.size()));
      firsts.push_back(i);
    }
  }
  std::vector<uint32_t> sizes(firsts.size(), 0);
  for (int32_t g : group)
    if (g >= 0) ++sizes[uint32_t(g)];
  std::vector<int32_t> prototypeOf(firsts.size(), -1);
  for (uint32_t g = 0; g < firsts.size(); ++g) {
    if (sizes[g] < 2) continue;
    const FlattenedObject& first = objects[firsts[g]];
    MeshPrototype prototype;
    prototype.firstInstance = firsts[g];
    prototype.instanceCount = sizes[g];
    prototype.positions.reserve(first.layout->vertexCount(*first.mesh));
    prototype.positions.assign(first.mesh->positions.begin(), first.mesh->positions.end());
    for (uint32_t source : first.layout->splitSources)
      prototype.positions.push_back(first.mesh->positions[source]);
    prototypeOf[g] = int32_t(s.meshInstances.prototypes.size());
    s.meshInstances.prototypes.push_back(std::move(prototype));
  }
  for (uint32_t i = 0; i < objects.size(); ++i)
    if (group[i] >= 0) placed[i].prototype = prototypeOf[uint32_t(group[i])];
}

}  // namespace candela
