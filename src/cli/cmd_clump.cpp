// `mpdem clump STL -n N -o template.csv`: a clump template filling a closed surface, and its shape
// error (docs/tools.md "mpdem clump").
#include <filesystem>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <fmt/format.h>

#include "cli/tool_commands.hpp"
#include "core/atomic_file.hpp"
#include "core/input_error.hpp"
#include "generate/region.hpp"
#include "geometry/mesh_mass.hpp"
#include "physics/clump_mass.hpp"
#include "tools/clump_fill.hpp"
#include "tools/clump_report.hpp"

namespace mpdem::cli {

namespace {

struct ClumpArgs {
  std::filesystem::path surface;  // closed STL (or barrier CSV)
  std::filesystem::path output;   // template CSV
  int count = 0;                  // spheres
  int resolution = 31;            // grid points along the longest bounding-box edge (odd: one at each middle)
};

// At most 128^3 grid points: the time grows as K^3 to K^5 (docs/tools.md "mpdem clump").
constexpr int kMaxResolution = 128;

void write_template(const std::filesystem::path& file, const std::vector<ClumpMember>& members) {
  write_file_atomically(
      file,
      [&](std::ostream& out) {
        out << "x,y,z,radius\n";
        for (const ClumpMember& m : members) out << fmt::format("{},{},{},{}\n", m.x.x, m.x.y, m.x.z, m.r);
      },
      Durability::kill);
}

int clump(const ClumpArgs& a) {
  const std::string command = "mpdem clump";
  if (a.count < 1) throw InputError(command, 0, "-n", "expected a number of spheres of at least 1");
  if (a.resolution < 2 || a.resolution > kMaxResolution)
    throw InputError(command, 0, "--resolution", fmt::format("expected 2 to {} grid points", kMaxResolution));
  const std::string file = a.surface.string();
  TriangleMesh mesh;
  MeshMassProperties exact;
  ClumpFill fill;
  try {
    mesh = read_region_mesh(a.surface);  // InputError for a bad file
    if (mesh.size() == 0) throw std::invalid_argument("the surface has no triangles");
    if (const std::string p = closed_surface_problem(mesh); !p.empty())
      throw std::invalid_argument("the surface is " + p);
    exact = mesh_mass_properties(mesh);
    fill = fill_with_spheres(mesh, a.count, a.resolution);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, "", e.what());
  }
  const ClumpMassProperties tpl = clump_mass_properties(fill.members);
  write_template(a.output, fill.members);

  fmt::print("{}: {} triangles, closed{}\n", file, mesh.size(),
             exact.inward ? "; wound inward (normals into the solid): volume integrals taken with the sign flipped"
                          : "");
  fmt::print("{} sphere(s) from a grid of spacing {:.6g} m ({} sample points inside, {:.2f} % covered){} -> {}\n",
             fill.members.size(), fill.spacing, fill.samples, 100.0 * double(fill.covered) / double(fill.samples),
             fill.members.size() < static_cast<std::size_t>(a.count)
                 ? fmt::format("; every sample point covered before {} spheres: raise --resolution for more", a.count)
                 : "",
             a.output.string());
  fmt::print("\n{}", shape_error_table(exact, tpl));
  fmt::print("\nsolid: exact for the triangulated surface (divergence theorem). template: the union of the spheres\n"
             "(relative integration error {:.1e} in volume, {:.1e} in the moments). Centroid error: the distance\n"
             "between the centroids over V^(1/3). Moments about each centroid, ascending; times the density: kg m^2.\n",
             tpl.volume_error, tpl.inertia_error);
  return 0;
}

}  // namespace

void add_clump_command(CLI::App& app, ToolAction& action) {
  auto a = std::make_shared<ClumpArgs>();
  auto* c = app.add_subcommand("clump", "fill a closed STL surface with N overlapping spheres -> clump template CSV");
  c->add_option("surface", a->surface, "closed surface: .stl (ASCII or binary, in m) or a barrier .csv")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("-n,--count", a->count, "number of spheres")->required();
  c->add_option("-o,--output", a->output, "template CSV to write (columns x,y,z,radius; m, the STL's frame)")
      ->required();
  c->add_option("--resolution", a->resolution, "sample grid points along the longest bounding-box edge (default 31)");
  c->callback([a, &action] { action = [a] { return clump(*a); }; });
}

}  // namespace mpdem::cli
