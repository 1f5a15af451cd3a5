#include "contact/bonds.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "contact/bond_making.hpp"
#include "core/deterministic_sum.hpp"
#include "core/run_error.hpp"
#include "model/bond_rules.hpp"
#include "parallel/periodic_images.hpp"

namespace mpdem {

namespace {
constexpr std::uint32_t kUnresolved = std::numeric_limits<std::uint32_t>::max();

// Acting states of a bond at an evaluation.
enum : std::uint8_t { kIdle = 0, kActs = 1, kBreaksNow = 2 };

// A vector v normal to n_old carried to the plane normal to n_new and turned by `spin` (rad)
// about n_new, its length kept: the bond's shear force and bending moment follow the bond's
// rotation (PC2004 section 2.2.2; the same projection as the tangential springs', physics.md 6).
Vec3 carried(const Vec3& v, const Vec3& n_new, double spin) {
  const double len2 = dot(v, v);
  if (len2 == 0.0) return v;
  Vec3 u = v - n_new * dot(v, n_new);
  u = u + cross(n_new, u) * spin;
  const double u2 = dot(u, u);
  return u2 > 0.0 ? u * std::sqrt(len2 / u2) : Vec3{};
}

}  // namespace

Bonds::Bonds(const Model& model)
    : model_(model), period_(PeriodicImages(model.params.domain).period()), materials_(model.materials.size()),
      laws_(bond_laws(model)) {}

BondRecord Bonds::made(const Particles& p, std::size_t a, std::size_t b) const {
  if (p.id[a] > p.id[b]) std::swap(a, b);
  BondRecord r;
  r.id_i = p.id[a];
  r.id_j = p.id[b];
  r.radius = laws_[law_index(p, a, b)].radius_ratio * std::min(p.radius[a], p.radius[b]);
  r.length = norm(nearest_image(p.x[b] - p.x[a], period_));
  return r;
}

std::size_t Bonds::add(const Particles& p, std::size_t a, std::size_t b) {
  const BondRecord r = made(p, a, b);
  const auto at = std::lower_bound(bonds_.begin(), bonds_.end(), r, bond_before);
  const std::size_t k = static_cast<std::size_t>(at - bonds_.begin());
  bonds_.insert(at, r);
  ii_.clear();  // looked up again at the next evaluation
  jj_.clear();
  latched_.clear();  // between steps: nothing latched
  return k;
}

void Bonds::make(const Particles& p) {
  for (const MadeBond& m : make_bonds(model_, p)) bonds_.push_back(made(p, m.i, m.j));
  std::sort(bonds_.begin(), bonds_.end(), bond_before);
  ii_.clear();
  jj_.clear();
  latched_.clear();
}

std::size_t Bonds::intact() const {
  return static_cast<std::size_t>(
      std::count_if(bonds_.begin(), bonds_.end(), [](const BondRecord& r) { return r.intact != 0; }));
}

bool Bonds::resolved(const Particles& p) const {
  if (ii_.size() != bonds_.size()) return false;
  const std::size_t owned = p.size(), all = p.size_with_ghosts();
  for (std::size_t b = 0; b < bonds_.size(); ++b) {
    if (!bonds_[b].intact) continue;
    const std::uint32_t i = ii_[b], j = jj_[b];
    if (i >= owned || j >= all || p.id[i] != bonds_[b].id_i || p.id[j] != bonds_[b].id_j) return false;
  }
  return true;
}

void Bonds::resolve(const Particles& p) {
  // The owned particles come first, so an id's owned index wins over its ghosts'.
  std::unordered_map<std::int64_t, std::uint32_t> at;
  at.reserve(p.size_with_ghosts());
  for (std::size_t k = 0; k < p.size_with_ghosts(); ++k) at.try_emplace(p.id[k], static_cast<std::uint32_t>(k));
  ii_.assign(bonds_.size(), kUnresolved);
  jj_.assign(bonds_.size(), kUnresolved);
  for (std::size_t b = 0; b < bonds_.size(); ++b) {
    const BondRecord& r = bonds_[b];
    if (!r.intact) continue;
    const auto i = at.find(r.id_i), j = at.find(r.id_j);
    if (i == at.end() || i->second >= p.size() || j == at.end())
      throw RunError(fmt::format("the bond between particles {} and {} lost particle {}: it is {} (a bond must not "
                                 "stretch beyond the reach of the particles' neighbourhood)",
                                 r.id_i, r.id_j, i == at.end() || i->second >= p.size() ? r.id_i : r.id_j,
                                 i != at.end() && i->second >= p.size() ? "held by another rank" : "beyond reach"));
    ii_[b] = i->second;
    jj_[b] = j->second;
  }
}

BondStats Bonds::evaluate(Particles& p, const EvalRequest& req) {
  BondStats st;
  if (bonds_.empty()) return st;
  if (!resolved(p)) resolve(p);
  const std::size_t n = bonds_.size();
  results_.resize(n);
  acting_.resize(n);
  stress_.resize(n);
  // The trapezoidal rule's first iteration of a step (or of its redo) forgets the last attempt's.
  latched_.resize(n, 0);
  if (req.iteration == 1) std::fill(latched_.begin(), latched_.end(), std::uint8_t{0});
  const double dt = req.dt, phi = req.phi;
  // J (held), W (dashpots), J (held by the bonds that break now)
  const std::array<double, 3> sums = deterministic_block_sums<3>(
      n, [&](std::size_t lo, std::size_t hi, std::array<double, 3>& s) {
        for (std::size_t b = lo; b < hi; ++b) {
          BondRecord& r = bonds_[b];
          if (!r.intact) {
            acting_[b] = kIdle;
            continue;
          }
          const std::size_t i = ii_[b], j = jj_[b];
          const Vec3 d = nearest_image(p.x[j] - p.x[i], period_);  // m
          const double dist = norm(d);
          const Vec3 nrm = d / dist;
          const BondLaw& law = laws_[law_index(p, i, j)];
          const BondSection sec = bond_section(r.radius);
          const BondSprings k = bond_springs(sec, r.length, law.young, law.stiffness_ratio);
          // The bond's centre, midway between the two surfaces, and the arms to it from i and j.
          const Vec3 arm_i = nrm * (p.radius[i] + 0.5 * (dist - p.radius[i] - p.radius[j]));    // m
          const Vec3 arm_j = arm_i - d;                                                         // m
          const Vec3 vrel = (p.v[j] + cross(p.w[j], arm_j)) - (p.v[i] + cross(p.w[i], arm_i));  // m/s
          const Vec3 wrel = p.w[j] - p.w[i];                                                    // rad/s
          // The relative motion over the step, weighted like the tangential springs' increment (64).
          const Vec3 du = (vrel * phi + r.v_start * (1.0 - phi)) * dt;   // m
          const Vec3 dth = (wrel * phi + r.w_start * (1.0 - phi)) * dt;  // rad
          const double spin = 0.5 * dot(p.w[i] + p.w[j], nrm) * dt;      // rad, the pair's turn about the bond
          const double dun = dot(du, nrm), dthn = dot(dth, nrm);
          // PC2004 eq. 8: the increments of the four springs, on the state carried to the new normal.
          const double fn = r.fn - k.normal * dun;
          const Vec3 fs = carried(r.fs, nrm, spin) - (du - nrm * dun) * k.shear;
          const double mn = r.mn - k.twist * dthn;
          const Vec3 ms = carried(r.ms, nrm, spin) - (dth - nrm * dthn) * k.bend;
          const double sigma = bond_tensile_stress(sec, fn, ms), tau = bond_shear_stress(sec, fs, mn);
          const double held = bond_energy(k, fn, fs, mn, ms);
          const bool past = sigma >= law.tensile_strength || tau >= law.shear_strength;
          // Within a step's iterations a bond once past its strength stays broken for the step:
          // the iteration then converges to the state without it instead of alternating across
          // the jump of its force (a fixed point may not exist between the two).
          if (past && req.iteration > 0 && !latched_[b]) {
            latched_[b] = 1;
            stress_[b] = {sigma, tau};
          }
          if (past || latched_[b]) {
            // Broken: no force from here on (a trial state past the strength acts neither).
            acting_[b] = kIdle;
            if (req.commit) {
              acting_[b] = kBreaksNow;
              r.intact = 0;
              if (!latched_[b]) stress_[b] = {sigma, tau};  // else the stresses when it passed
              s[2] += held;
            }
            continue;
          }
          // Dashpots on the relative motion, each at the ratio zeta of its spring's critical damping.
          const bool fi = p.fixed[i] != 0, fj = p.fixed[j] != 0;
          const double m = bond_reduced(p.mass[i], p.mass[j], fi, fj);
          const double jm = bond_reduced(p.inertia[i], p.inertia[j], fi, fj);
          const double vn = dot(vrel, nrm), wn = dot(wrel, nrm);
          const Vec3 vs = vrel - nrm * vn, ws = wrel - nrm * wn;
          const double cn = bond_dashpot(law.damping, m, k.normal), cs = bond_dashpot(law.damping, m, k.shear);
          const double ct = bond_dashpot(law.damping, jm, k.twist), cb = bond_dashpot(law.damping, jm, k.bend);
          const Vec3 f = nrm * (fn - cn * vn) + fs - vs * cs;       // N, on j
          const Vec3 moment = nrm * (mn - ct * wn) + ms - ws * cb;  // N m, on j
          results_[b] = {f, cross(arm_i, -f) - moment, cross(arm_j, f) + moment};
          acting_[b] = kActs;
          s[0] += held;
          s[1] += cn * vn * vn + cs * dot(vs, vs) + ct * wn * wn + cb * dot(ws, ws);
          if (req.commit) {
            r.fn = fn;
            r.fs = fs;
            r.mn = mn;
            r.ms = ms;
            r.normal = nrm;
            r.v_start = vrel;
            r.w_start = wrel;
          }
        }
      });
  // In bond order, so that every particle's sum has one order for any thread count.
  for (std::size_t b = 0; b < n; ++b) {
    if (acting_[b] == kActs) {
      const std::size_t i = ii_[b], j = jj_[b];
      p.force[j] += results_[b].f;
      p.force[i] -= results_[b].f;
      p.torque[i] += results_[b].ti;
      p.torque[j] += results_[b].tj;
      ++st.intact;
    } else if (acting_[b] == kBreaksNow) {
      const BondRecord& r = bonds_[b];
      const BondLaw& law = laws_[law_index(p, ii_[b], jj_[b])];
      const bool tension = stress_[b].sigma / law.tensile_strength >= stress_[b].tau / law.shear_strength;
      breaks_.push_back({req.time, r.id_i, r.id_j, tension ? BondBreakMode::tension : BondBreakMode::shear,
                         stress_[b].sigma, stress_[b].tau});
      ++st.broken;
    }
  }
  if (req.commit) std::fill(latched_.begin(), latched_.end(), std::uint8_t{0});
  st.energy = sums[0];
  st.damping_power = sums[1];
  st.broken_energy = sums[2];
  return st;
}

std::vector<BondBreak> Bonds::take_breaks() {
  std::vector<BondBreak> out;
  out.swap(breaks_);
  return out;
}

void Bonds::remove_particles(std::span<const std::int64_t> ids) {
  const std::unordered_set<std::int64_t> gone(ids.begin(), ids.end());
  std::erase_if(bonds_, [&](const BondRecord& r) { return gone.contains(r.id_i) || gone.contains(r.id_j); });
  ii_.clear();
  jj_.clear();
  latched_.clear();
}

void Bonds::keep_owned(const Particles& p) {
  const std::unordered_set<std::int64_t> mine(p.id.begin(), p.id.begin() + static_cast<std::ptrdiff_t>(p.size()));
  std::erase_if(bonds_, [&](const BondRecord& r) { return !mine.contains(r.id_i); });
  ii_.clear();
  jj_.clear();
  latched_.clear();
}

double Bonds::longest() const {
  double l = 0.0;
  for (const BondRecord& r : bonds_) l = std::max(l, r.length);
  return l;
}

void Bonds::import_records(std::vector<BondRecord> r) {
  std::sort(r.begin(), r.end(), bond_before);
  bonds_ = std::move(r);
  ii_.clear();
  jj_.clear();
  latched_.clear();
}

void Bonds::save_records(BinaryWriter& o, std::vector<BondRecord> r) {
  std::sort(r.begin(), r.end(), bond_before);
  o.vector(r);
}

void Bonds::save(BinaryWriter& o) const { save_records(o, bonds_); }

void Bonds::restore(BinaryReader& in) { import_records(in.vector<BondRecord>()); }

}  // namespace mpdem
