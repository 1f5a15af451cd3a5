// `mpdem mesh SHAPE`: barrier meshes -> barrier CSV or STL (docs/tools.md "mpdem mesh").
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/tool_commands.hpp"
#include "core/input_error.hpp"
#include "tools/mesh_builder.hpp"
#include "tools/mesh_output.hpp"

namespace mpdem::cli {

namespace {

struct MeshArgs {
  std::filesystem::path output;
  std::string format;  // csv, stl, stl-ascii ("" = by extension)
  std::string group;
  std::int64_t first_id = 0;  // id of the first triangle (CSV)
  bool flip = false;
  std::vector<double> rotate_deg{0, 0, 0}, translate{0, 0, 0};
  // shape parameters (m, deg)
  std::vector<double> size;
  std::vector<int> divisions{1, 1};
  bool closed = false;
  double radius = 0, height = 0, top_radius = 0, outlet_radius = 0, wall_height = 0;
  int segments = 32;
  ChuteSpec chute;
  std::vector<double> hole_size;
  double hole_radius = 0;
};

MeshFileFormat file_format(const MeshArgs& a) {
  std::string f = a.format;
  if (f.empty()) f = a.output.extension() == ".csv" ? "csv" : a.output.extension() == ".stl" ? "stl" : "";
  if (f == "csv") return MeshFileFormat::Csv;
  if (f == "stl" || f == "stl-binary") return MeshFileFormat::StlBinary;
  if (f == "stl-ascii") return MeshFileFormat::StlAscii;
  throw InputError("mpdem mesh", 0, "--format",
                   "expected csv, stl (binary) or stl-ascii, or an output name ending in .csv or .stl");
}

int write(const MeshArgs& a, const std::string& shape, const std::function<TriangleMesh()>& build) {
  const MeshFileFormat format = file_format(a);
  TriangleMesh m;
  try {
    m = build();
  } catch (const std::invalid_argument& e) {
    throw InputError("mpdem mesh " + shape, 0, "", e.what());
  }
  if (a.flip) m.flip();
  transform_mesh(m, 1.0, {a.rotate_deg[0], a.rotate_deg[1], a.rotate_deg[2]},
                 {a.translate[0], a.translate[1], a.translate[2]});
  write_mesh(a.output, m, format, a.group, a.first_id);
  fmt::print("{}: {} triangles, area {:.6g} m^2 -> {}\n", shape, m.size(), total_area(m), a.output.string());
  return 0;
}

// Options every shape takes, and the callback that queues the build.
CLI::App* shape(CLI::App& mesh, const std::string& name, const std::string& help, const std::shared_ptr<MeshArgs>& a,
                ToolAction& action, const std::function<TriangleMesh()>& build) {
  auto* c = mesh.add_subcommand(name, help);
  c->add_option("-o,--output", a->output, "file to write (.csv barrier CSV, .stl STL)")->required();
  c->add_option("--format", a->format, "csv, stl (binary) or stl-ascii (default: from the extension)");
  c->add_option("--group", a->group, "group column of the CSV / solid name of the STL");
  c->add_option("--first-id", a->first_id,
                "id of the first triangle in a CSV (default 0), to combine meshes in one scene");
  c->add_flag("--flip", a->flip, "reverse all normals");
  c->add_option("--rotate-deg", a->rotate_deg, "rotation about x, then y, then z (deg)")->expected(3);
  c->add_option("--translate", a->translate, "translation after the rotation (m)")->expected(3);
  c->callback([a, &action, name, build] { action = [a, name, build] { return write(*a, name, build); }; });
  return c;
}

}  // namespace

void add_mesh_command(CLI::App& app, ToolAction& action) {
  auto* mesh = app.add_subcommand("mesh", "barrier meshes (rect, box, cylinder, funnel, chute, plate) -> CSV/STL");
  mesh->require_subcommand(1);
  auto a = std::make_shared<MeshArgs>();
  MeshArgs& r = *a;

  auto* rect = shape(*mesh, "rect", "rectangle in z = 0 centred at the origin, normal +z", a, action,
                     [a] { return make_rectangle(a->size[0], a->size[1], a->divisions[0], a->divisions[1]); });
  rect->add_option("--size", r.size, "lx ly (m)")->expected(2)->required();
  rect->add_option("--divisions", r.divisions, "nx ny cells (default 1 1)")->expected(2);

  auto* box = shape(*mesh, "box", "box [-lx/2, lx/2] x [-ly/2, ly/2] x [0, lz] open at the top, normals inward", a,
                    action, [a] { return make_box(a->size[0], a->size[1], a->size[2], a->closed); });
  box->add_option("--size", r.size, "lx ly lz (m)")->expected(3)->required();
  box->add_flag("--closed", r.closed, "add the lid (watertight)");

  auto* cyl = shape(*mesh, "cylinder", "cylinder about z from z = 0 to height, normals inward", a, action,
                    [a] { return make_cylinder(a->radius, a->height, a->segments, a->closed); });
  cyl->add_option("--radius", r.radius, "radius (m)")->required();
  cyl->add_option("--height", r.height, "height (m)")->required();
  cyl->add_option("--segments", r.segments, "facets around (default 32)");
  cyl->add_flag("--closed", r.closed, "add end caps (watertight)");

  auto* fun = shape(
      *mesh, "funnel", "hopper: cone from the outlet (z = 0) to the top, optional wall above", a, action,
      [a] { return make_funnel(a->top_radius, a->outlet_radius, a->height, a->wall_height, a->segments); });
  fun->add_option("--top-radius", r.top_radius, "radius at the top of the cone (m)")->required();
  fun->add_option("--outlet-radius", r.outlet_radius, "outlet radius (m)")->required();
  fun->add_option("--height", r.height, "cone height (m)")->required();
  fun->add_option("--wall-height", r.wall_height, "cylindrical wall above the cone (m, default 0)");
  fun->add_option("--segments", r.segments, "facets around (default 32)");

  auto* ch = shape(*mesh, "chute", "incline + circular transition + horizontal run-out (Hutter apparatus)", a, action,
                   [a] { return make_chute(a->chute); });
  ch->add_option("--length", r.chute.incline_length, "incline length along the slope (m)")->required();
  ch->add_option("--angle", r.chute.angle_deg, "incline angle (deg, default 40)");
  ch->add_option("--transition-radius", r.chute.transition_radius, "arc radius (m, default 0.2; 0 = kink)");
  ch->add_option("--runout", r.chute.runout_length, "run-out length (m, default 0.5)");
  ch->add_option("--width", r.chute.width, "width (m, default 0.1)");
  ch->add_option("--arc-segments", r.chute.arc_segments, "facets along the arc (default 16)");
  ch->add_option("--wall-height", r.chute.wall_height, "side walls (m, default 0 = none)");

  auto* pl = shape(*mesh, "plate", "plate in z = 0 with a centred rectangular or circular hole, normal +z", a, action,
                   [a]() -> TriangleMesh {
                     if (!a->hole_size.empty())
                       return make_plate_with_rect_hole(a->size[0], a->size[1], a->hole_size[0], a->hole_size[1]);
                     if (a->hole_radius > 0)
                       return make_plate_with_round_hole(a->size[0], a->size[1], a->hole_radius, a->segments);
                     throw std::invalid_argument("give --hole-size HX HY or --hole-radius R");
                   });
  pl->add_option("--size", r.size, "lx ly (m)")->expected(2)->required();
  auto* hs = pl->add_option("--hole-size", r.hole_size, "rectangular hole hx hy (m)")->expected(2);
  auto* hr = pl->add_option("--hole-radius", r.hole_radius, "circular hole radius (m)");
  hs->excludes(hr);
  pl->add_option("--segments", r.segments, "circular hole: facets around (default 32)");
}

}  // namespace mpdem::cli
