// MeshSolid: point-in-mesh by ray parity and sphere clearance (docs/tools.md "Regions").
#include "geometry/mesh_solid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/triangle_closest_point.hpp"

namespace mpdem {

namespace {

struct P2 {
  double u, v;  // (y, z) of a point projected along x
};

double orient(const P2& a, const P2& b, const P2& q) { return (b.u - a.u) * (q.v - a.v) - (b.v - a.v) * (q.u - a.u); }

// Side of q relative to the directed edge a -> b, evaluated in a canonical vertex order so that
// the reversed edge gives exactly the negated value: a point on a shared edge is seen on the
// edge (0) by both triangles, never inside both or neither through rounding.
double edge_side2(const P2& a, const P2& b, const P2& q) {
  const bool swap = a.u > b.u || (a.u == b.u && a.v > b.v);
  return swap ? -orient(b, a, q) : orient(a, b, q);
}

// Tie rule: a point exactly on edge a -> b belongs to the triangle iff the edge points into one
// fixed half-plane of directions; of two triangles sharing the edge on opposite sides, exactly one
// (they traverse it in opposite directions) claims the point.
bool owns_edge(const P2& a, const P2& b) { return b.v > a.v || (b.v == a.v && b.u < a.u); }

// Builds CSR lists: for each item, the cells [first, last] of its range; counts then fills.
template <class Range>
void fill_csr(std::size_t items, std::size_t cells, Range range, std::vector<std::uint32_t>& start,
              std::vector<std::uint32_t>& list) {
  start.assign(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
      list.assign(start[cells], 0);
      fill.assign(start.begin(), start.end() - 1);
    }
    for (std::size_t t = 0; t < items; ++t)
      range(t, [&](std::size_t c) {
        if (pass == 0) ++start[c + 1];
        else list[fill[c]++] = static_cast<std::uint32_t>(t);
      });
  }
}

}  // namespace

MeshSolid::MeshSolid(const TriangleMesh& mesh) {
  if (mesh.size() == 0) throw std::invalid_argument("the surface has no triangles");
  if (const std::string p = closed_surface_problem(mesh); !p.empty())
    throw std::invalid_argument("the surface is " + p);
  tri_ = soup(mesh);
  volume_ = std::abs(signed_volume(mesh));
  lo_ = hi_ = tri_[0][0];
  for (const auto& t : tri_)
    for (const Vec3& p : t) {
      lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
      hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y), std::max(hi_.z, p.z)};
    }
  const Vec3 ext = hi_ - lo_;
  if (!(ext.x > 0.0 && ext.y > 0.0 && ext.z > 0.0 && volume_ > 0.0))
    throw std::invalid_argument("the surface encloses no volume");

  // Columns: about sqrt(T) per axis keeps a handful of triangles per column.
  const int nc = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(tri_.size()))), 1, 256);
  ny_ = nz_ = nc;
  hy_ = ext.y / ny_;
  hz_ = ext.z / nz_;
  fill_csr(
      tri_.size(), static_cast<std::size_t>(ny_) * nz_,
      [&](std::size_t t, auto emit) {
        const auto& tr = tri_[t];
        const int y0 = column_y(std::min({tr[0].y, tr[1].y, tr[2].y})),
                  y1 = column_y(std::max({tr[0].y, tr[1].y, tr[2].y}));
        const int z0 = column_z(std::min({tr[0].z, tr[1].z, tr[2].z})),
                  z1 = column_z(std::max({tr[0].z, tr[1].z, tr[2].z}));
        for (int j = y0; j <= y1; ++j)
          for (int k = z0; k <= z1; ++k) emit(static_cast<std::size_t>(j) * nz_ + k);
      },
      col_start_, col_tri_);

  // Cells: about 4 per triangle, at most 64^3.
  const double target = std::clamp(4.0 * static_cast<double>(tri_.size()), 1.0, 262144.0);
  h_ = std::cbrt(ext.x * ext.y * ext.z / target);
  for (int a = 0; a < 3; ++a) n_[a] = std::clamp(static_cast<int>(std::ceil(ext[a] / h_)), 1, 1024);
  fill_csr(
      tri_.size(), static_cast<std::size_t>(n_[0]) * n_[1] * n_[2],
      [&](std::size_t t, auto emit) {
        const auto& tr = tri_[t];
        std::array<int, 3> c0{}, c1{};
        for (int a = 0; a < 3; ++a) {
          c0[a] = cell(std::min({tr[0][a], tr[1][a], tr[2][a]}), a);
          c1[a] = cell(std::max({tr[0][a], tr[1][a], tr[2][a]}), a);
        }
        for (int i = c0[0]; i <= c1[0]; ++i)
          for (int j = c0[1]; j <= c1[1]; ++j)
            for (int k = c0[2]; k <= c1[2]; ++k) emit((static_cast<std::size_t>(i) * n_[1] + j) * n_[2] + k);
      },
      cell_start_, cell_tri_);
  stamp_.assign(tri_.size(), 0);
}

int MeshSolid::column_y(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - lo_.y) / hy_)), 0, ny_ - 1);
}
int MeshSolid::column_z(double z) const {
  return std::clamp(static_cast<int>(std::floor((z - lo_.z) / hz_)), 0, nz_ - 1);
}
int MeshSolid::cell(double v, int axis) const {
  return std::clamp(static_cast<int>(std::floor((v - lo_[axis]) / h_)), 0, n_[axis] - 1);
}

// Does the ray {p + s e_x, s > 0} cross triangle t? Projected along x, p must lie in the
// triangle (with the tie rule), and the triangle's plane must be ahead of p there.
bool MeshSolid::ray_crosses(const std::array<Vec3, 3>& t, const Vec3& p) const {
  P2 a{t[0].y, t[0].z}, b{t[1].y, t[1].z}, c{t[2].y, t[2].z};
  const P2 q{p.y, p.z};
  const double area2 = orient(a, b, c);
  if (area2 == 0.0) return false;  // parallel to the ray: its neighbours decide
  if (area2 < 0.0) std::swap(b, c);
  const P2 v[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    const double s = edge_side2(v[k], v[(k + 1) % 3], q);
    if (s < 0.0 || (s == 0.0 && !owns_edge(v[k], v[(k + 1) % 3]))) return false;
  }
  const Vec3 n = cross(t[1] - t[0], t[2] - t[0]);
  const double x = t[0].x - (n.y * (p.y - t[0].y) + n.z * (p.z - t[0].z)) / n.x;
  return x > p.x;
}

bool MeshSolid::contains(const Vec3& p) const {
  if (p.x < lo_.x || p.x > hi_.x || p.y < lo_.y || p.y > hi_.y || p.z < lo_.z || p.z > hi_.z) return false;
  const std::size_t c = static_cast<std::size_t>(column_y(p.y)) * nz_ + column_z(p.z);
  bool inside = false;
  for (std::uint32_t k = col_start_[c]; k < col_start_[c + 1]; ++k)
    if (ray_crosses(tri_[col_tri_[k]], p)) inside = !inside;
  return inside;
}

std::uint32_t MeshSolid::next_query() const {
  if (++query_ == 0) {  // stamp wrap-around: start afresh
    std::fill(stamp_.begin(), stamp_.end(), 0);
    query_ = 1;
  }
  return query_;
}

// Passes f the squared distance (m^2) from p to each triangle of cell (i, j, k) that this query has
// not tested yet; stops and returns false as soon as f returns false.
template <class F>
bool MeshSolid::each_new_distance2(const Vec3& p, int i, int j, int k, F&& f) const {
  return each_new_closest(p, i, j, k, [&](const Vec3& q) { return f(norm2(q - p)); });
}

// Passes f the closest point (m) to p of each triangle of cell (i, j, k) that this query has not
// tested yet; stops and returns false as soon as f returns false.
template <class F>
bool MeshSolid::each_new_closest(const Vec3& p, int i, int j, int k, F&& f) const {
  const std::size_t c = (static_cast<std::size_t>(i) * n_[1] + j) * n_[2] + k;
  for (std::uint32_t m = cell_start_[c]; m < cell_start_[c + 1]; ++m) {
    const std::uint32_t t = cell_tri_[m];
    if (stamp_[t] == query_) continue;
    stamp_[t] = query_;
    const auto& tr = tri_[t];
    if (!f(closest_point_on_triangle(p, tr[0], tr[1], tr[2]).point)) return false;
  }
  return true;
}

bool MeshSolid::clear_of_surface(const Vec3& p, double d) const {
  next_query();
  std::array<int, 3> c0{}, c1{};
  for (int a = 0; a < 3; ++a) {
    if (p[a] + d < lo_[a] || p[a] - d > hi_[a]) return true;  // the sphere misses the bounding box
    c0[a] = cell(p[a] - d, a);
    c1[a] = cell(p[a] + d, a);
  }
  const double d2 = d * d;
  for (int i = c0[0]; i <= c1[0]; ++i)
    for (int j = c0[1]; j <= c1[1]; ++j)
      for (int k = c0[2]; k <= c1[2]; ++k) {
        if (!each_new_distance2(p, i, j, k, [&](double e2) { return e2 >= d2; })) return false;
      }
  return true;
}

double MeshSolid::distance_to_surface(const Vec3& p) const { return std::sqrt(norm2(closest_surface_point(p) - p)); }

Vec3 MeshSolid::closest_surface_point(const Vec3& p) const {
  next_query();
  const std::array<int, 3> c{cell(p.x, 0), cell(p.y, 1), cell(p.z, 2)};
  int k_max = 0;
  for (int a = 0; a < 3; ++a) k_max = std::max({k_max, c[a], n_[a] - 1 - c[a]});
  double best2 = std::numeric_limits<double>::infinity();  // m^2
  Vec3 best = tri_.empty() ? p : tri_.front()[0];          // m
  const auto visit = [&](int i, int j, int l) {
    each_new_closest(p, i, j, l, [&](const Vec3& q) {
      if (const double e2 = norm2(q - p); e2 < best2) {
        best2 = e2;
        best = q;
      }
      return true;
    });
  };
  for (int k = 0; k <= k_max; ++k) {
    // Shell k: the cells whose largest index offset from c is k. A cell outside shells 0..k is
    // at least k cell sizes from p (p lies in, or beyond, its clamped cell).
    const int i0 = std::max(c[0] - k, 0), i1 = std::min(c[0] + k, n_[0] - 1);
    const int j0 = std::max(c[1] - k, 0), j1 = std::min(c[1] + k, n_[1] - 1);
    const int l0 = std::max(c[2] - k, 0), l1 = std::min(c[2] + k, n_[2] - 1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        if (std::abs(i - c[0]) == k || std::abs(j - c[1]) == k) {
          for (int l = l0; l <= l1; ++l) visit(i, j, l);
        } else {
          if (c[2] - k >= 0) visit(i, j, c[2] - k);
          if (k > 0 && c[2] + k < n_[2]) visit(i, j, c[2] + k);
        }
      }
    const double reach = k * h_;
    if (best2 <= reach * reach) break;
  }
  return best;
}

}  // namespace mpdem
