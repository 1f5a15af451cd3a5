// Changes to the state between steps by a caller (the Python module): the state set, particles
// added and removed. One rank: the module runs in one process.
#include <algorithm>
#include <string>
#include <unordered_set>

#include "core/input_error.hpp"
#include "sim/inlets.hpp"
#include "sim/simulation.hpp"

namespace mpdem {

namespace {
void refuse_several_ranks(const Communicator* comm, const char* what) {
  if (comm) throw InputError("", 0, "", std::string(what) + " between steps is for a run on one rank");
}
}  // namespace

void Simulation::state_changed() {
  if (!initialized_) return;              // initialize() will evaluate the state as it is
  const double before = record_.balance;  // J
  initialized_ = false;
  energy_checked_ = false;  // what the caller put in is not a jump of a step
  initialize();
  record_.start_balance += record_.balance - before;  // ... nor drift of the run
}

std::int64_t Simulation::next_free_id() const {
  const Particles& p = scene_.particles;
  std::int64_t next = inlets_ ? inlets_->next_id() : 0;
  for (std::size_t i = 0; i < p.size(); ++i) next = std::max(next, p.id[i] + 1);
  return next;
}

void Simulation::add_particles(Particles fresh) {
  refuse_several_ranks(comm_, "adding particles");
  if (scene_.particles.has_bodies())
    throw InputError("", 0, "clump", "adding particles to a scene with clumps is not supported yet");
  if (fresh.size() == 0) return;
  Particles& p = scene_.particles;
  std::unordered_set<std::int64_t> taken(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(p.size()));
  std::int64_t largest = -1;
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    if (!taken.insert(fresh.id[i]).second)
      throw InputError("", 0, "id", "a particle with id " + std::to_string(fresh.id[i]) + " exists already");
    largest = std::max(largest, fresh.id[i]);
  }
  if (inlets_) inlets_->ids_after(largest);
  initialize();
  interactions_->add_particles(p, scene_.barriers, std::move(fresh));
  state_changed();
}

void Simulation::remove_particles(const std::vector<std::int64_t>& ids) {
  if (scene_.particles.has_bodies())
    throw InputError("", 0, "clump", "removing particles from a scene with clumps is not supported yet");
  refuse_several_ranks(comm_, "removing particles");
  const Particles& p = scene_.particles;
  std::unordered_set<std::int64_t> gone(ids.begin(), ids.end());
  std::vector<char> keep(p.size(), 1);
  std::size_t found = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (gone.count(p.id[i]) != 0) {
      keep[i] = 0;
      ++found;
    }
  if (found != gone.size())
    for (const std::int64_t id : ids)
      if (std::find(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(p.size()), id) ==
          p.id.begin() + static_cast<std::ptrdiff_t>(p.size()))
        throw InputError("", 0, "id", "no particle with id " + std::to_string(id));
  initialize();
  remove_marked(keep, false);
}

}  // namespace mpdem
