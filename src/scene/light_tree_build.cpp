// The light tree's build; see light_tree_build.h.
#include "scene/light_tree_build.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/constants.h"

namespace candela {
namespace {

struct Direction {
  double x = 0, y = 0, z = 1;
};

double dot(const Direction& a, const Direction& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Direction cross(const Direction& a, const Direction& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

double safeAcos(double c) { return std::acos(std::clamp(c, -1.0, 1.0)); }

double length(const Direction& d) { return std::sqrt(dot(d, d)); }

// The angle between unit vectors a and b, accurate near 0 and pi (pbrt-v4's AngleBetween).
double angleBetween(const Direction& a, const Direction& b) {
  const auto halfChordAngle = [](const Direction& d) {
    return 2.0 * std::asin(std::min(1.0, 0.5 * length(d)));
  };
  if (dot(a, b) < 0.0) return kPiDouble - halfChordAngle({a.x + b.x, a.y + b.y, a.z + b.z});
  return halfChordAngle({a.x - b.x, a.y - b.y, a.z - b.z});
}

// A group of lights as the tree's importance sees it: a box, a cone of emitting normals and
// their power.
struct Cluster {
  bool empty = true;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  Direction axis;
  double cosThetaO = 1, sinThetaO = 0, thetaO = 0, power = 0;

  double diagonal(int d) const { return hi[d] - lo[d]; }
  double surfaceArea() const {
    const double x = diagonal(0), y = diagonal(1), z = diagonal(2);
    return 2.0 * (x * y + y * z + z * x);
  }
};

Cluster clusterOf(const LightBounds& l) {
  Cluster c;
  c.empty = false;
  const float lo[3] = {l.lo.x, l.lo.y, l.lo.z}, hi[3] = {l.hi.x, l.hi.y, l.hi.z};
  for (int d = 0; d < 3; ++d) {
    c.lo[d] = lo[d];
    c.hi[d] = hi[d];
  }
  const double n = std::sqrt(double(l.axis.x) * l.axis.x + double(l.axis.y) * l.axis.y +
                             double(l.axis.z) * l.axis.z);
  if (n > 0.0) c.axis = {l.axis.x / n, l.axis.y / n, l.axis.z / n};
  c.cosThetaO = n > 0.0 ? l.cosThetaO : -1.0;
  c.sinThetaO = std::sqrt(std::max(0.0, 1.0 - c.cosThetaO * c.cosThetaO));
  c.thetaO = safeAcos(c.cosThetaO);
  c.power = l.power;
  return c;
}

// The smallest cone found holding cones a and b (pbrt-v4's DirectionCone Union), into c.
void uniteCones(const Cluster& a, const Cluster& b, Cluster* c) {
  const Cluster& wider = a.thetaO >= b.thetaO ? a : b;
  const Cluster& narrower = a.thetaO >= b.thetaO ? b : a;
  c->axis = wider.axis;
  c->cosThetaO = wider.cosThetaO;
  c->sinThetaO = wider.sinThetaO;
  c->thetaO = wider.thetaO;
  if (wider.thetaO >= kPiDouble) return;  // the whole sphere already
  // The wider holds the narrower where theta_d + theta_n <= theta_w, i.e. (all three in [0, pi])
  // cos theta_d >= cos(theta_w - theta_n): a test without inverse trigonometry, which decides
  // most unions of a mesh's neighbouring faces.
  const double cosD = dot(a.axis, b.axis);
  if (cosD >= wider.cosThetaO * narrower.cosThetaO + wider.sinThetaO * narrower.sinThetaO) return;
  // Else the exact test, on an angle that is 0 for equal axes (cos^2 + sin^2 may round above 1,
  // and acos of a unit vector's dot with itself above 0: either made equal cones whole spheres).
  const double thetaD = angleBetween(a.axis, b.axis);
  if (thetaD + narrower.thetaO <= wider.thetaO) return;
  const double thetaO = 0.5 * (a.thetaO + thetaD + b.thetaO);
  const Direction k = cross(a.axis, b.axis);
  const double kLength = length(k);
  c->cosThetaO = -1.0;
  c->sinThetaO = 0.0;
  c->thetaO = kPiDouble;
  if (thetaO >= kPiDouble || !(kLength > 0.0)) return;
  // a's axis turned towards b's by theta_o - theta_a about their common normal.
  const Direction n{k.x / kLength, k.y / kLength, k.z / kLength};
  const Direction t = cross(n, a.axis);
  const double r = thetaO - a.thetaO, cr = std::cos(r), sr = std::sin(r);
  c->axis = {a.axis.x * cr + t.x * sr, a.axis.y * cr + t.y * sr, a.axis.z * cr + t.z * sr};
  c->cosThetaO = std::cos(thetaO);
  c->sinThetaO = std::sin(thetaO);
  c->thetaO = thetaO;
}

Cluster unite(const Cluster& a, const Cluster& b) {
  if (a.empty) return b;
  if (b.empty) return a;
  Cluster c;
  c.empty = false;
  for (int d = 0; d < 3; ++d) {
    c.lo[d] = std::min(a.lo[d], b.lo[d]);
    c.hi[d] = std::max(a.hi[d], b.hi[d]);
  }
  uniteCones(a, b, &c);
  c.power = a.power + b.power;
  return c;
}

// pbrt-v4's surface area and orientation heuristic for cluster c as one side of a split along
// `dim` of a range whose box is `whole`: power times the solid angle its cone reaches (theta_e
// is pi/2 for every light: render/light_tree.h) times its area, more for thin splits.
double splitCost(const Cluster& c, const Cluster& whole, int dim) {
  const double thetaO = c.thetaO, thetaE = 0.5 * kPiDouble;
  const double thetaW = std::min(thetaO + thetaE, kPiDouble);
  const double sinThetaO = c.sinThetaO;
  const double mOmega = 2.0 * kPiDouble * (1.0 - c.cosThetaO) +
                        kPiDouble / 2.0 *
                            (2.0 * thetaW * sinThetaO - std::cos(thetaO - 2.0 * thetaW) -
                             2.0 * thetaO * sinThetaO + c.cosThetaO);
  const double longest = std::max({whole.diagonal(0), whole.diagonal(1), whole.diagonal(2)});
  const double kr = whole.diagonal(dim) > 0.0 ? longest / whole.diagonal(dim) : 1.0;
  return c.power * mOmega * kr * c.surfaceArea();
}

// Slot k of `node` holds cluster c.
void writeSlot(const Cluster& c, int k, LightTreeNode* node) {
  const double dx = c.diagonal(0), dy = c.diagonal(1), dz = c.diagonal(2);
  node->centerX[k] = float(0.5 * (c.lo[0] + c.hi[0]));
  node->centerY[k] = float(0.5 * (c.lo[1] + c.hi[1]));
  node->centerZ[k] = float(0.5 * (c.lo[2] + c.hi[2]));
  // Rounded up, so that the sphere still holds the box in float; a point's stays 0, not the
  // least denormal, which every importance at the point would then meet (a microcode assist per
  // operation on the CPU: docs/performance.md, optimisation log).
  const float radius = float(0.5 * std::sqrt(dx * dx + dy * dy + dz * dz));
  node->radius[k] =
      radius > 0.0f ? std::nextafter(radius, std::numeric_limits<float>::infinity()) : 0.0f;
  node->axisX[k] = float(c.axis.x);
  node->axisY[k] = float(c.axis.y);
  node->axisZ[k] = float(c.axis.z);
  node->cosThetaO[k] = float(c.cosThetaO);
  node->sinThetaO[k] = float(c.sinThetaO);
  node->power[k] = float(c.power);
}

// Sets node->byPower where its first `groups` slots share one sphere and one cone.
void markByPower(int groups, LightTreeNode* node) {
  const LightTreeNode& n = *node;
  node->byPower = 1;
  for (int k = 1; k < groups; ++k) {
    const bool same = n.centerX[k] == n.centerX[0] && n.centerY[k] == n.centerY[0] &&
                      n.centerZ[k] == n.centerZ[0] && n.radius[k] == n.radius[0] &&
                      n.axisX[k] == n.axisX[0] && n.axisY[k] == n.axisY[0] &&
                      n.axisZ[k] == n.axisZ[0] && n.cosThetaO[k] == n.cosThetaO[0];
    if (!same) node->byPower = 0;
  }
}

// The fields of a light's bounds in a fixed order, to sort lights by.
std::array<double, 14> boundsKey(const LightBounds& l) {
  return {l.lo.x,   l.lo.y,   l.lo.z,      l.hi.x,  l.hi.y,     l.hi.z,     l.axis.x,
          l.axis.y, l.axis.z, l.cosThetaO, l.power, l.anchor.x, l.anchor.y, l.anchor.z};
}

class Builder {
 public:
  Builder(const std::vector<LightBounds>& lights, std::vector<uint64_t>* trails)
      : trails_(*trails) {
    for (uint32_t i = 0; i < lights.size(); ++i) {
      clusters_.push_back(candela::clusterOf(lights[i]));
      if (lights[i].power > 0.0) order_.push_back(i);
    }
    // The lights in an order of their own (see buildLightTree), ties in the order given.
    std::stable_sort(order_.begin(), order_.end(), [&lights](uint32_t a, uint32_t b) {
      return boundsKey(lights[a]) < boundsKey(lights[b]);
    });
    rank_.resize(lights.size());
    for (uint32_t i = 0; i < order_.size(); ++i) rank_[order_[i]] = i;
  }

  std::vector<LightTreeNode> build() {
    if (!order_.empty()) buildNode(0, order_.size(), 0, 0);
    return std::move(nodes_);
  }

 private:
  static constexpr int kBuckets = 12;

  Cluster clusterOf(size_t begin, size_t end) const {
    Cluster c;
    for (size_t i = begin; i < end; ++i) c = unite(c, clusters_[order_[i]]);
    return c;
  }

  double centroid(uint32_t light, int dim) const {
    const Cluster& c = clusters_[light];
    return 0.5 * (c.lo[dim] + c.hi[dim]);
  }

  // Splits [begin, end) (at least 2 lights) in two and returns where the second part starts:
  // the cheapest of the bucket boundaries along each axis by splitCost, or, where the centroids
  // coincide or the tree must stay balanced to keep within kMaxLightTreeDepth, the median along
  // the centroids' widest axis.
  size_t split(size_t begin, size_t end, uint32_t depth) {
    const size_t count = end - begin, middle = begin + count / 2;
    const uint32_t levelsLeft = kMaxLightTreeDepth - depth;
    const bool balance =
        levelsLeft < 2 || count > (uint64_t(1) << (kLightTreeTrailBits * (levelsLeft - 2)));
    // The range's box (only that of `whole` counts) and its lights' centroids' box.
    Cluster whole;
    whole.empty = false;
    double cmin[3], cmax[3];
    for (int d = 0; d < 3; ++d) {
      whole.lo[d] = cmin[d] = std::numeric_limits<double>::infinity();
      whole.hi[d] = cmax[d] = -whole.lo[d];
    }
    for (size_t i = begin; i < end; ++i) {
      const Cluster& c = clusters_[order_[i]];
      for (int d = 0; d < 3; ++d) {
        whole.lo[d] = std::min(whole.lo[d], c.lo[d]);
        whole.hi[d] = std::max(whole.hi[d], c.hi[d]);
        cmin[d] = std::min(cmin[d], centroid(order_[i], d));
        cmax[d] = std::max(cmax[d], centroid(order_[i], d));
      }
    }
    auto bucketOf = [&](uint32_t light, int d) {
      const double t = (centroid(light, d) - cmin[d]) / (cmax[d] - cmin[d]);
      return std::min(kBuckets - 1, int(kBuckets * t));
    };
    double best = std::numeric_limits<double>::infinity();
    int bestDim = -1, bestBucket = 0;
    for (int d = 0; d < 3 && !balance; ++d) {
      if (!(cmax[d] > cmin[d])) continue;
      Cluster buckets[kBuckets];
      for (size_t i = begin; i < end; ++i) {
        const uint32_t l = order_[i];
        Cluster& b = buckets[bucketOf(l, d)];
        b = unite(b, clusters_[l]);
      }
      Cluster below[kBuckets];  // below[i]: buckets 0..i
      for (int i = 0; i < kBuckets; ++i)
        below[i] = unite(i > 0 ? below[i - 1] : Cluster(), buckets[i]);
      Cluster above;
      for (int i = kBuckets - 2; i >= 0; --i) {
        above = unite(above, buckets[i + 1]);
        if (below[i].empty || above.empty) continue;
        const double cost = splitCost(below[i], whole, d) + splitCost(above, whole, d);
        if (cost < best) {
          best = cost;
          bestDim = d;
          bestBucket = i;
        }
      }
    }
    if (bestDim < 0) {  // halves along the centroids' widest axis (any halves where they coincide)
      int widest = 0;
      for (int d = 1; d < 3; ++d)
        if (cmax[d] - cmin[d] > cmax[widest] - cmin[widest]) widest = d;
      std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                       [&](uint32_t a, uint32_t b) {
                         const double ca = centroid(a, widest), cb = centroid(b, widest);
                         return ca < cb || (ca == cb && rank_[a] < rank_[b]);
                       });
      return middle;
    }
    const auto second =
        std::partition(order_.begin() + begin, order_.begin() + end,
                       [&](uint32_t l) { return bucketOf(l, bestDim) <= bestBucket; });
    const size_t at = size_t(second - order_.begin());
    return at > begin && at < end ? at : middle;
  }

  // A node for the lights [begin, end) at `depth`, reached by `trail`; returns its index. Its
  // clusters come of three rounds of splits in two.
  uint32_t buildNode(size_t begin, size_t end, uint64_t trail, uint32_t depth) {
    std::vector<size_t> bounds = {begin, end};  // cluster k: [bounds[k], bounds[k + 1])
    for (int round = 0; round < 3; ++round) {
      std::vector<size_t> finer = {begin};
      for (size_t k = 0; k + 1 < bounds.size(); ++k) {
        if (bounds[k + 1] - bounds[k] > 1) finer.push_back(split(bounds[k], bounds[k + 1], depth));
        finer.push_back(bounds[k + 1]);
      }
      bounds = std::move(finer);
    }
    const int groups = int(bounds.size()) - 1;
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.emplace_back();
    LightTreeNode node{};
    for (int k = 0; k < groups; ++k) {
      writeSlot(clusterOf(bounds[k], bounds[k + 1]), k, &node);
      const uint64_t childTrail = trail | (uint64_t(k) << (kLightTreeTrailBits * depth));
      if (bounds[k + 1] - bounds[k] == 1) {
        const uint32_t light = order_[bounds[k]];
        node.child[k] = light | kLightTreeLeaf;
        trails_[light] = childTrail;
      } else {
        node.child[k] = buildNode(bounds[k], bounds[k + 1], childTrail, depth + 1);
      }
    }
    markByPower(groups, &node);
    nodes_[index] = node;
    return index;
  }

  std::vector<uint64_t>& trails_;
  std::vector<Cluster> clusters_;  // one per light
  std::vector<uint32_t> order_;
  std::vector<uint32_t> rank_;  // of each light in the order of its own
  std::vector<LightTreeNode> nodes_;
};

}  // namespace

std::vector<LightTreeNode> buildLightTree(const std::vector<LightBounds>& lights,
                                          std::vector<uint64_t>* trails) {
  trails->assign(lights.size(), kNotInLightTree);
  return Builder(lights, trails).build();
}

}  // namespace candela
