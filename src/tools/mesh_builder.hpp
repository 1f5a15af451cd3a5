#pragma once
// Mesh builder: barrier meshes of common apparatus in a canonical position (then placed with
// transform_mesh). Normal convention - the normals point INTO the region where particles live:
//   rectangle, plates, chute floor: +z (particles above);  chute side walls: towards the chute's
//   centre line;  box, cylinder, funnel: towards the inside (particles inside).
// `flip()` turns a mesh inside out (e.g. particles flowing around a cylindrical pillar).
#include "core/vec3.hpp"
#include "geometry/mesh_transform.hpp"
#include "geometry/triangle_mesh.hpp"

namespace mpdem {

// lx x ly rectangle in z = 0 centred at the origin, split into nx x ny cells of two triangles.
TriangleMesh make_rectangle(double lx, double ly, int nx, int ny);
// Box [-lx/2, lx/2] x [-ly/2, ly/2] x [0, lz]: floor and four walls, plus the lid when `closed`
// (then watertight). Two triangles per face.
TriangleMesh make_box(double lx, double ly, double lz, bool closed);
// Cylinder of `radius` about the z axis from z = 0 to `height`, `segments` flat facets around
// (vertices on the circle); with `closed`, fan caps at both ends make it watertight.
TriangleMesh make_cylinder(double radius, double height, int segments, bool closed);
// Funnel (hopper): a cone from the outlet circle (outlet_radius, z = 0) to the top circle
// (top_radius, z = height), with an optional cylindrical wall of `wall_height` above it. The
// outlet stays open; the vertices of both circles lie on the circles.
TriangleMesh make_funnel(double top_radius, double outlet_radius, double height, double wall_height, int segments);

// Chute (thesis case study 1, the Hutter apparatus): an inclined plane falling in +x at
// `angle_deg`, joined tangentially by a circular arc of `transition_radius` to a horizontal
// run-out in z = 0 that starts at x = 0 and ends at x = runout_length. The incline is
// `incline_length` long along its slope; the chute spans y in [-width/2, width/2]. With
// wall_height > 0, vertical side walls follow the profile up to wall_height above it.
struct ChuteSpec {
  double incline_length = 1.0;     // m
  double angle_deg = 40.0;         // deg, incline angle to the horizontal
  double transition_radius = 0.2;  // m, radius of the arc (0 = sharp kink)
  double runout_length = 0.5;      // m
  double width = 0.1;              // m
  int arc_segments = 16;           // facets along the arc
  double wall_height = 0.0;        // m, side walls (0 = none)
};
TriangleMesh make_chute(const ChuteSpec& spec);

// lx x ly plate in z = 0 centred at the origin with a centred hx x hy rectangular hole; the hole's
// edges lie exactly at x = +-hx/2, y = +-hy/2.
TriangleMesh make_plate_with_rect_hole(double lx, double ly, double hx, double hy);
// lx x ly plate with a centred circular hole of radius r: a `segments`-gon whose vertices lie on
// the circle (so the hole is the inscribed polygon; its narrowest width is 2 r cos(pi/segments)).
TriangleMesh make_plate_with_round_hole(double lx, double ly, double r, int segments);


}  // namespace mpdem
