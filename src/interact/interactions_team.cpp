// Interactions::evaluate with its passes in the caller's parallel region: velocity Verlet's step
// runs as one region (integrate/verlet.cpp), so that its threads are woken once a step instead of
// once a pass. The passes are the same functions as evaluate()'s, orphaned work-sharing loops;
// only the serial parts (the lists' safety net, the passes' set-up and totals) run on one thread.
#include <omp.h>

#include "contact/barrier_contacts.hpp"
#include "contact/particle_contacts.hpp"
#include "core/scoped_timer.hpp"
#include "interact/body_forces.hpp"
#include "interact/interactions.hpp"
#include "neighbor/neighbor_search.hpp"

namespace mpdem {

bool Interactions::team_ready(const Particles& p) const {
  return one_region_ && !comm_ && !near_ && !heat_ && !bonds_ && !p.has_bodies() && external_.empty() &&
         BodyForces(model_.params.fields).only_first();
}

void Interactions::evaluate_in_team(Particles& p, Barriers& b, const EvalRequest& req, DriftCheck* next) {
  // The set-up (a mid-step rebuild among it) on one thread; what it throws stops every thread
  // after the single's barrier, and goes to the caller after the region.
#pragma omp single
  {
    try {
      prepare_evaluation(p, b, req);
      particle_contacts_->begin(p, *search_, req);
      team_barriers_ = barrier_contacts_->begin(p, b, *search_, req);
    } catch (...) {
      team_error_ = std::current_exception();
    }
  }
  if (team_error_) return;
  {
    TeamTimer timer(times_.fields);
    start_first_forces(p);  // its barrier: the forces start before the contacts add to them
  }
  {
    TeamTimer timer(times_.pairs);
    particle_contacts_->run_blocks(p, *search_);
  }
  if (team_barriers_) {
    TeamTimer timer(times_.barriers);
    barrier_contacts_->run_groups(p, b, *search_, req);  // several threads: ends at a barrier
  }
#pragma omp single
  {
    try {
      const PairStats pp = particle_contacts_->finish();
      const PairStats pb = team_barriers_ ? barrier_contacts_->finish(b, req) : PairStats{};
      {
        ScopedTimer timer(times_.exchange);
        search_->fold_ghosts(p);  // what the periodic images received goes to their sources
      }
      book_evaluation(p, b, req, pp, pb, 0.0);
      if (next) *next = next_drift_check(p, b, req.dt);
    } catch (...) {
      team_error_ = std::current_exception();
    }
  }
}

}  // namespace mpdem
