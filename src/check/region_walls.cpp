// Generator regions crossed by barrier triangles (check/region_walls.hpp) and their report
// (check/scene_checks.hpp).
#include "check/region_walls.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "check/scene_checks.hpp"
#include "check/source_lookup.hpp"

namespace mpdem {

namespace {

using Polygon = std::vector<Vec3>;

// Keeps the part of a convex polygon where dot(n, p) >= d (Sutherland-Hodgman, one plane).
void clip(Polygon& poly, const Vec3& n, double d) {
  Polygon kept;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec3& a = poly[k];
    const Vec3& b = poly[(k + 1) % poly.size()];
    const double da = dot(n, a) - d, db = dot(n, b) - d;
    if (da >= 0.0) kept.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) kept.push_back(a + (b - a) * (da / (da - db)));
  }
  poly = std::move(kept);
}

void clip_to_box(Polygon& poly, const Vec3& lo, const Vec3& hi) {
  for (int a = 0; a < 3 && !poly.empty(); ++a) {
    Vec3 n{};
    (a == 0 ? n.x : (a == 1 ? n.y : n.z)) = 1.0;
    clip(poly, n, lo[a]);
    if (!poly.empty()) clip(poly, -n, -hi[a]);
  }
}

double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Distance from the origin to a convex polygon of the plane (0 inside).
double distance_to_origin(const std::vector<std::array<double, 2>>& q) {
  double best = std::hypot(q[0][0], q[0][1]);
  bool pos = true, neg = true;
  for (std::size_t k = 0; k < q.size(); ++k) {
    const auto& a = q[k];
    const auto& b = q[(k + 1) % q.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double c = cross2(ex, ey, -a[0], -a[1]);
    pos = pos && c > 0.0;
    neg = neg && c < 0.0;
    const double len2 = ex * ex + ey * ey;
    const double t = len2 > 0.0 ? std::clamp(-(a[0] * ex + a[1] * ey) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(a[0] + t * ex, a[1] + t * ey));
  }
  return (pos || neg) && q.size() >= 3 ? 0.0 : best;
}

std::string vec_text(const Vec3& v) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", v.x, v.y, v.z); }

}  // namespace

RegionProbe::RegionProbe(const GenerateSpec& spec) : spec_(spec.region) {
  const Region region(spec.region, spec.origin, spec.line);
  lo_ = region.lo();
  hi_ = region.hi();
  if (spec_.shape == RegionShape::Cylinder) {
    height_ = norm(spec_.axis);
    w_ = spec_.axis / height_;
    const Vec3 helper = std::abs(w_.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    u_ = cross(w_, helper);
    u_ = u_ / norm(u_);
    v_ = cross(w_, u_);
  }
  if (spec_.shape == RegionShape::Mesh) mesh_ = std::make_unique<Region>(region);
  double scale = norm(hi_ - lo_);
  for (int a = 0; a < 3; ++a) scale = std::max({scale, std::abs(lo_[a]), std::abs(hi_[a])});
  // A wall placed on the region's boundary differs from it by rounding only.
  tolerance_ = 1e-9 * scale;
}

bool RegionProbe::crossed_by(const std::array<Vec3, 3>& t, double depth) const {
  const double s = depth + tolerance_;
  Polygon poly(t.begin(), t.end());
  switch (spec_.shape) {
    case RegionShape::Box: clip_to_box(poly, lo_ + Vec3{s, s, s}, hi_ - Vec3{s, s, s}); return !poly.empty();
    case RegionShape::Cylinder: {
      if (!(spec_.radius > s)) return false;
      // Between the end discs, then the distance from the axis in the plane normal to it.
      clip(poly, w_, dot(w_, spec_.base) + s);
      if (!poly.empty()) clip(poly, -w_, -(dot(w_, spec_.base) + height_ - s));
      if (poly.empty()) return false;
      std::vector<std::array<double, 2>> q;
      for (const Vec3& p : poly) q.push_back({dot(u_, p - spec_.base), dot(v_, p - spec_.base)});
      return distance_to_origin(q) < spec_.radius - s;
    }
    case RegionShape::Mesh: {
      clip_to_box(poly, lo_ + Vec3{s, s, s}, hi_ - Vec3{s, s, s});
      if (poly.empty()) return false;
      const double h = norm(hi_ - lo_) / 32.0;
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) {  // fan of the clipped polygon
        const Vec3 a = poly[0], ab = poly[k] - a, ac = poly[k + 1] - a;
        const double longest = std::max({norm(ab), norm(ac), norm(ac - ab)});
        const int n = static_cast<int>(std::clamp(std::ceil(longest / h), 1.0, 64.0));
        for (int i = 0; i <= n; ++i)
          for (int j = 0; i + j <= n; ++j)
            if (mesh_->holds(a + ab * (double(i) / n) + ac * (double(j) / n), s)) return true;
      }
      return false;
    }
  }
  return false;
}

std::string RegionProbe::description() const {
  switch (spec_.shape) {
    case RegionShape::Box: return "box from " + vec_text(spec_.min) + " to " + vec_text(spec_.max);
    case RegionShape::Cylinder:
      return fmt::format("cylinder with base {}, axis {}, radius {:.6g}", vec_text(spec_.base), vec_text(spec_.axis),
                         spec_.radius);
    case RegionShape::Mesh: return "mesh '" + spec_.mesh.filename().string() + "'";
  }
  return "";
}

void check_region_walls(const Scene& scene, SceneProblems& out) {
  const Barriers& b = scene.barriers;
  if (b.size() == 0) return;
  for (std::size_t s = 0; s < scene.particle_sources.size(); ++s) {
    const ParticleSource& src = scene.particle_sources[s];
    if (!src.generate) continue;
    const RegionProbe region(*src.generate);
    // Generated centres keep r + gap from the boundary: a wall no deeper than gap - t_b/2 clears them.
    std::map<int, std::vector<std::size_t>> crossing;  // barrier source -> elements, ascending
    for (std::size_t e = 0; e < b.size(); ++e) {
      const double depth = std::max(0.0, src.generate->gap - 0.5 * b.thickness[e]);
      if (region.crossed_by({b.vertex(e, 0), b.vertex(e, 1), b.vertex(e, 2)}, depth))
        crossing[barrier_source_of(scene, e)].push_back(e);
    }
    const SourceLocation where = particle_source_location(scene, static_cast<int>(s));
    for (const auto& [bs, elems] : crossing) {
      std::string ids;
      for (std::size_t k = 0; k < elems.size() && k < kListedIds; ++k)
        ids += fmt::format("{}{}", k ? ", " : "", b.id[elems[k]]);
      if (elems.size() > kListedIds) ids += fmt::format(" and {} more", elems.size() - kListedIds);
      SceneProblem pr;
      pr.severity = Severity::Error;
      pr.file = where.file;
      pr.line = where.line;
      pr.key = "particles.generate.region";
      pr.message = fmt::format(
          "the generate region ({}) of {} is crossed by {} triangle{} of the barriers of {} (element id{} {}): the "
          "generator places particles without regard to barriers, so some would overlap the wall or start on its "
          "far side. Move the region clear of the barrier (a wall on the region's boundary is fine).",
          region.description(), where.name, elems.size(), elems.size() == 1 ? "" : "s",
          barrier_source_location(scene, bs).name, elems.size() == 1 ? "" : "s", ids);
      out.push_back(std::move(pr));
    }
  }
}

}  // namespace mpdem
