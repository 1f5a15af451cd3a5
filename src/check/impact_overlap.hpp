#pragma once
// The overlap an impact at the expected speed would reach, per pair of materials, against
// checks.max_overlap: soft materials exceed it in ordinary pours, and the run then stops.
// The estimate is the undamped peak overlap (physics/time_step_estimate.hpp), an upper bound
// for a damped contact.
#include <string>
#include <vector>

#include "model/params.hpp"
#include "model/scene.hpp"

namespace mpdem {

// The expected impact speed: the fastest initial particle, or a free fall over the scene's
// height along gravity (particle centres and barrier vertices; at most the domain's extent
// along gravity when it is bounded), whichever is faster.
struct ImpactSpeed {
  double speed = 0.0;          // m/s, max(fastest, sqrt(2 |g| fall_height))
  double fastest = 0.0;        // m/s, largest initial particle speed
  double fall_height = 0.0;    // m, extent along gravity
  std::string origin() const;  // what sets it: "a fall of 0.47 m under gravity", ...
};

ImpactSpeed expected_impact_speed(const Scene& scene);

// Peak overlap of a head-on impact at `speed` between particles of materials a and b (equal
// materials: equal spheres; otherwise also the smallest of one against the largest of the
// other), or of a particle of material a on a barrier element of material b.
struct ImpactEstimate {
  int a = -1, b = -1;    // material indices (b: the barrier element's material when `barrier`)
  bool barrier = false;  // particle-barrier impact
  ContactLawKind law = ContactLawKind::Hertz;
  double overlap = 0.0;  // m, peak overlap
  double radius = 0.0;   // m, the (smaller) radius it is relative to
  double ratio = 0.0;    // -, overlap / radius, as checks.max_overlap measures it
};

// Every pair of materials the scene's particles and barrier elements have, deepest first.
std::vector<ImpactEstimate> impact_estimates(const Scene& scene, double speed);

}  // namespace mpdem
