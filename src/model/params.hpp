#pragma once
// Run parameters: the thesis's ten parameter classes (temperature, time integration, electric
// field, magnetic field, gravity, tangential contact coefficients, tolerances and convergence,
// near field, contact dissipation, analysis type) plus domain, neighbour search and output.
// Constant during a run. Every field states its SI unit; defaults here are the documented
// defaults of docs/scene.md.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/coarse_grain.hpp"
#include "core/vec3.hpp"
#include "model/bond_params.hpp"
#include "model/liquid_bridge.hpp"
#include "model/open_boundaries.hpp"

namespace mpdem {

enum class Integrator { Trapezoidal, Verlet };

struct TimeParams {
  double duration = 0.0;  // s, simulated time to run (required, > 0)
  // Velocity Verlet unless [time] integrator = "trapezoidal" (the thesis's rule).
  Integrator integrator = Integrator::Verlet;
  double phi = 0.5;             // -, trapezoidal weight in [0, 1] (0 explicit, 1 implicit)
  double dt = 0.0;              // s, (initial) time step (required, > 0)
  double dt_min = 0.0;          // s, adaptive lower bound (default dt / 1000)
  double dt_max = 0.0;          // s, adaptive upper bound (default dt)
  bool adaptive = false;        // adaptive time stepping (physics.md section 10)
  int desired_iterations = 10;  // K_D, iterations per step the adaptivity aims at
  double p = 2.0;               // convergence exponent of the fixed-point iteration
  int max_iterations = 50;      // cap on fixed-point iterations per step (fixed dt)
};

// Relative tolerances of the fixed-point iteration, one per field (physics.md section 9).
struct ToleranceParams {
  double position = 1e-8;          // TOL_r
  double velocity = 1e-8;          // TOL_v
  double rotation = 1e-8;          // TOL_alpha
  double angular_velocity = 1e-8;  // TOL_w
  double temperature = 1e-8;       // TOL_T
  // Absolute floors, RMS per particle: a field is converged when
  //   rms|y_K - y_(K-1)| <= TOL rms|y_K - y(t)| + floor,
  // so fields that hardly change over a step (a resting bed, a uniform temperature) converge at
  // once instead of chasing round-off (docs/integrators.md).
  double position_floor = 1e-12;         // m
  double velocity_floor = 1e-10;         // m/s
  double rotation_floor = 1e-12;         // rad
  double angular_velocity_floor = 1e-8;  // rad/s
  double temperature_floor = 1e-9;       // K
};

struct AnalysisParams {
  bool rotation = true;  // integrate angular velocity and orientation
  bool thermal = false;  // integrate temperature (physics.md section 8)
};

struct FieldParams {
  Vec3 gravity{0.0, 0.0, -9.81};  // m/s^2
  Vec3 electric{};                // V/m, uniform E
  Vec3 magnetic{};                // T, uniform B
  double drag = 0.0;              // N s/m, viscous drag -c v on every particle that is not fixed
};

// Empirical near-field law f = (a1 d^-b1 - a2 d^-b2) n for one material pair (46).
struct NearFieldPair {
  std::string material_a, material_b;
  double a1 = 0.0, b1 = 0.0, a2 = 0.0, b2 = 0.0;
};

struct NearFieldParams {
  bool empirical = false;            // empirical power law (46) on
  double a1 = 0.0;                   // N m^b1
  double b1 = 0.0;                   // -
  double a2 = 0.0;                   // N m^b2
  double b2 = 0.0;                   // -
  std::vector<NearFieldPair> pairs;  // per-material-pair overrides of a1, b1, a2, b2
  bool coulomb = false;              // Coulomb force between charges (44)
  double permittivity = 1.0;         // eps_r, relative permittivity of the medium
  double cutoff = 0.0;               // m, range of both laws (0 = near field off)
};

// The laws' own scene keys as given (docs/scene.md "Contact laws"), by name: the law's header
// (contact/laws/) states their units, ranges and defaults.
using LawKeyValues = std::map<std::string, double, std::less<>>;
// How the tangential spring follows a changing stiffness (physics.md section 6): the thesis's total
// spring f_t = -k_t(delta) s, or Mindlin's incremental df_t = -k_t(delta) ds (Yade, Kratos).
enum class TangentialSpring : std::int64_t { Total, Incremental };

// Coefficients of one contact kind (particle-particle or particle-barrier): the defaults of
// every pair of materials.
struct ContactLawParams {
  // The law, by the scene keys that select it in contact/laws/law_list.hpp.
  std::string law = "hertz";
  std::string cohesion = "none";
  LawKeyValues law_keys;
  std::optional<double> restitution;    // e in [kMinRestitution, 1]; calibrated damping (physics.md 5 Departure)
  std::optional<double> damping_ratio;  // xi_n >= 0 used as written in (50); exclusive with e
  double mu_static = 0.5;               // -, static Coulomb coefficient
  double mu_dynamic = 0.4;              // -, dynamic Coulomb coefficient (<= mu_static)
  double mu_rolling = 0.0;              // -, rolling resistance coefficient
  // xi_t, tangential damping ratio (67); unset: the normal ratio xi_n (calibrated from the
  // restitution, or damping_ratio), as LIGGGHTS and Kratos damp the tangential spring.
  std::optional<double> tangential_damping;
  TangentialSpring tangential_spring = TangentialSpring::Total;
};

// [[contact.pair]]: overrides of the defaults for the contacts between two materials (a
// particle of one and a particle or barrier of the other; `kind` restricts it to one of the two).
struct ContactPairParams {
  std::string material_a, material_b;
  bool particle_particle = true;  // applies to particle-particle contacts
  bool particle_barrier = true;   // applies to particle-barrier contacts
  std::optional<std::string> law, cohesion;
  LawKeyValues law_keys;  // replace the defaults' values key by key
  std::optional<double> restitution, damping_ratio, mu_static, mu_dynamic, mu_rolling, tangential_damping;
  std::optional<TangentialSpring> tangential_spring;
  // Its liquid_bridge table: bridges on for the pair (unless model = "none") with these keys over
  // [liquid_bridge]'s.
  std::optional<LiquidBridgeKeys> liquid_bridge;
  std::size_t line = 0;  // line of the entry, for messages
};

struct ContactParams {
  ContactLawParams particle_particle;
  ContactLawParams particle_barrier;
  std::vector<ContactPairParams> pairs;
  LiquidBridgeParams liquid_bridge;  // [liquid_bridge]: capillary bridges' defaults
};

struct ThermalParams {
  double air_temperature = 293.15;          // K
  Vec3 air_velocity{};                      // m/s
  double environment_temperature = 293.15;  // K, radiation sink
  bool conduction = true;
  bool convection = false;
  bool radiation = false;
};

enum class ExitPolicy { Remove, Stop };

struct DomainParams {
  bool bounded = false;  // false: no domain check
  Vec3 min{}, max{};     // m, axis-aligned box
  ExitPolicy on_exit = ExitPolicy::Stop;
  // Axes (x, y, z) along which the domain is periodic, with period max - min: particles leaving
  // through those faces come back through the opposite ones (parallel/periodic_images.hpp).
  std::array<bool, 3> periodic{};
  std::size_t periodic_line = 0;  // line of domain.periodic in the scene file, for messages (0 = none)
  bool any_periodic() const { return periodic[0] || periodic[1] || periodic[2]; }
};

struct NeighborParams {
  double skin = 0.0;  // m, Verlet skin (0 = 0.1 x smallest diameter)
};

// Encoding of the VTK XML files (io/vtk_xml.hpp): values inline as text, raw appended binary,
// or zlib-compressed appended binary.
enum class VtkFormat { Ascii, Binary, Compressed };

struct OutputParams {
  std::string dir = "output";            // relative to the scene file's folder
  VtkFormat format = VtkFormat::Binary;  // VTU/VTP/VTI encoding ("format"; binary: the fastest to write)
  double contacts_every = 0.0;           // s between contact snapshots (VTU + CSV; 0 = off)
  // Barrier loads written (barrier VTU, barrier_groups.csv): true: means over each output's
  // interval ("mean"), false: the last evaluation's sample ("sample")
  bool mean_barrier_loads = true;
  double particles_every = 0.0;     // s of simulated time between particle VTU (0 = off)
  double barriers_every = 0.0;      // s between barrier VTU (0 = off)
  double particle_csv_every = 0.0;  // s between particle CSV snapshots (0 = off)
  double body_csv_every = 0.0;      // s between body CSV snapshots of the clumps' bodies (0 = off)
  double bonds_every = 0.0;         // s between bond VTU snapshots (0 = off; only with [bonds])
  double barrier_log_every = 0.0;   // s between barrier-group log rows (0 = off)
  int log_every = 100;              // steps between global log rows (>= 1)
  int checkpoint_every = 0;         // steps between checkpoints (0 = off)
  double progress_every = 10.0;     // s of wall time between plain progress lines
};

// How the ranks of a decomposed run share the work (docs/parallel.md, "Load balance"); a
// one-rank run ignores it.
enum class BalanceCost { Work, Time };
struct ParallelParams {
  int balance_every = 1000;        // steps between imbalance measurements (0 = never: fixed uniform cuts)
  double balance_threshold = 1.1;  // -, max / mean cost per rank above which the cut planes move
  // Work: owned particles + listed neighbour pairs (deterministic: runs repeat bit for bit);
  // Time: the rank's measured evaluation time since the last measurement.
  BalanceCost balance_cost = BalanceCost::Work;
};

// Instability detection: the run stops with a message naming particles, time and step (the
// drift only warns at the end: the run is complete by then).
struct CheckParams {
  double max_overlap = 0.05;   // -, largest overlap / smaller radius (0 = off)
  double energy_jump = 0.5;    // -, largest one-step rise of the energy balance relative
                               //    to kinetic + rotational + elastic energy (0 = off)
  double energy_drift = 0.05;  // -, largest change of the energy balance over the whole run relative
                               //    to the start balance before the end-of-run warning (0 = off)
  // The contacts' energy ledger (their dissipation booked every step, which the two energy checks
  // need). false: the contact kernels compute energies only for the steps that write a log row
  // (`elastic`), the log has no damping_dissipated, friction_dissipated and total_energy, and
  // energy_jump and energy_drift are off (scene/checks_reader.hpp).
  bool energy_ledger = true;
};

// One [[coarse_grain]] entry (docs/output.md "Coarse-grained fields"): fields on a grid (.vti
// series) or a profile along one axis (CSV), from the particles and the contact list.
struct CoarseGrainSpec {
  std::string name;      // files cg_<name>...; "1", "2", ... unless given
  CgGrid grid;           // points; a profile averages the two other axes over grid.min..max
  bool profile = false;  // true: a profile along `axis` (CSV), else a grid (.vti)
  int axis = 2;          // 0, 1, 2: the profile's axis
  CgKernel kernel = CgKernel::gaussian;
  double width = 0.0;    // m, kernel width w
  double every = 0.0;    // s between outputs
  double average = 0.0;  // s, averaging window ending at each output (0: the instantaneous fields)
  int samples = 20;      // -, snapshots averaged in a window (when average > 0)
};

struct Params {
  TimeParams time;
  ToleranceParams tolerance;
  AnalysisParams analysis;
  FieldParams fields;
  NearFieldParams near_field;
  ContactParams contact;
  ThermalParams thermal;
  DomainParams domain;
  NeighborParams neighbor;
  OutputParams output;
  CheckParams checks;
  ParallelParams parallel;
  BondParams bonds;                           // [bonds], [[bonds.pair]], the bond CSV
  std::vector<InletSpec> inlets;              // [[inlet]] entries, in scene order
  std::vector<SinkSpec> sinks;                // [[sink]] entries, in scene order
  std::vector<CoarseGrainSpec> coarse_grain;  // [[coarse_grain]] entries, in scene order
};

}  // namespace mpdem
