// Checkpoints of a Simulation (issue: restart): everything the next step depends on, so a
// resumed run is bitwise identical to an uninterrupted one with the same thread count - the
// particle arrays in their current order (with the rates of the accepted state), the
// neighbour lists' build positions (rebuilds then happen at the same steps), contact history,
// statistics, the adaptive step and the output series.
#include <fmt/core.h>

#include <cstring>
#include <string>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/output_manager.hpp"
#include "sim/simulation.hpp"

namespace mpdem {

namespace {
// The last byte is the format version: 2 since the barrier history is kept per particle index
// (session 2). Older files are refused with a message that says so.
constexpr char kMagic[8] = {'M', 'P', 'D', 'E', 'M', 'C', 'K', '2'};

}  // namespace

void Simulation::write_checkpoint(const std::filesystem::path& file) {
  BinaryWriter w;
  w.value(kMagic);
  w.value<std::uint64_t>(scene_.barriers.size());
  w.value<std::uint64_t>(scene_.model.materials.size());
  w.value(time_);
  w.value(steps_);
  w.value(evaluations_);
  w.value(removed_);
  w.value(redone_);
  w.value(dt_);
  w.value(last_balance_);
  w.value(last_active_);
  w.value(energy_checked_);
  scene_.particles.for_each_array([&](const char*, auto& a) { w.vector(a); });
  interactions_->save(w, scene_.particles);
  w.value<bool>(output_ != nullptr);
  if (output_) output_->save(w);  // last: resume_from hands the rest to the OutputManager
  write_file_atomically(file, [&](std::ostream& os) {
    os.write(w.bytes().data(), static_cast<std::streamsize>(w.bytes().size()));
  });
}

void Simulation::resume_from(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name, 0, "", "cannot open the checkpoint file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  try {
    BinaryReader r(bytes.data(), bytes.size());
    const auto magic = r.value<std::array<char, 8>>();
    if (std::memcmp(magic.data(), kMagic, 7) == 0 && magic[7] != kMagic[7])
      throw std::runtime_error(std::string("it has checkpoint format ") + magic[7] + ", this mpdem reads format " +
                               kMagic[7] + " only (written by another mpdem version); start the run again from its scene");
    if (std::memcmp(magic.data(), kMagic, 8) != 0) throw std::runtime_error("not an mpdem checkpoint");
    if (r.value<std::uint64_t>() != scene_.barriers.size() || r.value<std::uint64_t>() != scene_.model.materials.size())
      throw std::runtime_error("it was written for a scene with other barriers or materials");
    time_ = r.value<double>();
    steps_ = r.value<std::uint64_t>();
    evaluations_ = r.value<std::uint64_t>();
    removed_ = r.value<std::size_t>();
    redone_ = r.value<std::uint64_t>();
    dt_ = r.value<double>();
    last_balance_ = r.value<double>();
    last_active_ = r.value<double>();
    energy_checked_ = r.value<bool>();
    Particles& p = scene_.particles;
    p.for_each_array([&](const char*, auto& a) { a = r.template vector<typename std::decay_t<decltype(a)>::value_type>(); });
    const std::size_t n = p.id.size();
    bool sizes_ok = true;
    p.for_each_array([&](const char*, auto& a) { sizes_ok = sizes_ok && a.size() == n; });
    if (!sizes_ok) throw std::runtime_error("particle arrays of different lengths");
    scene_.barriers.move_to(time_);
    interactions_->restore(r, p, scene_.barriers);
    // The output series are restored once run() has opened the outputs.
    if (r.value<bool>()) resume_output_state_ = r.rest();
  } catch (const std::runtime_error& e) {
    throw InputError(name, 0, "", std::string("cannot resume from this checkpoint: ") + e.what());
  }
  initialized_ = true;
  resumed_ = true;
}

}  // namespace mpdem
