#pragma once
// Particles as bytes, for messages between ranks (halo ghosts and migration): every array of
// Particles::for_each_array, array by array, so that an array added there travels too; or, for
// the refresh of ghosts at every evaluation, only the arrays a step changes that an interaction
// reads (kMotion, kMotionAndTemperature). Native byte order: the ranks of one run share a
// machine kind.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/vec3.hpp"
#include "state/particles.hpp"

namespace mpdem {

// Which arrays a message holds: all (ghosts built, particles migrating), or what a ghost's copy
// can miss between two builds and an interaction reads: centre, velocity, spin (kMotion), and the
// temperature when heat transfer is on. The other arrays change only between steps, at a rebuild;
// the orientation changes every step, but no interaction reads a ghost's (it stays the build's).
enum class ParticleArrays { kAll, kMotion, kMotionAndTemperature };

inline bool carried(ParticleArrays which, std::string_view name) {
  return which == ParticleArrays::kAll || name == "x" || name == "v" || name == "w" ||
         (which == ParticleArrays::kMotionAndTemperature && name == "T");
}

// Appends particles idx of p to out: a count, then each array's values; x shifted by `shift` (m).
inline void pack_particles(Particles& p, std::span<const std::uint32_t> idx, const Vec3& shift,
                           std::vector<std::byte>& out, ParticleArrays which = ParticleArrays::kAll) {
  const std::uint64_t n = idx.size();
  const std::size_t at = out.size();
  out.resize(at + sizeof n);
  std::memcpy(out.data() + at, &n, sizeof n);
  p.for_each_array([&](const char* name, auto& a) {
    if (!carried(which, name)) return;
    using T = typename std::decay_t<decltype(a)>::value_type;
    const std::size_t base = out.size();
    out.resize(base + idx.size() * sizeof(T));
    for (std::size_t k = 0; k < idx.size(); ++k) {
      T value = a[idx[k]];
      if constexpr (std::is_same_v<T, Vec3>)
        if (std::string_view(name) == "x") value += shift;
      std::memcpy(out.data() + base + k * sizeof(T), &value, sizeof(T));
    }
  });
}

// The bytes pack_particles appends for n particles (with the same `which`).
inline std::size_t packed_bytes(Particles& p, std::size_t n, ParticleArrays which = ParticleArrays::kAll) {
  std::size_t bytes = sizeof(std::uint64_t);
  p.for_each_array([&](const char* name, auto& a) {
    if (carried(which, name)) bytes += n * sizeof(typename std::decay_t<decltype(a)>::value_type);
  });
  return bytes;
}

// Reads one block written by pack_particles (with the same `which`) from bytes at `pos` (advanced
// past it) into those arrays of p: appended (kAll only), or overwriting [at, at + n) when `at` is
// given (a ghost refresh); returns how many. Throws on a truncated message or a range past the
// arrays' end.
inline std::size_t unpack_particles(Particles& p, std::span<const std::byte> bytes, std::size_t& pos,
                                    std::size_t at = static_cast<std::size_t>(-1),
                                    ParticleArrays which = ParticleArrays::kAll) {
  std::uint64_t n = 0;
  if (bytes.size() - pos < sizeof n) throw std::runtime_error("truncated particle message");
  std::memcpy(&n, bytes.data() + pos, sizeof n);
  pos += sizeof n;
  const bool append = at == static_cast<std::size_t>(-1);
  if (append && which != ParticleArrays::kAll) throw std::logic_error("unpack_particles: appends need every array");
  if (!append && (at > p.size_with_ghosts() || p.size_with_ghosts() - at < n))
    throw std::runtime_error("particle message longer than the ghosts it refreshes");
  p.for_each_array([&](const char* name, auto& a) {
    if (!carried(which, name)) return;
    using T = typename std::decay_t<decltype(a)>::value_type;
    if ((bytes.size() - pos) / sizeof(T) < n) throw std::runtime_error("truncated particle message");
    const std::size_t base = append ? a.size() : at;
    if (append) a.resize(base + static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < n; ++k) std::memcpy(&a[base + k], bytes.data() + pos + k * sizeof(T), sizeof(T));
    pos += static_cast<std::size_t>(n) * sizeof(T);
  });
  return static_cast<std::size_t>(n);
}

}  // namespace mpdem
