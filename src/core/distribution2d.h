// A 2D distribution over [0,1)^2 of n x m cells (pbrt-v4's PiecewiseConstant2D), stored as
// cumulative sums: `marginal` (rows + 1 values) over the rows and, per row, `conditional`
// (columns + 1 values each) over its columns. Sampling inverts the sums and is continuous within
// a cell. Within a cell the density is constant, or, given the weights at the cells' corners
// (`corners`, (columns + 1) x (rows + 1)), their bilinear interpolation (Mitsuba 3 samples its
// environment maps so): then each cell's mass must be the mean of its corners times a factor
// constant over the cell. Each sum has a guide table (Chen and Asau's cutpoints): where the
// search for u in [k/n, (k+1)/n) starts and ends, so inverting costs a step or two rather than
// log2(n) dependent loads, with the very result of the full search. Built on the host
// (buildDistribution2D), sampled by the kernel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/device.h"
#include "core/float_error.h"
#include "core/sampling.h"

namespace candela {

// Inverts cdf[0..n] (non-decreasing, cdf[0] = 0, cdf[n] = 1) at u in [0, 1): the segment that
// holds u, where in it u lies (*t in [0, 1)) and the density there (0 for a segment of no mass).
// guide[0..n] is cdf's guide table (buildGuide).
CANDELA_HDI_ALWAYS uint32_t invertCdf(const float* cdf, const uint32_t* guide, uint32_t n, float u,
                                      float* t, float* pdf) {
  // The segment sought is the first o with cdf[o + 1] > u. The guide brackets it in [lo, hi];
  // the two loops only widen the bracket where rounding put u * n in the neighbouring cell.
  const uint32_t cell = u * float(n) < float(n) ? uint32_t(u * float(n)) : n - 1;
  uint32_t lo = guide[cell], hi = guide[cell + 1];
  while (lo > 0 && cdf[lo] > u) --lo;
  while (hi < n - 1 && cdf[hi + 1] <= u) ++hi;
  while (lo < hi) {
    const uint32_t mid = (lo + hi) / 2;
    if (cdf[mid + 1] <= u) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  const uint32_t o = lo;
  const float width = cdf[o + 1] - cdf[o];
  const float within = width > 0.0f ? (u - cdf[o]) / width : 0.5f;
  *t = within < 0.0f ? 0.0f : (within < 0.99999994f ? within : 0.99999994f);
  *pdf = width * float(n);
  return o;
}

// The point (o + t) / n of cell o of n, t in [0, 1). Rounding can carry it onto a neighbouring
// cell's edge; it must stay in cell o as Distribution2D::pdf finds cells (floor of x n), or MIS
// would weigh it by the wrong pdf.
CANDELA_HDI_ALWAYS float pointInCell(uint32_t o, float t, uint32_t n) {
  float x = (float(o) + t) / float(n);
  while (x * float(n) >= float(o + 1)) x = nextFloatDown(x);
  while (x * float(n) < float(o)) x = nextFloatUp(x);
  return x;
}

// invertCdf's point in [0, 1), its segment and the density there.
CANDELA_HDI_ALWAYS float sampleCdf(const float* cdf, const uint32_t* guide, uint32_t n, float u,
                                   uint32_t* segment, float* pdf) {
  float t;
  *segment = invertCdf(cdf, guide, n, u, &t, pdf);
  return pointInCell(*segment, t, n);
}

struct Distribution2D {
  const float* conditional;          // rows x (columns + 1)
  const float* marginal;             // rows + 1
  const uint32_t* conditionalGuide;  // rows x (columns + 1)
  const uint32_t* marginalGuide;     // rows + 1
  uint32_t columns, rows;
  const float* corners = nullptr;  // (rows + 1) x (columns + 1); none: constant within cells

  // A cell and a point (s, t) in [0,1)^2 within it from uniform (u1, u2), with the density of
  // the point (column + s, row + t) / (columns, rows) over [0,1)^2; false where it has none.
  CANDELA_HDI_ALWAYS bool sampleCell(float u1, float u2, uint32_t* column, uint32_t* row, float* s,
                                     float* t, float* pdf) const {
    float pdfRow, pdfColumn;
    *row = invertCdf(marginal, marginalGuide, rows, u2, t, &pdfRow);
    const size_t rowStart = size_t(*row) * (columns + 1);
    *column =
        invertCdf(conditional + rowStart, conditionalGuide + rowStart, columns, u1, s, &pdfColumn);
    *pdf = pdfRow * pdfColumn;
    if (corners) {
      float w[4];
      cornerWeights(*column, *row, w);
      sampleBilinear(*s, *t, w, s, t);
      *pdf *= bilinearPdf(*s, *t, w);
    }
    return *pdf > 0.0f;
  }

  // The density sampleCell gives point (s, t) of cell (column, row).
  CANDELA_HDI_ALWAYS float cellPdf(uint32_t column, uint32_t row, float s, float t) const {
    const float* c = conditional + size_t(row) * (columns + 1);
    const float cell = (marginal[row + 1] - marginal[row]) * float(rows) *
                       (c[column + 1] - c[column]) * float(columns);
    if (!corners) return cell;
    float w[4];
    cornerWeights(column, row, w);
    return cell * bilinearPdf(s, t, w);
  }

  // A point (x, y) in [0,1)^2 from uniform (u1, u2), with its density; false where it has none.
  CANDELA_HDI bool sample(float u1, float u2, float* x, float* y, float* pdf) const {
    uint32_t column, row;
    float s, t;
    sampleCell(u1, u2, &column, &row, &s, &t, pdf);
    *x = pointInCell(column, s, columns);
    *y = pointInCell(row, t, rows);
    if (corners) *pdf = this->pdf(*x, *y);  // as pdf() finds it from the point
    return *pdf > 0.0f;
  }

  CANDELA_HDI float pdf(float x, float y) const {
    uint32_t column = uint32_t(x * float(columns)), row = uint32_t(y * float(rows));
    column = column < columns ? column : columns - 1;
    row = row < rows ? row : rows - 1;
    return cellPdf(column, row, x * float(columns) - float(column), y * float(rows) - float(row));
  }

 private:
  CANDELA_HDI_ALWAYS void cornerWeights(uint32_t column, uint32_t row, float w[4]) const {
    const float* top = corners + size_t(row) * (columns + 1) + column;
    const float* bottom = top + (columns + 1);
    w[0] = top[0];
    w[1] = top[1];
    w[2] = bottom[0];
    w[3] = bottom[1];
  }
};

// The guide table of cdf[0..n]: guide[k], k in [0, n], is the first segment o with
// cdf[o + 1] > k / n (n - 1 where none is), computed in the float arithmetic sampleCdf uses.
inline void buildGuide(const float* cdf, uint32_t n, uint32_t* guide) {
  uint32_t o = 0;
  for (uint32_t k = 0; k <= n; ++k) {
    const float u = float(k) / float(n);
    while (o < n - 1 && cdf[o + 1] <= u) ++o;
    guide[k] = o;
  }
}

struct Distribution2DArrays {
  std::vector<float> conditional, marginal;
  std::vector<uint32_t> conditionalGuide, marginalGuide;
  std::vector<float> corners;  // empty: constant within cells
};

// The cumulative sums of the cell masses mass(j, i) (row j < rows, column i < columns, every
// value >= 0) and their guide tables. A row without mass gets a uniform conditional (never
// reached: its marginal share is 0); without any mass at all the marginal is uniform too. Each
// mass is asked for twice (a row's sum, then its running sums), so none has to be stored.
template <class Mass>
void buildDistribution2DOf(Mass mass, uint32_t columns, uint32_t rows, Distribution2DArrays* d) {
  std::vector<float>* conditional = &d->conditional;
  std::vector<float>* marginal = &d->marginal;
  conditional->assign(size_t(rows) * (columns + 1), 0.0f);
  std::vector<double> rowSums(rows, 0.0);
  for (uint32_t j = 0; j < rows; ++j) {
    double sum = 0.0;
    for (uint32_t i = 0; i < columns; ++i) sum += mass(j, i);
    rowSums[j] = sum;
    float* c = conditional->data() + size_t(j) * (columns + 1);
    double running = 0.0;
    for (uint32_t i = 0; i < columns; ++i) {
      running += mass(j, i);
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

  d->conditionalGuide.assign(conditional->size(), 0);
  for (uint32_t j = 0; j < rows; ++j) {
    const size_t start = size_t(j) * (columns + 1);
    buildGuide(conditional->data() + start, columns, d->conditionalGuide.data() + start);
  }
  d->marginalGuide.assign(marginal->size(), 0);
  buildGuide(marginal->data(), rows, d->marginalGuide.data());
}

// The distribution of the masses f (rows x columns, row-major), constant within cells.
inline void buildDistribution2D(const std::vector<double>& f, uint32_t columns, uint32_t rows,
                                Distribution2DArrays* d) {
  buildDistribution2DOf([&](uint32_t j, uint32_t i) { return f[size_t(j) * columns + i]; }, columns,
                        rows, d);
}

// The bilinear distribution of the corner weights (rows + 1 rows of columns + 1, every value
// >= 0) over cells whose rows may differ in height: each cell's mass is the mean of its corners
// times its row's factor (rowFactor[rows], its height in units of the others'), as
// Distribution2D's bilinear density needs.
inline void buildBilinearDistribution2D(std::vector<float> corners,
                                        const std::vector<double>& rowFactor, uint32_t columns,
                                        uint32_t rows, Distribution2DArrays* d) {
  const float* weights = corners.data();
  buildDistribution2DOf(
      [&](uint32_t j, uint32_t i) {
        const float* top = weights + size_t(j) * (columns + 1);
        const float* bottom = top + (columns + 1);
        return 0.25 * (double(top[i]) + top[i + 1] + bottom[i] + bottom[i + 1]) * rowFactor[j];
      },
      columns, rows, d);
  d->corners = std::move(corners);
}

}  // namespace candela
