#pragma once
// A dense cell grid over fixed sphere centres: the pairs closer than the cell size are all found
// among the 27 cells around each centre. Built once per pass, O(N); pairs come in a fixed order
// (cells in index order, then the centres' list order), so passes are deterministic.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/vec3.hpp"

namespace mpdem {

class SphereCells {
 public:
  // Cells of at least `h` (m) over the box [lo, hi] (centres outside are clamped to the edge cells),
  // coarser when the box would need more than `max_cells` cells.
  SphereCells(const Vec3& lo, const Vec3& hi, double h, std::size_t max_cells = std::size_t{1} << 22) : lo_(lo), h_(h) {
    const Vec3 e = hi - lo;
    for (;;) {
      double cells = 1.0;
      for (int a = 0; a < 3; ++a) cells *= std::max(1.0, std::ceil(e[a] / h_));
      if (cells <= static_cast<double>(max_cells)) break;
      h_ *= 1.26;
    }
    for (int a = 0; a < 3; ++a) dim_[a] = static_cast<int>(std::max(1.0, std::ceil(e[a] / h_)));
    head_.assign(static_cast<std::size_t>(dim_[0]) * dim_[1] * dim_[2], -1);
  }

  // Sorts the centres into the cells (x: m, centres, shape [n]).
  void build(const std::vector<Vec3>& x) {
    std::fill(head_.begin(), head_.end(), -1);
    next_.assign(x.size(), -1);
    // Reverse insertion keeps every cell's list in ascending index order.
    for (std::size_t i = x.size(); i-- > 0;) {
      const std::size_t c = flat(index(x[i].x, 0), index(x[i].y, 1), index(x[i].z, 2));
      next_[i] = head_[c];
      head_[c] = static_cast<int>(i);
    }
  }

  // Calls f(i, j) once for every pair i < j of centres in the same or neighbouring cells (the
  // cells of the last build), cell by cell.
  template <class F>
  void each_pair(F&& f) const {
    for (int ci = 0; ci < dim_[0]; ++ci)
      for (int cj = 0; cj < dim_[1]; ++cj)
        for (int ck = 0; ck < dim_[2]; ++ck)
          for (int i = head_[flat(ci, cj, ck)]; i >= 0; i = next_[i])
            for (int a = std::max(0, ci - 1); a <= std::min(dim_[0] - 1, ci + 1); ++a)
              for (int b = std::max(0, cj - 1); b <= std::min(dim_[1] - 1, cj + 1); ++b)
                for (int c = std::max(0, ck - 1); c <= std::min(dim_[2] - 1, ck + 1); ++c)
                  for (int j = head_[flat(a, b, c)]; j >= 0; j = next_[j])
                    if (j > i) f(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
  }

  double cell_size() const { return h_; }  // m

 private:
  int index(double v, int a) const {
    const double s = std::floor((v - lo_[a]) / h_);
    return static_cast<int>(std::clamp(s, 0.0, static_cast<double>(dim_[a] - 1)));
  }
  std::size_t flat(int i, int j, int k) const { return (static_cast<std::size_t>(i) * dim_[1] + j) * dim_[2] + k; }

  Vec3 lo_;
  double h_;  // m, cell size
  int dim_[3] = {1, 1, 1};
  std::vector<int> head_, next_;  // first centre per cell, next centre in the same cell
};

}  // namespace mpdem
