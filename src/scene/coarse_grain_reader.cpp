#include "scene/coarse_grain_reader.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <string>
#include <string_view>

#include "analysis/cg_kernel.hpp"
#include "analysis/coarse_grain.hpp"
#include "core/input_error.hpp"
#include "model/derived_limits.hpp"

namespace mpdem {

namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

// A name becomes file names (cg_NAME.pvd, cg_NAME/cg_NAME_000001.vti, and their temporary
// names while written): room for the rest within a file system's 255 bytes per name.
constexpr std::size_t kMaxNameBytes = 200;
// Points of all entries together: each holds about 750 bytes at the peak of a sample (a
// snapshot's fields, the running sums of an average, the output's buffers), so that 1e7 points
// need about 7.5 GB.
constexpr double kMaxPoints = 1e7;
constexpr double kBytesPerPoint = 750.0;

void check_name(const TomlSection& s, const std::string& name) {
  if (name.empty() || name.find_first_of("/\\ ,\"") != std::string::npos)
    s.fail("name", "expected a non-empty name without spaces, commas, quotes or slashes (it names files)");
  if (name.size() > kMaxNameBytes)
    s.fail("name", "expected a name of at most 200 bytes (it names files, cg_NAME_000000.vti), got " +
                       std::to_string(name.size()) + " bytes");
  for (const char ch : name)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
      s.fail("name", "expected a name without control characters (it names files)");
}

// The point spacing along each resolved axis and the length of each averaged one (the sums are
// divided by it) must be usable; `keys[k]` is the key to blame along axis k.
void check_extents(const TomlSection& t, const CgGrid& g, const std::array<std::string_view, 3>& keys) {
  for (int k = 0; k < 3; ++k) {
    const auto a = static_cast<std::size_t>(k);
    const bool resolved = g.resolved[a];
    const double length = (g.max[k] - g.min[k]) / (resolved ? g.cells[a] : 1);  // m
    const std::string what = std::string(resolved ? "the point spacing (max - min) / cells" : "the averaged length") +
                             " along " + kAxes[k];
    if (const std::string p = usable_problem(length, what, "m"); !p.empty())
      t.fail(keys[a], p + "; expected a finite extent whose spacing is finite and > 0");
  }
}

// Points of the entry's grid (resolved axes only), as a double: the product cannot overflow.
double point_count(const CgGrid& grid) {
  double n = 1.0;
  for (std::size_t k = 0; k < 3; ++k)
    if (grid.resolved[k]) n *= grid.cells[k];
  return n;
}

void read_grid(const TomlSection& g, CoarseGrainSpec& out) {
  out.grid.min = g.require(g.vec3("min"), "min");
  out.grid.max = g.require(g.vec3("max"), "max");
  const auto cells = g.require(g.numbers("cells", 3, 3), "cells");
  for (int k = 0; k < 3; ++k) {
    const double c = cells[static_cast<std::size_t>(k)];
    if (!(c >= 1.0 && c <= 1e6) || c != static_cast<double>(static_cast<int>(c)))
      g.fail("cells", "expected three whole numbers from 1 to 10^6");
    out.grid.cells[static_cast<std::size_t>(k)] = static_cast<int>(c);
    if (!(out.grid.min[k] < out.grid.max[k])) g.fail("max", std::string("expected max > min along ") + kAxes[k]);
  }
  // Axes averaged over [min, max] instead of resolved (slabs: one axis, 2-D fields).
  if (const auto avg = g.strings("average_over", 0, 2)) {
    for (const std::string& a : *avg) {
      int k = 0;
      while (k < 3 && a != kAxes[k]) ++k;
      if (k == 3) g.fail("average_over", "expected axis names \"x\", \"y\" or \"z\", got \"" + a + "\"");
      out.grid.resolved[static_cast<std::size_t>(k)] = false;
      out.grid.cells[static_cast<std::size_t>(k)] = 1;
    }
  }
}

void read_profile(const TomlSection& p, const Model& model, CoarseGrainSpec& out) {
  out.profile = true;
  const std::string axis = p.require(p.string("axis"), "axis");
  out.axis = 0;
  while (out.axis < 3 && axis != kAxes[out.axis]) ++out.axis;
  if (out.axis == 3) p.fail("axis", "expected \"x\", \"y\" or \"z\", got \"" + axis + "\"");
  const double lo = p.require(p.number("min"), "min"), hi = p.require(p.number("max"), "max");
  if (!(lo < hi)) p.fail("max", "expected max > min");
  int bins = 0;
  p.get("bins", bins, 1, 1000000);
  if (bins == 0) p.fail("bins", "missing required key");
  // The two other axes are averaged over the domain (or the given extent).
  const DomainParams& d = model.params.domain;
  const auto emin = p.vec3("extent_min"), emax = p.vec3("extent_max");
  if ((!emin || !emax) && !d.bounded)
    p.fail(emin ? "extent_max" : "extent_min",
           "a profile averages over the other two axes: give extent_min and extent_max, or a [domain]");
  out.grid.min = emin ? *emin : d.min;
  out.grid.max = emax ? *emax : d.max;
  out.grid.min[out.axis] = lo;
  out.grid.max[out.axis] = hi;
  for (int k = 0; k < 3; ++k) {
    const bool along = k == out.axis;
    out.grid.resolved[static_cast<std::size_t>(k)] = along;
    out.grid.cells[static_cast<std::size_t>(k)] = along ? bins : 1;
    if (!along && !(out.grid.min[k] < out.grid.max[k]))
      p.fail("extent_max", std::string("expected extent_max > extent_min along ") + kAxes[k]);
  }
}

}  // namespace

void read_coarse_grain(const TomlSection& root, Model& model) {
  int unnamed = 0;
  double points = 0.0;  // of every entry read so far
  for (const TomlSection& s :
       root.tables("coarse_grain", {"name", "grid", "profile", "kernel", "width", "every", "average", "samples"})) {
    CoarseGrainSpec c;
    c.name = std::to_string(++unnamed);
    s.get("name", c.name);
    check_name(s, c.name);
    for (const CoarseGrainSpec& other : model.params.coarse_grain)
      if (other.name == c.name) s.fail("name", "another [[coarse_grain]] has the name \"" + c.name + "\"");
    const auto grid = s.table("grid", {"min", "max", "cells", "average_over"});
    const auto profile = s.table("profile", {"axis", "min", "max", "bins", "extent_min", "extent_max"});
    if (grid && profile) s.fail("profile", "give either grid or profile, not both");
    if (!grid && !profile) s.fail("grid", "missing required key (or profile)");
    if (grid) read_grid(*grid, c);
    else read_profile(*profile, model, c);
    if (grid) check_extents(*grid, c.grid, {"max", "max", "max"});
    else {
      std::array<std::string_view, 3> keys{"extent_max", "extent_max", "extent_max"};
      keys[static_cast<std::size_t>(c.axis)] = "max";
      check_extents(*profile, c.grid, keys);
    }
    points += point_count(c.grid);
    if (points > kMaxPoints)
      (grid ? *grid : *profile)
          .fail(grid ? "cells" : "bins",
                "the coarse-grained fields would have " + fmt::format("{:.3g}", points) + " points (" +
                    (model.params.coarse_grain.empty() ? std::string("this entry")
                                                       : std::string("all [[coarse_grain]] entries so far")) +
                    "), about " + fmt::format("{:.3g}", points * kBytesPerPoint * 1e-9) +
                    " GB of memory; expected at most 1e7 points (about 7.5 GB): use fewer cells or average over an "
                    "axis");
    if (const auto k = s.string("kernel")) {
      if (*k == "gaussian") c.kernel = CgKernel::gaussian;
      else if (*k == "lucy") c.kernel = CgKernel::lucy;
      else s.fail("kernel", "expected \"gaussian\" or \"lucy\", got \"" + *k + "\"");
    }
    c.width = s.require(s.number("width", kPositive), "width");
    // The kernel's normalisation divides by width^d (d resolved axes): finite and > 0 both ways.
    const int dims = cg_dims(c.grid);
    if (const double wd = std::pow(c.width, dims); !usable_positive(wd) || !usable_positive(1.0 / wd))
      s.fail("width", fmt::format("the kernel's normalisation 1 / width^{} over- or underflows (width^{} = {:g} m^{}); "
                                  "expected a width between about 1e-100 and 1e100 m",
                                  dims, dims, wd, dims));
    // Along a periodic resolved axis the kernel reaches through one image either side only.
    const DomainParams& d = model.params.domain;
    const double cutoff = cg_cutoff(c.kernel, c.width);  // m
    for (int k = 0; k < 3; ++k) {
      const double period = d.max[k] - d.min[k];
      if (d.periodic[static_cast<std::size_t>(k)] && c.grid.resolved[static_cast<std::size_t>(k)] && period < cutoff)
        s.fail("width", fmt::format("the kernel's cutoff {:.6g} m (width {:.6g} m) exceeds the period {:.6g} m along "
                                    "the periodic axis {}; use a smaller width or average over that axis",
                                    cutoff, c.width, period, kAxes[k]));
    }
    c.every = s.require(s.number("every", kPositive), "every");
    s.get("average", c.average, kNonNegative);
    if (c.average > c.every) s.fail("average", "expected a window no longer than every (the windows would overlap)");
    s.get("samples", c.samples, 1, 100000);
    model.params.coarse_grain.push_back(std::move(c));
  }
}

}  // namespace mpdem
