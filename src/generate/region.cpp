// Generator regions (docs/tools.md "Regions").
#include "generate/region.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "io/barrier_csv.hpp"
#include "core/input_error.hpp"
#include "io/stl_reader.hpp"
#include "core/value_range.hpp"
#include "model/derived_limits.hpp"

namespace mpdem {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::string box_size_problem(const Vec3& extent) {
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(extent[c]))
      return std::string("the region's extent along ") + "xyz"[c] + " overflows (" + number_text(extent[c]) +
             " m); expected a region of finite size";
  if (const std::string p = usable_problem(extent.x * extent.y * extent.z, "the region's volume", "m^3"); !p.empty())
    return p + "; expected a finite volume > 0";
  return "";
}

std::string cylinder_size_problem(const Vec3& axis, double radius, bool& axis_at_fault) {
  axis_at_fault = true;
  if (const std::string p = usable_problem(norm2(axis), "the squared axis length", "m^2"); !p.empty())
    return p + "; expected an axis whose length and its square are finite and > 0";
  axis_at_fault = false;
  if (const std::string p = usable_problem(radius * radius, "the squared radius", "m^2"); !p.empty())
    return p + "; expected a radius whose square is finite and > 0";
  const double volume = kPi * radius * radius * std::sqrt(norm2(axis));
  if (const std::string p = usable_problem(volume, "the cylinder's volume", "m^3"); !p.empty())
    return p + "; expected a finite volume > 0";
  return "";
}

TriangleMesh read_region_mesh(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".stl") return weld(read_stl(file).triangles);
  Barriers b;
  read_barrier_csv(file, BarrierSource{}, Model{}, b);
  std::vector<std::array<Vec3, 3>> tris;
  for (std::size_t e = 0; e < b.size(); ++e) tris.push_back({b.p0[e], b.p1[e], b.p2[e]});
  return weld(tris);
}

Region::Region(const RegionSpec& spec, const std::string& origin, std::size_t line) : spec_(spec) {
  const auto fail = [&](const std::string& key, const std::string& msg) { throw InputError(origin, line, key, msg); };
  switch (spec.shape) {
    case RegionShape::Box: {
      for (int a = 0; a < 3; ++a)
        if (!(spec.min[a] < spec.max[a])) fail("max", "expected max > min in every component of the box");
      if (const std::string p = box_size_problem(spec.max - spec.min); !p.empty()) fail("max", p);
      lo_ = spec.min;
      hi_ = spec.max;
      const Vec3 e = hi_ - lo_;
      volume_ = e.x * e.y * e.z;
      break;
    }
    case RegionShape::Cylinder: {
      height_ = norm(spec.axis);
      if (!(height_ > 0.0)) fail("axis", "expected a non-zero axis vector (base centre -> top centre)");
      if (!(spec.radius > 0.0)) fail("radius", "expected a cylinder radius > 0");
      bool axis_at_fault = false;
      if (const std::string p = cylinder_size_problem(spec.axis, spec.radius, axis_at_fault); !p.empty())
        fail(axis_at_fault ? "axis" : "radius", p);
      w_ = spec.axis / height_;
      // Any unit vector normal to the axis: cross with the coordinate axis least aligned to it.
      const Vec3 helper = std::abs(w_.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
      u_ = cross(w_, helper);
      u_ = u_ / norm(u_);
      v_ = cross(w_, u_);
      volume_ = kPi * spec.radius * spec.radius * height_;
      // Bounding box of the two end discs: half-extent R sqrt(1 - w_a^2) per axis.
      for (int a = 0; a < 3; ++a) {
        const double r = spec.radius * std::sqrt(std::max(0.0, 1.0 - w_[a] * w_[a]));
        const double e0 = spec.base[a], e1 = spec.base[a] + spec.axis[a];
        const double l = std::min(e0, e1) - r, h = std::max(e0, e1) + r;
        if (a == 0) {
          lo_.x = l;
          hi_.x = h;
        } else if (a == 1) {
          lo_.y = l;
          hi_.y = h;
        } else {
          lo_.z = l;
          hi_.z = h;
        }
      }
      break;
    }
    case RegionShape::Mesh: {
      TriangleMesh mesh;
      try {
        mesh = read_region_mesh(spec.mesh);
        solid_ = std::make_shared<const MeshSolid>(mesh);
      } catch (const std::invalid_argument& e) {
        throw InputError(spec.mesh.string(), 0, "", e.what());
      }
      volume_ = solid_->volume();
      lo_ = solid_->lo();
      hi_ = solid_->hi();
      break;
    }
  }
}

bool Region::has_room(double c) const {
  switch (spec_.shape) {
    case RegionShape::Box:
    case RegionShape::Mesh: return hi_.x - lo_.x > 2 * c && hi_.y - lo_.y > 2 * c && hi_.z - lo_.z > 2 * c;
    case RegionShape::Cylinder: return spec_.radius > c && height_ > 2 * c;
  }
  return false;
}

bool Region::sample(Rng& rng, double c, Vec3& out) const {
  switch (spec_.shape) {
    case RegionShape::Box:
      out = {rng.uniform(lo_.x + c, hi_.x - c), rng.uniform(lo_.y + c, hi_.y - c), rng.uniform(lo_.z + c, hi_.z - c)};
      return true;
    case RegionShape::Cylinder: {
      // Uniform in the disc of radius R - c by rejection from its square (78.5 % accepted).
      const double rc = spec_.radius - c;
      double a = 0.0, b = 0.0;
      do {
        a = rng.uniform(-rc, rc);
        b = rng.uniform(-rc, rc);
      } while (a * a + b * b > rc * rc);
      const double t = rng.uniform(c, height_ - c);
      out = spec_.base + u_ * a + v_ * b + w_ * t;
      return true;
    }
    case RegionShape::Mesh:
      out = {rng.uniform(lo_.x + c, hi_.x - c), rng.uniform(lo_.y + c, hi_.y - c), rng.uniform(lo_.z + c, hi_.z - c)};
      return solid_->contains(out) && solid_->clear_of_surface(out, c);
  }
  return false;
}

bool Region::holds(const Vec3& p, double c) const {
  switch (spec_.shape) {
    case RegionShape::Box:
      for (int a = 0; a < 3; ++a)
        if (p[a] - c < lo_[a] || p[a] + c > hi_[a]) return false;
      return true;
    case RegionShape::Cylinder: {
      const Vec3 d = p - spec_.base;
      const double t = dot(d, w_);
      const double a = dot(d, u_), b = dot(d, v_);
      return t >= c && t <= height_ - c && std::sqrt(a * a + b * b) <= spec_.radius - c;
    }
    case RegionShape::Mesh: return solid_->contains(p) && solid_->clear_of_surface(p, c);
  }
  return false;
}

}  // namespace mpdem
