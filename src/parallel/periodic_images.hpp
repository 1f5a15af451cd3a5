#pragma once
// PeriodicImages: periodic boundaries ([domain] periodic, physics.md section 11) as ghost
// particles. At every list build the owned particles within `width` of a periodic face get an
// image on the far side of the period (up to 7, at edges and corners), appended after the owned
// particles (state/particles.hpp); the neighbour list pairs owned particles with them like with
// any other particle. Each evaluation copies the sources' state onto the ghosts (refresh), and
// afterwards adds what the ghosts received to their sources (fold), in ascending ghost order, so
// sums do not depend on the thread count. MPI halo particles are the same kind of ghost.
//
// Positions are wrapped into [min, max) only between steps (wrap, at the rebuilds that also
// reorder), never within a step: the integrators hold their step-start state by index. Between
// rebuilds a particle may therefore lie up to about skin/2 outside the period; the unwrapped
// centre is always x + image * period. A clump body's centre is wrapped and its members shifted
// with it (state/bodies.hpp): a member keeps its body's image counter and may lie outside the
// period by its offset from the centre; its images are chosen as any particle's.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec3.hpp"
#include "model/params.hpp"
#include "state/particles.hpp"

namespace mpdem {

// m, how far from a periodic face particles get images: a pair across the face lies within the
// list's reach (2 R_max + extra_range + skin) of both faces, and a skin more covers particles
// that drifted out of the period since their last wrap (a rebuild within a step). Clump members
// move with their body's wrapped centre, so one may lie outside the period by its offset from the
// centre: member_offset (m), the largest such offset, widens the band by as much.
inline double periodic_image_width(double max_radius, double extra_range, double skin, double member_offset = 0.0) {
  return 2.0 * max_radius + extra_range + 2.0 * skin + member_offset;
}

// m, the separation d of two centres as its nearest image: whole periods (period, m, per axis;
// 0 where not periodic, PeriodicImages::period) taken off along the periodic axes.
inline Vec3 nearest_image(Vec3 d, const Vec3& period) {
  for (int c = 0; c < 3; ++c)
    if (period[c] > 0.0) d[c] -= period[c] * std::round(d[c] / period[c]);
  return d;
}

class PeriodicImages {
 public:
  PeriodicImages() = default;
  explicit PeriodicImages(const DomainParams& d);

  bool active() const { return periodic_[0] || periodic_[1] || periodic_[2]; }
  const Vec3& period() const { return period_; }  // m, max - min along the periodic axes (0 elsewhere)

  // Wraps the owned centres into [min, max) along the periodic axes, counting the images; a clump
  // body's centre likewise, its members shifted by the same periods.
  void wrap(Particles& p) const;
  // Chooses the ghosts of the owned centres x [N] (m) within width (m) of a periodic face.
  // Throws std::invalid_argument when a period is shorter than 2 x width: a particle could then
  // meet two images of another.
  void select(std::span<const Vec3> x, double width);
  // Appends the chosen ghosts to p (which holds no ghosts): copies of their sources, shifted.
  void append(Particles& p) const;
  // Copies the sources' state onto the ghosts and clears the ghosts' accumulators.
  void refresh(Particles& p) const;
  // Adds the ghosts' force, torque and heat to their sources.
  void fold(Particles& p) const;

  std::size_t size() const { return source_.size(); }
  std::uint32_t source(std::size_t g) const { return source_[g]; }  // owned index of ghost g
  const Vec3& shift(std::size_t g) const { return shift_[g]; }      // m, ghost centre - source centre
  std::size_t memory_bytes() const;

 private:
  std::array<bool, 3> periodic_{};
  Vec3 lo_{}, hi_{};                   // m, the domain box
  Vec3 period_{};                      // m
  std::vector<std::uint32_t> source_;  // [G] owned index of each ghost, ascending
  std::vector<Vec3> shift_;            // [G] m, ghost centre - source centre
};

}  // namespace mpdem
