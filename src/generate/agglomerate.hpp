#pragma once
// A bonded agglomerate (`mpdem agglomerate`, docs/tools.md): a dense random packing of spheres in
// a sphere or a closed surface's solid (generate/dense_packing.hpp), bonded by the gap rule
// (generate/bond_pairs.hpp). How many particles and how large the container are tied by the
// solid fraction: give one, the other follows.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "model/radius_distribution.hpp"

namespace mpdem {

struct AgglomerateSpec {
  RadiusDistribution radius;
  std::size_t count = 0;          // particles; 0: as many as fill the container to `fraction`
  double fraction = 0.55;         // -, solid fraction: sum of sphere volumes / container volume
  std::filesystem::path surface;  // container: this closed surface's solid (.stl or barrier .csv); empty: a sphere
  double scale = 0.0;             // -, the surface's coordinates times this (about the origin); 0: set by count
  Vec3 centre{};                  // m, the sphere's centre
  double sphere_radius = 0.0;     // m, the sphere's radius; 0: set by count
  double tolerance = 1e-3;        // -, largest overlap accepted, over the smaller radius of the pair
  double gap = -1.0;              // m, bonds between surface gaps below this; < 0: 1 % of the mean radius
  std::uint64_t seed = 1;
  std::size_t max_sweeps = 20000;
  bool largest_cluster_only = false;         // drop the particles outside the largest bonded cluster
  std::string origin = "mpdem agglomerate";  // named by error messages
};

struct Agglomerate {
  std::vector<Vec3> x;                            // m, centres, shape [n]
  std::vector<double> radius;                     // m, shape [n]
  std::vector<std::array<std::size_t, 2>> bonds;  // indices (i < j), sorted, shape [bonds]
  double container_volume = 0.0;                  // m^3
  double sphere_radius = 0.0;                     // m, the sphere used (0 for a surface)
  double scale = 0.0;                             // -, the surface's scale used (0 for a sphere)
  double fraction = 0.0;                          // -, solid fraction the packing reached
  double kept_fraction = 0.0;                     // -, the same of the particles kept (largest_cluster_only)
  double gap = 0.0;                               // m, the bond gap used
  double largest_overlap = 0.0;                   // -, over the smaller radius of the pair
  double largest_protrusion = 0.0;                // -, out of the container, over the radius
  std::size_t sweeps = 0;                         // overlap-removal sweeps
  std::size_t unbonded = 0;                       // particles without a bond
  std::size_t largest_cluster = 0;                // particles in the largest bonded cluster
  std::size_t dropped = 0;                        // particles dropped by largest_cluster_only
};

// Deterministic for a given spec (seed included). Throws InputError (spec.origin, 0, the option:
// "--fraction", "--sphere", ...) for an impossible request or a packing that does not reach the
// tolerance within max_sweeps.
Agglomerate make_agglomerate(const AgglomerateSpec& spec);

// Particle CSV (docs/scene.md "Particle CSV"): id, x, y, z, radius [, material] [, density]
// (density in kg/m^3; <= 0: no column), ids 0 .. n-1, after a first line "# comment"; and the
// bond CSV: the header id_i,id_j, then one row per bond.
void write_agglomerate_particles(const std::filesystem::path& file, const Agglomerate& a, const std::string& material,
                                 double density, const std::string& comment);
void write_bond_csv(const std::filesystem::path& file, const std::vector<std::array<std::size_t, 2>>& bonds);

}  // namespace mpdem
