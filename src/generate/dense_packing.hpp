#pragma once
// Dense random packing of spheres in a container by growth and overlap removal: centres drawn at
// random with the radii shrunk to a loose solid fraction, then sweeps that push every overlapping
// pair apart along its line of centres and put every sphere back inside the container
// (Gauss-Seidel projections), the radii growing back to full size while the overlaps stay small,
// until the largest overlap is below a tolerance. Deterministic for a seed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "generate/packing_container.hpp"

namespace mpdem {

struct PackingOptions {
  double tolerance = 1e-3;         // -, largest overlap accepted, over the smaller radius of the pair
  std::size_t max_sweeps = 20000;  // sweeps before giving up
  std::uint64_t seed = 1;          // random centres
};

struct DensePacking {
  std::vector<Vec3> x;              // m, centres, shape [n] (the order of the radii)
  double largest_overlap = 0.0;     // -, largest (r_i + r_j - |x_j - x_i|) / min(r_i, r_j), 0 without overlap
  double largest_protrusion = 0.0;  // -, largest distance a sphere sticks out of the container, over its radius
  std::size_t sweeps = 0;           // sweeps made
  bool converged = false;           // both below the tolerance
};

// radii: m, shape [n], all > 0, each fitting the container. Stops at convergence or after
// max_sweeps (converged false, with what it reached).
DensePacking pack_dense(const std::vector<double>& radii, const PackingContainer& container, const PackingOptions& o);

}  // namespace mpdem
