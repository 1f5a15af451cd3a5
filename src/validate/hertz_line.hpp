#pragma once
// Reference for the normal-contact validation cases: elastic spheres on a line (and optionally a
// rigid-mounted flat wall below the first one) pushing each other with the undamped Hertz law
//   F = 4/3 E* sqrt(r*) delta^(3/2)        (49), E* (51), r* (52); r* = R for a plane
// integrated with classical RK4 at a step far below the engine's. Written independently of the
// engine's contact code so that it can serve as its oracle.
#include <optional>
#include <vector>

namespace mpdem::validate {

struct LineSphere {
  double x = 0.0;        // m, centre along the line (spheres sorted by x)
  double v = 0.0;        // m/s
  double mass = 0.0;     // kg
  double radius = 0.0;   // m
  double young = 0.0;    // Pa
  double poisson = 0.0;  // -
};

struct LineWall {
  double x = 0.0;        // m, wall surface; the first sphere lies above it (x > wall)
  double young = 0.0;    // Pa (+inf: rigid)
  double poisson = 0.0;  // -
};


class HertzLine {
 public:
  HertzLine(std::vector<LineSphere> spheres, std::optional<LineWall> wall, double max_step);
  // Integrates from the current time to t (> current) with steps <= max_step.
  void advance_to(double t);
  double time() const { return t_; }
  const std::vector<LineSphere>& spheres() const { return s_; }
  // Overlap of spheres k and k+1 (> 0 in contact)   [m]
  double overlap(std::size_t k) const;

 private:
  // Accelerations of the spheres at positions x   [m/s^2]
  void accelerations(const std::vector<double>& x, std::vector<double>& a) const;
  void rk4(double h);

  std::vector<LineSphere> s_;
  std::optional<LineWall> wall_;
  std::vector<double> k_pair_;  // N/m^1.5, 4/3 E* sqrt(r*) of spheres k, k+1
  double k_wall_ = 0.0;         // N/m^1.5, of the first sphere and the wall
  double max_step_;             // s
  double t_ = 0.0;              // s
};

}  // namespace mpdem::validate
