// A piecewise-constant 2D distribution over [0,1)^2 of n x m cells (pbrt-v4's
// PiecewiseConstant2D), stored as cumulative sums: `marginal` (rows + 1 values) over the rows and,
// per row, `conditional` (columns + 1 values each) over its columns. Sampling inverts the sums
// and is continuous within a cell; the density of a point is its cell's share times the cell
// count. Built on the host (buildDistribution2D), sampled by the kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/device.h"

namespace candela {

// Inverts cdf[0..n] (non-decreasing, cdf[0] = 0, cdf[n] = 1) at u in [0, 1): the point in [0, 1)
// whose segment holds u, its segment and the density there (0 for a segment of no mass).
CANDELA_HDI float sampleCdf(const float* cdf, uint32_t n, float u, uint32_t* segment, float* pdf) {
  uint32_t lo = 0, hi = n;  // the first segment o with cdf[o + 1] > u
  while (lo < hi) {
    const uint32_t mid = (lo + hi) / 2;
    if (cdf[mid + 1] <= u) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  const uint32_t o = lo < n ? lo : n - 1;
  const float width = cdf[o + 1] - cdf[o];
  float t = width > 0.0f ? (u - cdf[o]) / width : 0.5f;
  t = t < 0.0f ? 0.0f : (t < 0.99999994f ? t : 0.99999994f);  // stay inside the segment
  *segment = o;
  *pdf = width * float(n);
  return (float(o) + t) / float(n);
}

struct Distribution2D {
  const float* conditional;  // rows x (columns + 1)
  const float* marginal;     // rows + 1
  uint32_t columns, rows;

  // A point (x, y) in [0,1)^2 from uniform (u1, u2), with its density; false where it has none.
  CANDELA_HDI bool sample(float u1, float u2, float* x, float* y, float* pdf) const {
    uint32_t row, column;
    float pdfRow, pdfColumn;
    *y = sampleCdf(marginal, rows, u2, &row, &pdfRow);
    *x = sampleCdf(conditional + size_t(row) * (columns + 1), columns, u1, &column, &pdfColumn);
    *pdf = pdfRow * pdfColumn;
    return *pdf > 0.0f;
  }

  CANDELA_HDI float pdf(float x, float y) const {
    uint32_t column = uint32_t(x * float(columns)), row = uint32_t(y * float(rows));
    column = column < columns ? column : columns - 1;
    row = row < rows ? row : rows - 1;
    const float* c = conditional + size_t(row) * (columns + 1);
    return (marginal[row + 1] - marginal[row]) * float(rows) * (c[column + 1] - c[column]) *
           float(columns);
  }
};

// The cumulative sums of f (rows x columns, row-major, every value >= 0). A row without mass
// gets a uniform conditional (never reached: its marginal share is 0); without any mass at all
// the marginal is uniform too.
inline void buildDistribution2D(const std::vector<double>& f, uint32_t columns, uint32_t rows,
                                std::vector<float>* conditional, std::vector<float>* marginal) {
  conditional->assign(size_t(rows) * (columns + 1), 0.0f);
  std::vector<double> rowSums(rows, 0.0);
  for (uint32_t j = 0; j < rows; ++j) {
    double sum = 0.0;
    for (uint32_t i = 0; i < columns; ++i) sum += f[size_t(j) * columns + i];
    rowSums[j] = sum;
    float* c = conditional->data() + size_t(j) * (columns + 1);
    double running = 0.0;
    for (uint32_t i = 0; i < columns; ++i) {
      running += f[size_t(j) * columns + i];
      c[i + 1] = sum > 0.0 ? float(running / sum) : float(double(i + 1) / columns);
    }
    c[columns] = 1.0f;
  }
  double total = 0.0;
  for (double s : rowSums) total += s;
  marginal->assign(rows + 1, 0.0f);
  double running = 0.0;
  for (uint32_t j = 0; j < rows; ++j) {
    running += rowSums[j];
    (*marginal)[j + 1] = total > 0.0 ? float(running / total) : float(double(j + 1) / rows);
  }
  (*marginal)[rows] = 1.0f;
}

}  // namespace candela
