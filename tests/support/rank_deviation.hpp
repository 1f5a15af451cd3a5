#pragma once
// How far a decomposed run's particles are from a one-rank reference run's, by id, over all ranks.
#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

#include "parallel/communicator.hpp"
#include "state/particles.hpp"

namespace mpdem::test {

// The largest deviation of `mine` (this rank's particles) from `ref` by id: x relative to the
// length `scale` (m), v and w relative to the reference's largest speed and spin; and how many
// particles matched, both over all ranks (collective).
inline std::pair<double, std::uint64_t> rank_deviation(const Communicator& world, const Particles& mine,
                                                       const Particles& ref, double scale) {
  double vmax = 0.0, wmax = 0.0, worst = 0.0;
  std::map<std::int64_t, std::size_t> at;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    at[ref.id[i]] = i;
    vmax = std::max(vmax, norm(ref.v[i]));
    wmax = std::max(wmax, norm(ref.w[i]));
  }
  std::uint64_t matched = 0;
  for (std::size_t i = 0; i < mine.size(); ++i)
    if (const auto it = at.find(mine.id[i]); it != at.end()) {
      const std::size_t j = it->second;
      ++matched;
      worst = std::max({worst, norm(mine.x[i] - ref.x[j]) / scale, norm(mine.v[i] - ref.v[j]) / vmax,
                        norm(mine.w[i] - ref.w[j]) / wmax});
    }
  return {world.max(worst), world.sum(matched)};
}

}  // namespace mpdem::test
