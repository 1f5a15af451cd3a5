#include "model/body_members.hpp"

#include "core/parallel.hpp"

namespace mpdem {

namespace {

template <bool kPositions>
void set_members(const std::vector<ClumpTemplate>& clumps, Particles& p) {
  Bodies& B = p.bodies;
  B.index_members(p);
  const std::size_t nb = B.size(), n = p.size();
  // Each body's rotation once, then the members in particle order (the particle arrays stream;
  // the body arrays, a quarter of their size or less, take the random reads).
  std::vector<Mat3>& R = B.rotation;
  R.resize(nb);
#pragma omp parallel for schedule(static) if (nb > kParallelThreshold / 4)
  for (std::size_t b = 0; b < nb; ++b) R[b] = quat_matrix(B.q[b]);
#pragma omp parallel for schedule(static) if (n > kParallelThreshold)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.body[i] == kNoBody) continue;
    const std::size_t b = B.owner[i];
    const Vec3 d = mat_apply(R[b], clumps[static_cast<std::size_t>(B.clump[b])].members()[p.member[i]].x);  // m
    p.v[i] = B.v[b] + cross(B.w[b], d);
    p.w[i] = B.w[b];
    if constexpr (kPositions) {
      p.x[i] = B.x[b] + d;
      p.q[i] = B.q[b];
      p.T[i] = B.T[b];
    }
  }
}

}  // namespace

void add_body(const Model& model, int material, int clump, const BodyInit& init, Particles& p) {
  const Material& mat = model.materials[static_cast<std::size_t>(material)];
  const ClumpTemplate& tpl = model.clumps[static_cast<std::size_t>(clump)];
  Bodies& B = p.bodies;
  const std::size_t b = B.size();
  B.resize(b + 1);
  B.id[b] = init.id;
  B.clump[b] = clump;
  B.material[b] = material;
  B.mass[b] = tpl.body_mass(mat.density);
  B.inertia[b] = tpl.body_inertia(mat.density);
  B.charge[b] = init.charge;
  B.fixed[b] = init.fixed ? 1 : 0;
  B.x[b] = init.x;
  B.v[b] = init.v;
  B.w[b] = init.w;
  B.q[b] = quat_normalized(quat_multiply(init.q, tpl.shape.to_input));
  B.T[b] = init.T;
  const Mat3 R = quat_matrix(B.q[b]);
  for (std::size_t k = 0; k < tpl.members().size(); ++k) {
    const ClumpMember& m = tpl.members()[k];
    const Vec3 d = mat_apply(R, m.x);  // m
    const std::size_t i = p.size();
    p.add(0, material, m.r, mat.density, init.x + d, init.v + cross(init.w, d));
    p.mass[i] = B.mass[b];
    p.inertia[i] = sphere_inertia(B.mass[b], m.r);
    p.charge[i] = init.charge * tpl.share(k);
    p.w[i] = init.w;
    p.q[i] = B.q[b];
    p.T[i] = init.T;
    p.body[i] = init.id;
    p.member[i] = static_cast<std::uint32_t>(k);
  }
}

double represented_mass(const Model& model, const Particles& p, std::size_t i) {
  if (p.body[i] == kNoBody) return p.mass[i];
  const auto b = static_cast<std::size_t>(p.bodies.find(p.body[i]));
  return p.bodies.mass[b] * model.clumps[static_cast<std::size_t>(p.bodies.clump[b])].share(p.member[i]);
}

Vec3 represented_velocity(const Particles& p, std::size_t i) {
  if (p.body[i] == kNoBody) return p.v[i];
  return p.bodies.v[static_cast<std::size_t>(p.bodies.find(p.body[i]))];
}

void place_members(const std::vector<ClumpTemplate>& clumps, Particles& p) { set_members<true>(clumps, p); }
void move_members(const std::vector<ClumpTemplate>& clumps, Particles& p) { set_members<false>(clumps, p); }

}  // namespace mpdem
