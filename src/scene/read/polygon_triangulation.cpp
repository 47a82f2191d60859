// Fan and ear-clipping triangulation; see polygon_triangulation.h.
#include "scene/read/polygon_triangulation.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

namespace candela {
namespace {

struct Point {
  double x, y;
};

// Twice the signed area of (a, b, c): positive when they turn the polygon's way.
double turn(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Corners come from text with a few decimals, read as floats: on a fine curve (a circle of a
// million corners) that rounding turns corners either way. A corner is reflex only when it turns
// back by more than rounding explains: a dent deeper than 1e-5 of the polygon's size, or than
// a few float steps of its coordinates.
bool isReflexTurn(const Point& a, const Point& b, const Point& c, double slack) {
  const double edges =
      std::fabs(b.x - a.x) + std::fabs(b.y - a.y) + std::fabs(c.x - b.x) + std::fabs(c.y - b.y);
  return turn(a, b, c) < -slack * edges;
}

// The slack of isReflexTurn for these points.
double roundingSlack(const std::vector<Point>& points) {
  Point lo = points[0], hi = points[0];
  for (const Point& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double size = std::max(hi.x - lo.x, hi.y - lo.y);
  const double largest = std::max({std::fabs(lo.x), std::fabs(lo.y), hi.x, hi.y});
  return 1e-5 * size + 4 * double(FLT_EPSILON) * largest;
}

// The corners on the plane that the polygon's normal (Newell's method) is most aligned with,
// mirrored where needed so that the polygon winds counter-clockwise there. Empty when the normal
// is zero or not finite (every corner on one line, or coordinates too large).
std::vector<Point> projectCorners(const std::vector<Vec3>& corners) {
  double normal[3] = {0, 0, 0};
  const size_t n = corners.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& a = corners[i];
    const Vec3& b = corners[(i + 1) % n];
    normal[0] += (double(a.y) - b.y) * (double(a.z) + b.z);
    normal[1] += (double(a.z) - b.z) * (double(a.x) + b.x);
    normal[2] += (double(a.x) - b.x) * (double(a.y) + b.y);
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(normal[i]) > std::fabs(normal[axis])) axis = i;
  if (!(std::fabs(normal[axis]) > 0) || !std::isfinite(normal[axis])) return {};
  // Dropping x, y or z keeps (y, z), (z, x) or (x, y): the order in which the normal's
  // component along the dropped axis is the 2D winding.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double mirror = normal[axis] > 0 ? 1 : -1;
  std::vector<Point> points(n);
  for (size_t i = 0; i < n; ++i) points[i] = {corners[i][u], mirror * corners[i][v]};
  return points;
}

void fan(size_t n, std::vector<CornerTriangle>* triangles) {
  for (size_t i = 1; i + 1 < n; ++i) triangles->push_back({0, uint32_t(i), uint32_t(i + 1)});
}

// Ear clipping over a ring of corners, with exact turns. Only reflex corners can lie inside an ear,
// and cutting an ear changes only its two neighbours, so each cut costs the reflex corners once
// per neighbour.
class EarClipper {
 public:
  explicit EarClipper(std::vector<Point> points)
      : p_(std::move(points)),
        prev_(p_.size()),
        next_(p_.size()),
        reflex_(p_.size()),
        alive_(p_.size(), true) {
    const size_t n = p_.size();
    for (size_t i = 0; i < n; ++i) {
      prev_[i] = uint32_t((i + n - 1) % n);
      next_[i] = uint32_t((i + 1) % n);
    }
    for (uint32_t i = 0; i < n; ++i) {
      reflex_[i] = isReflex(i);
      if (reflex_[i]) reflexList_.push_back(i);
    }
    for (uint32_t i = 0; i < n; ++i)
      if (isEar(i)) ears_.push_back(i);
  }

  void run(std::vector<CornerTriangle>* triangles) {
    size_t left = p_.size();
    uint32_t cursor = 0;
    while (left > 3) {
      uint32_t v = cursor;
      if (!nextEar(&v)) v = fallbackCorner(cursor);
      const uint32_t a = prev_[v], b = next_[v];
      triangles->push_back({a, v, b});
      alive_[v] = false;
      next_[a] = b;
      prev_[b] = a;
      --left;
      cursor = b;
      for (const uint32_t w : {a, b}) {
        reflex_[w] = isReflex(w);
        if (isEar(w)) ears_.push_back(w);
      }
    }
    triangles->push_back({prev_[cursor], cursor, next_[cursor]});
  }

 private:
  bool isReflex(uint32_t i) const { return turn(p_[prev_[i]], p_[i], p_[next_[i]]) < 0; }

  bool isEar(uint32_t i) const {
    if (reflex_[i]) return false;
    const uint32_t a = prev_[i], b = next_[i];
    const Point &pa = p_[a], &pi = p_[i], &pb = p_[b];
    for (const uint32_t r : reflexList_) {
      if (!alive_[r] || !reflex_[r] || r == a || r == i || r == b) continue;
      const Point& q = p_[r];
      const bool corner = (q.x == pa.x && q.y == pa.y) || (q.x == pi.x && q.y == pi.y) ||
                          (q.x == pb.x && q.y == pb.y);
      if (!corner && turn(pa, pi, q) >= 0 && turn(pi, pb, q) >= 0 && turn(pb, pa, q) >= 0)
        return false;
    }
    return true;
  }

  // The latest corner found to be an ear that still is one.
  bool nextEar(uint32_t* v) {
    while (!ears_.empty()) {
      const uint32_t candidate = ears_.back();
      ears_.pop_back();
      if (alive_[candidate] && isEar(candidate)) {
        *v = candidate;
        return true;
      }
    }
    return false;
  }

  // No ear left (the polygon crosses itself, or rounding hid one): the first corner from `start`
  // that is not reflex, else `start`.
  uint32_t fallbackCorner(uint32_t start) const {
    uint32_t v = start;
    do {
      if (!reflex_[v]) return v;
      v = next_[v];
    } while (v != start);
    return start;
  }

  std::vector<Point> p_;
  std::vector<uint32_t> prev_, next_;
  std::vector<bool> reflex_, alive_;
  std::vector<uint32_t> reflexList_;  // every corner reflex at the start; entries go stale
  std::vector<uint32_t> ears_;        // candidates, checked again when taken
};

}  // namespace

bool triangulatePolygon(const std::vector<Vec3>& corners, std::vector<CornerTriangle>* triangles) {
  triangles->clear();
  const size_t n = corners.size();
  std::vector<Point> points = projectCorners(corners);
  if (points.empty()) {  // no plane to work in: every triangle is degenerate anyway
    fan(n, triangles);
    return true;
  }
  const double slack = roundingSlack(points);
  bool convex = true;
  for (size_t i = 0; i < n && convex; ++i)
    convex = !isReflexTurn(points[(i + n - 1) % n], points[i], points[(i + 1) % n], slack);
  if (convex) {
    fan(n, triangles);
    return true;
  }
  if (n > kMaxConcaveFaceCorners) return false;
  EarClipper clipper(std::move(points));
  triangles->reserve(n - 2);
  clipper.run(triangles);
  return true;
}

}  // namespace candela
