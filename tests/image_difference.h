// How far an image is from one it should equal up to rounding: the GPU's renders held against
// the CPU's, one CPU ray engine's or render loop's against another's.
#pragma once

#include <cstddef>
#include <vector>

namespace candela::test {

// The mean over the values of (a - b)^2 / (a^2 + 0.01), a from `reference`: relative where a
// value is bright, absolute near black, where rounding alone makes large relative differences.
inline double relMseAgainst(const std::vector<float>& reference, const std::vector<float>& image) {
  if (reference.empty() || reference.size() != image.size()) return 1e30;
  double sum = 0;
  for (size_t i = 0; i < reference.size(); ++i) {
    const double a = reference[i], b = image[i];
    sum += (a - b) * (a - b) / (a * a + 1e-2);
  }
  return sum / double(reference.size());
}

}  // namespace candela::test
