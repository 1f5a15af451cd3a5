#pragma once
// Pre-run scene checks: everything about a loaded scene that would make the run misbehave at or
// soon after its first step, found all at once (not only the first) before anything runs. Used
// by `mpdem check` (errors exit 2) and by `mpdem run` before step 1 (problems that would
// certainly stop the run refuse it, the others warn).
#include "check/scene_problem.hpp"
#include "model/scene.hpp"
#include "scene/scene_reader.hpp"

namespace mpdem {

// Every check below, in this order. The scene as load_scene() returns it (particles not yet
// reordered by a run, so that they can be traced to their sources).
SceneProblems check_scene(const Scene& scene);

// Particles outside a bounded [domain] at t = 0 (error; stops the run with on_exit = "stop",
// else they are removed at step 1). One problem per particle source.
void check_outside_domain(const Scene& scene, SceneProblems& out);
// Particle-particle and particle-barrier overlaps at t = 0 deeper than checks.max_overlap
// (errors that stop the run; with the check off, warnings beyond kInitialOverlapWarning).
void check_initial_overlaps(const Scene& scene, SceneProblems& out);
// [[particles]] generate regions that a barrier triangle passes through (errors: the generator
// places particles without regard to barriers).
void check_region_walls(const Scene& scene, SceneProblems& out);
// A periodic [domain] (errors): barrier elements crossing a periodic face at t = 0 (a wall is
// not copied across the period), and periods shorter than twice the neighbour search's reach.
void check_periodic_domain(const Scene& scene, SceneProblems& out);
// Barrier elements whose motion carries them across a periodic face after t = 0, before the
// run's end (errors; the run starts with a warning: it goes on, wrongly, from then on).
void check_periodic_motion(const Scene& scene, SceneProblems& out);
// [[inlet]] entries (check/inlet_checks.cpp): a volume where the centres of its particles lie
// entirely outside a bounded domain (error; refuses the run with on_exit = "stop") or partly
// (error with on_exit = "stop", else a warning), a start at or after the run's end (warning).
void check_inlets(const Scene& scene, SceneProblems& out);
// Estimated peak overlap of an impact at the expected speed (initial particles, falls, inlets)
// per material pair against checks.max_overlap (warnings).
void check_impact_overlaps(const Scene& scene, SceneProblems& out);

// At most this many ids (or pairs) are listed in one message; the rest are counted.
inline constexpr std::size_t kListedIds = 5;

}  // namespace mpdem
