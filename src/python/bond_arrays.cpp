#include "python/bond_arrays.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "output/bond_cells.hpp"
#include "parallel/periodic_images.hpp"
#include "python/numpy_layout.hpp"

namespace mpdem::python {

namespace {
// A numpy copy of values (n entries of T: (n,) or (n, 3)).
template <class T>
py::array numpy(const std::vector<T>& v) {
  using S = typename Layout<T>::Scalar;
  py::array_t<S> out(shape_of<T>(v.size()));
  if (!v.empty()) std::memcpy(out.mutable_data(), v.data(), v.size() * sizeof(T));
  return out;
}
}  // namespace

py::object bond_arrays(Simulation& sim) {
  const Bonds* bonds = sim.interactions().bonds();
  if (bonds == nullptr) return py::none();
  const BondCells c = bond_cells(bonds->records(), sim.particles(), PeriodicImages(sim.model().params.domain).period());
  py::array_t<bool> intact(static_cast<py::ssize_t>(c.size()));
  std::transform(c.intact.begin(), c.intact.end(), intact.mutable_data(), [](std::uint8_t k) { return k != 0; });
  py::dict d;
  d["id_i"] = numpy(c.id_i);
  d["id_j"] = numpy(c.id_j);
  d["intact"] = intact;
  d["normal_force"] = numpy(c.normal_force);
  d["shear_force"] = numpy(c.shear_force);
  d["twisting_moment"] = numpy(c.twisting_moment);
  d["bending_moment"] = numpy(c.bending_moment);
  d["sigma"] = numpy(c.sigma_max);
  d["tau"] = numpy(c.tau_max);
  d["length"] = numpy(c.length);
  return d;
}

py::object new_bond_breaks(Simulation& sim) {
  if (sim.interactions().bonds() == nullptr) return py::none();
  const std::vector<BondBreak> k = sim.take_bond_breaks();
  std::vector<double> time, sigma, tau;
  std::vector<std::int64_t> id_i, id_j;
  py::list mode;
  for (const BondBreak& b : k) {
    time.push_back(b.time);
    id_i.push_back(b.id_i);
    id_j.push_back(b.id_j);
    mode.append(b.mode == BondBreakMode::tension ? "tension" : "shear");
    sigma.push_back(b.sigma);
    tau.push_back(b.tau);
  }
  py::dict d;
  d["time"] = numpy(time);
  d["id_i"] = numpy(id_i);
  d["id_j"] = numpy(id_j);
  d["mode"] = py::module_::import("numpy").attr("array")(mode, py::arg("dtype") = "U7");
  d["sigma"] = numpy(sigma);
  d["tau"] = numpy(tau);
  return d;
}

}  // namespace mpdem::python
