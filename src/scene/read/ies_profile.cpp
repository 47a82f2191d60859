// Reading IES files and resampling them; see ies_profile.h.
#include "scene/read/ies_profile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "render/light_profile.h"
#include "scene/content_hash.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The numbers after the TILT line, each with the line it is on.
class Numbers {
 public:
  Numbers(const std::string& text, size_t offset, size_t line, std::string label)
      : text_(text), at_(offset), line_(line), label_(std::move(label)) {}

  // The next number; `what` names it for messages.
  double next(const std::string& what) {
    while (at_ < text_.size() &&
           (std::isspace(static_cast<unsigned char>(text_[at_])) || text_[at_] == ',')) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    if (at_ >= text_.size()) fail("the file ends where " + what + " was expected");
    size_t end = at_;
    while (end < text_.size() && !std::isspace(static_cast<unsigned char>(text_[end])) &&
           text_[end] != ',')
      ++end;
    const std::string token = text_.substr(at_, end - at_);
    at_ = end;
    char* stop = nullptr;
    const double value = std::strtod(token.c_str(), &stop);
    if (token.empty() || *stop != '\0' || !std::isfinite(value))
      fail("expected " + what + ", got \"" + token + "\"");
    return value;
  }

  // A count in [1, max].
  size_t count(const std::string& what, size_t max) {
    const double v = next(what);
    if (!(v >= 1 && v <= double(max) && v == std::floor(v)))
      fail("expected " + what + " (a whole number from 1 to " + std::to_string(max) + "), got " +
           formatNumber(v));
    return size_t(v);
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw SceneError(label_ + ":" + std::to_string(line_) + ": " + message);
  }

 private:
  const std::string& text_;
  size_t at_;
  size_t line_;
  std::string label_;
};

// `count` angles, increasing, each in [0, limit].
std::vector<double> readAngles(Numbers& in, size_t count, const std::string& what, double limit) {
  std::vector<double> angles;
  for (size_t i = 0; i < count; ++i) {
    const double a = in.next(what);
    if (!(a >= 0 && a <= limit))
      in.fail("expected " + what + " from 0 to " + formatNumber(limit) + " degrees, got " +
              formatNumber(a));
    if (!angles.empty() && !(a > angles.back()))
      in.fail("expected " + what + " in increasing order, got " + formatNumber(a) + " after " +
              formatNumber(angles.back()));
    angles.push_back(a);
  }
  return angles;
}

// Linear interpolation of values[k] over increasing `angles` at a (clamped to their range).
double interpolate(const std::vector<double>& angles, const double* values, double a) {
  if (angles.size() == 1 || a <= angles.front()) return values[0];
  if (a >= angles.back()) return values[angles.size() - 1];
  const size_t hi = size_t(std::upper_bound(angles.begin(), angles.end(), a) - angles.begin());
  const double t = (a - angles[hi - 1]) / (angles[hi] - angles[hi - 1]);
  return values[hi - 1] + t * (values[hi] - values[hi - 1]);
}

}  // namespace

IesProfile readIesProfile(const std::string& path, const std::string& label) {
  std::string text, reason;
  if (!readTextFile(path, &text, &reason)) throw SceneError(label + ": cannot read: " + reason);
  // The header: keyword lines up to "TILT=", after which come the numbers.
  size_t at = 0, line = 1;
  bool tilt = false;
  while (at < text.size()) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string header = text.substr(at, end - at);
    header.erase(header.find_last_not_of(" \t\r") + 1);  // CRLF files, trailing blanks
    at = std::min(end + 1, text.size());
    tilt = header.rfind("TILT=", 0) == 0;
    if (tilt && header != "TILT=NONE")
      throw SceneError(label + ":" + std::to_string(line) +
                       ": expected TILT=NONE (a lamp whose output does not change with its "
                       "tilt), got \"" +
                       header + "\"");
    ++line;
    if (tilt) break;
  }
  if (!tilt) throw SceneError(label + ": no TILT line; expected an IES (LM-63) photometric file");
  Numbers in(text, at, line, label);
  in.next("the number of lamps");
  in.next("the lumens per lamp");
  const double multiplier = in.next("the candela multiplier");
  const size_t verticalCount = in.count("the number of vertical angles", 100000);
  const size_t horizontalCount = in.count("the number of horizontal angles", 100000);
  const double type = in.next("the photometric type");
  if (type != 1)
    in.fail("expected photometric type 1 (type C, as luminaires are measured), got " +
            formatNumber(type));
  for (const char* field : {"the units type", "the width", "the length", "the height",
                            "the ballast factor", "the ballast-lamp factor", "the input watts"})
    in.next(field);
  IesProfile p;
  p.vertical = readAngles(in, verticalCount, "vertical angles", 180);
  if (!(p.vertical.front() == 0 || p.vertical.front() == 90) ||
      !(p.vertical.back() == 90 || p.vertical.back() == 180))
    in.fail("expected vertical angles from 0 or 90 to 90 or 180 degrees, got " +
            formatNumber(p.vertical.front()) + " to " + formatNumber(p.vertical.back()));
  p.horizontal = readAngles(in, horizontalCount, "horizontal angles", 360);
  const double first = p.horizontal.front(), last = p.horizontal.back();
  const bool symmetric = (first == 0 && (last == 0 || last == 90 || last == 180 || last == 360)) ||
                         (first == 90 && last == 270);
  if (!symmetric)
    in.fail(
        "expected horizontal angles 0 alone, or from 0 to 90, 180 or 360, or from 90 to 270 "
        "degrees, got " +
        formatNumber(first) + " to " + formatNumber(last));
  double largest = 0;
  for (size_t i = 0; i < verticalCount * horizontalCount; ++i) {
    const double value = in.next("a candela value") * multiplier;
    if (!(value >= 0 && std::isfinite(value)))
      in.fail("expected non-negative candela values, got " + formatNumber(value));
    largest = std::max(largest, value);
    p.candela.push_back(value);
  }
  if (!(largest > 0)) in.fail("every candela value is 0; expected a lamp that emits");
  return p;
}

double iesValue(const IesProfile& p, double theta, double phi) {
  if (theta < p.vertical.front() || theta > p.vertical.back()) return 0;
  phi = std::fmod(phi, 360.0);
  if (phi < 0) phi += 360;
  const double first = p.horizontal.front(), last = p.horizontal.back();
  // Fold phi into the planes the file gives, by its symmetry.
  if (first == 0 && last == 90) {
    if (phi > 180) phi = 360 - phi;
    if (phi > 90) phi = 180 - phi;
  } else if (first == 0 && last == 180) {
    if (phi > 180) phi = 360 - phi;
  } else if (first == 90 && last == 270) {
    if (phi < 90) phi = 180 - phi;
    if (phi > 270) phi = 540 - phi;
  }
  // In the planes on either side of phi, then between them.
  const size_t n = p.vertical.size();
  const std::vector<double>& planes = p.horizontal;
  const auto inPlane = [&](size_t h) { return interpolate(p.vertical, &p.candela[h * n], theta); };
  if (phi <= planes.front()) return inPlane(0);
  if (phi >= planes.back()) return inPlane(planes.size() - 1);
  const size_t hi = size_t(std::upper_bound(planes.begin(), planes.end(), phi) - planes.begin());
  const double t = (phi - planes[hi - 1]) / (planes[hi] - planes[hi - 1]);
  return inPlane(hi - 1) + t * (inPlane(hi) - inPlane(hi - 1));
}

TextureDesc profileTexture(const IesProfile& p, const std::string& file) {
  TextureDesc t;
  t.file = file;
  t.format = TextureFormat::Float;
  t.width = p.horizontal.size() == 1 ? 1 : kProfileColumns;
  t.height = kProfileRows;
  double largest = 0;
  for (double c : p.candela) largest = std::max(largest, c);
  t.texelsF.assign(size_t(4) * t.width * t.height, 0.0f);
  for (uint32_t j = 0; j < t.height; ++j)
    for (uint32_t i = 0; i < t.width; ++i) {
      const double theta = 180.0 * j / (t.height - 1), phi = 360.0 * i / t.width;
      // Rows beyond the file's angles repeat its edge (render/light_profile.h cuts there).
      const double within = std::min(std::max(theta, p.vertical.front()), p.vertical.back());
      // Relative to the largest value: any scale will do, and this one keeps floats in range.
      const float v = float(iesValue(p, within, phi) / largest);
      float* texel = &t.texelsF[4 * (size_t(j) * t.width + i)];
      texel[0] = texel[1] = texel[2] = v;
      texel[3] = 1.0f;
    }
  t.contentHash = hashTexture(t);
  return t;
}

double profileTextureMean(const TextureDesc& t, double first, double last) {
  // Bilinear within each cell: exact in phi by the trapezoidal rule over the columns, and in
  // theta by sub-steps of each row's band weighted by their solid angle.
  constexpr int kSteps = 16;
  double sum = 0;
  for (uint32_t j = 0; j + 1 < t.height; ++j) {
    const double t0 = kPi * j / (t.height - 1), t1 = kPi * (j + 1) / (t.height - 1);
    // The file's first and last angles (0, 90 or 180 degrees) fall on row boundaries.
    if (t1 <= first * kPi / 180 + 1e-9 || t0 >= last * kPi / 180 - 1e-9) continue;
    for (int k = 0; k < kSteps; ++k) {
      const double f = (k + 0.5) / kSteps;
      const double theta = t0 + f * (t1 - t0);
      const double band = std::sin(theta) * (t1 - t0) / kSteps;  // solid angle / (2 pi)
      double ring = 0;
      for (uint32_t i = 0; i < t.width; ++i) {
        const double top = t.texelsF[4 * (size_t(j) * t.width + i)];
        const double bottom = t.texelsF[4 * (size_t(j + 1) * t.width + i)];
        ring += top + f * (bottom - top);
      }
      sum += band * ring / t.width;
    }
  }
  return sum / 2.0;  // over 4 pi: (2 pi sum) / (4 pi)
}

}  // namespace candela
