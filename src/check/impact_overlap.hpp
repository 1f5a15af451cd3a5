#pragma once
// The overlap an impact at the expected speed would reach, per pair of materials, against
// checks.max_overlap: soft materials exceed it in ordinary pours, and the run then stops.
// The estimate is the undamped peak overlap (physics/time_step_estimate.hpp), an upper bound
// for a damped contact.
#include <string>
#include <vector>

#include "contact/laws/law_interface.hpp"
#include "model/params.hpp"
#include "model/scene.hpp"

namespace mpdem {

// The expected impact speed: the fastest initial particle, a free fall over the scene's height
// along gravity (particle centres and barrier vertices; at most the domain's extent along
// gravity when it is bounded), or the fastest inlet's particles, whichever is faster. An inlet's
// particles reach sqrt(v^2 + 2 |g| H): v their largest insertion speed (|velocity| + sqrt(3)
// velocity_spread), H the fall from the top of the inlet's volume to the lowest point of the
// scene (particle centres, barrier vertices, inlet volumes; not below a bounded domain).
struct ImpactSpeed {
  double speed = 0.0;            // m/s, the largest of the three
  double fastest = 0.0;          // m/s, largest initial particle speed
  double fall_height = 0.0;      // m, extent along gravity (0 without particles)
  std::string inlet;             // the fastest inlet's name when it sets the speed, else ""
  double insertion_speed = 0.0;  // m/s, that inlet's largest insertion speed
  double inlet_fall = 0.0;       // m, that inlet's fall
  std::string origin() const;    // what sets it: "a fall of 0.47 m under gravity", ...
};
ImpactSpeed expected_impact_speed(const Scene& scene);

// Peak overlap of a head-on impact at `speed` between particles of materials a and b (equal
// materials: equal spheres; otherwise also the smallest of one against the largest of the
// other), or of a particle of material a on a barrier element of material b.
struct ImpactEstimate {
  int a = -1, b = -1;    // material indices (b: the barrier element's material when `barrier`)
  bool barrier = false;  // particle-barrier impact
  LawId law = 0;         // the pair's law (contact/laws/law_list.hpp)
  double overlap = 0.0;  // m, peak overlap
  double radius = 0.0;   // m, the (smaller) radius it is relative to
  double ratio = 0.0;    // -, overlap / radius, as checks.max_overlap measures it
};

// Every pair of materials the scene's particles (those present and those its inlets insert) and
// barrier elements have, deepest first.
std::vector<ImpactEstimate> impact_estimates(const Scene& scene, double speed);

}  // namespace mpdem
