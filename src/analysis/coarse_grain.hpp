#pragma once
// Coarse graining (Goldhirsch 2010; Weinhart et al., Granular Matter 2012 "From discrete
// particles to continuum fields near a boundary", and 2013; MercuryCG): continuum fields
// (density, momentum, stress, ...) from one snapshot of particles and contacts, evaluated at the
// points of a CgGrid, and their time average (CgAverage). Pure computation, no I/O.
//
// Conventions:
//  - Stress is compression positive: a pair pressed together (force on i along +branch) gives a
//    positive normal stress, and so does the kinetic stress. sigma[3a+b] = Σ f_a b_b ∫phi: row =
//    force component, column = branch component. With it the static momentum balance reads
//    ∂_b sigma_ab = rho g_a + t_a (t: boundary_force_density below).
//  - An averaged axis is integrated out: the kernel is not applied along it and the sums are
//    divided by the extent length max - min. Every particle and contact counts whatever its
//    position along an averaged axis, so the caller sets the extent to the whole domain (or the
//    periodic cell) along it; then the field is the average over that axis.
//  - Points are ordered x fastest, then y, then z (VTK ImageData order), over resolved axes only.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "analysis/cg_kernel.hpp"
#include "core/vec3.hpp"

namespace mpdem {

struct CgGrid {
  Vec3 min, max;                                   // m, resolved range or averaging extent per axis; min < max
  std::array<int, 3> cells{1, 1, 1};               // -, points along each resolved axis (>= 1; unused if averaged)
  std::array<bool, 3> resolved{true, true, true};  // false: the axis is averaged over [min, max]
};

// Throws std::invalid_argument unless every axis has finite min < max and resolved axes cells >= 1.
void cg_validate(const CgGrid& grid);
int cg_dims(const CgGrid& grid);                 // number of resolved axes, 0..3
std::size_t cg_point_count(const CgGrid& grid);  // product of cells over resolved axes
// Coordinates [m] of point `index`: resolved axes at cell centres min + (i + 0.5)(max - min)/cells,
// averaged axes at the centre of their extent.
Vec3 cg_point(const CgGrid& grid, std::size_t index);

struct CgParticle {
  Vec3 x;         // m, centre
  Vec3 v;         // m/s, velocity
  double mass;    // kg
  double volume;  // m^3
  int contacts;   // -, its contact count (coordination)
};

// One contact, listed once; the force on the other member of a pair is minus `force`.
struct CgContact {
  std::size_t i;  // index of the particle the force acts on
  Vec3 force;     // N, on i (normal + tangential)
  Vec3 branch;    // m, x_i - x_j for a pair (given, not recomputed: periodic images), x_i - contact point at a barrier
  bool boundary;  // true: particle-barrier contact (the barrier is not a particle)
};

// Fields at the grid points; every vector has one entry per point (tensors row-major, 9 entries).
struct CgFields {
  std::vector<double> density;                        // kg/m^3, rho = Σ m phi
  std::vector<double> solid_fraction;                 // -, nu = Σ V phi
  std::vector<double> number_density;                 // 1/m^3, n = Σ phi
  std::vector<Vec3> momentum;                         // kg/(m^2 s), p = Σ m v phi (mass flux)
  std::vector<Vec3> velocity;                         // m/s, V = p / rho (0 where rho = 0)
  std::vector<Vec3> boundary_force_density;           // N/m^3, t = Σ_barrier contacts f phi(r - contact point)
  std::vector<std::array<double, 9>> kinetic_stress;  // Pa, Σ m (v - V(r)) ⊗ (v - V(r)) phi
  std::vector<std::array<double, 9>> contact_stress;  // Pa, Σ f ⊗ b ∫_0^1 phi(r - x_i + s b) ds
  std::vector<std::array<double, 9>> stress;          // Pa, kinetic + contact
  std::vector<double> temperature;                    // m^2/s^2, tr(kinetic) / (3 rho) (0 where rho = 0)
  std::vector<double> coordination;                   // -, Σ z phi / Σ phi (0 where Σ phi = 0)

  std::size_t size() const { return density.size(); }
};

// The fields of one snapshot (Weinhart et al. 2012). Each particle and contact visits only the
// points within the kernel's cutoff of it (of its branch segment for a contact). Throws
// std::invalid_argument for an invalid grid/width or a non-finite position or branch, and
// std::out_of_range for a contact index >= particles.size().
// period: m, the periodic cell's length along each periodic axis (0: not periodic). Along a
// periodic resolved axis particles and branches also act through their images one period either
// side, so points near a periodic face see the particles across it (the grid should lie within
// the cell; throws std::invalid_argument when a period is shorter than the kernel cutoff).
CgFields coarse_grain(const CgGrid& grid, CgKernel kernel, double width, std::span<const CgParticle> particles,
                      std::span<const CgContact> contacts, const Vec3& period = {});

// Time average of snapshots on one grid. Averages the primary sums (rho, nu, n, p, t, the contact
// stress, Σ z phi) and derives V = <p>/<rho>, Z = <Σ z phi>/<n>, T and the stress from them. The
// kinetic stress is the average of <Σ m v ⊗ v phi> - <p> ⊗ <p> / <rho>, computed stably as the mean
// of the snapshots' kinetic stresses plus the rho-weighted spread of their velocities about
// <p>/<rho> (weighted Welford update), so it includes the fluctuation of the mean flow.
class CgAverage {
 public:
  // Throws std::invalid_argument if the point count differs from the earlier samples'.
  void add(const CgFields& fields);
  CgFields mean() const;  // empty fields when no sample was added
  std::size_t samples() const { return samples_; }
  void clear();
  // Checkpoints: visits the sample count and every running sum (f(std::size_t&) and
  // f(std::vector<T>&)), in a fixed order, so a caller can write them and read them back.
  template <class F>
  void visit_state(F&& f) {
    visit(*this, f);
  }
  template <class F>
  void visit_state(F&& f) const {  // f(const std::size_t&), f(const std::vector<T>&)
    visit(*this, f);
  }

 private:
  std::size_t samples_ = 0;
  CgFields sum_;                               // sums over samples of the primary fields
  std::vector<double> coordination_sum_;       // 1/m^3, Σ_samples Σ z phi
  std::vector<std::array<double, 9>> spread_;  // Pa, Σ_samples rho_s (V_s - <V>) ⊗ (V_s - <V>)

  template <class Self, class F>
  static void visit(Self& a, F& f) {
    f(a.samples_);
    f(a.sum_.density), f(a.sum_.solid_fraction), f(a.sum_.number_density), f(a.sum_.momentum), f(a.sum_.velocity);
    f(a.sum_.boundary_force_density), f(a.sum_.kinetic_stress), f(a.sum_.contact_stress), f(a.sum_.stress);
    f(a.sum_.temperature), f(a.sum_.coordination), f(a.coordination_sum_), f(a.spread_);
  }
};

}  // namespace mpdem
