#include "io/scene_fingerprint.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

#include "io/fingerprint_hash.hpp"

namespace mpdem {

namespace {

using namespace fingerprint;

FingerprintPart materials_part(const std::vector<Material>& materials) {
  static constexpr const char* kFields[] = {"name",          "density",    "young",  "poisson",    "conductivity",
                                            "heat_capacity", "emissivity", "charge", "temperature"};
  constexpr std::size_t kPer = std::size(kFields);
  FingerprintPart p{"materials", {}, 0, kPer, "materials", {}};
  std::vector<std::string> names;
  for (const Material& m : materials) {
    p.items.push_back(hash_of(m.name, m.variant_of));
    for (const double v :
         {m.density, m.young, m.poisson, m.conductivity, m.heat_capacity, m.emissivity, m.charge, m.temperature})
      p.items.push_back(hash_of(v));
    names.push_back(m.variant_of < 0 ? "'" + m.name + "'" : "'" + m.name + "' (a CSV row's own values)");
  }
  p.label = [names = std::move(names)](std::size_t k) {
    const std::size_t m = k / kPer, f = k % kPer;
    if (f == 0) return "the name of material " + std::to_string(m + 1) + ", " + names[m];
    return "material " + names[m] + ": " + kFields[f];
  };
  return p;
}

// Scenes built in code may leave an element's group unnamed.
std::string group_name(const std::vector<std::string>& names, int g) {
  return g >= 0 && static_cast<std::size_t>(g) < names.size() ? names[static_cast<std::size_t>(g)] : "";
}

FingerprintPart barriers_part(const Barriers& b) {
  static constexpr const char* kAspects[] = {"id or group", "rest vertices", "motion law",
                                             "young, poisson, thickness or temperature"};
  constexpr std::size_t kPer = std::size(kAspects);
  FingerprintPart p{"barriers", {}, 0, kPer, "barrier elements", {}};
  p.items.reserve(b.size() * kPer);
  for (std::size_t e = 0; e < b.size(); ++e) {
    const std::string group = group_name(b.group_names, b.group[e]);
    const MotionLaw& m = b.motion[e];
    p.items.push_back(hash_of(b.id[e], group));
    p.items.push_back(hash_of(b.p0[e], b.p1[e], b.p2[e]));
    std::uint64_t motion = hash_of(m.a, m.A, m.w1, m.B, m.w2);
    if (m.rotation) {  // a scene without rotations keeps the hashes it had before rotations existed
      Hash h;
      h.add(motion);
      h.add(m.rotation->axis);
      h.add(m.rotation->origin);
      h.add(m.rotation->omega);
      h.add(std::uint64_t{m.rotation->omega_table.size()});
      for (const auto& row : m.rotation->omega_table) {
        h.add(row[0]);
        h.add(row[1]);
      }
      if (m.rotation->since != 0.0) h.add(m.rotation->since);
      motion = h.value();
    }
    if (m.timed() || m.since != 0.0) {  // the default window and origin keep the earlier hashes
      Hash h;
      h.add(motion);
      h.add(m.active_from);
      h.add(m.active_until);
      h.add(m.since);
      motion = h.value();
    }
    p.items.push_back(motion);
    p.items.push_back(hash_of(b.young[e], b.poisson[e], b.thickness[e], b.temperature[e]));
  }
  p.label = [ids = b.id, group = b.group, names = b.group_names](std::size_t k) {
    const std::size_t e = k / kPer;
    return "element id " + std::to_string(ids[e]) + " of group '" + group_name(names, group[e]) +
           "': " + kAspects[k % kPer];
  };
  return p;
}

// Mass and inertia are left out: they follow from the radius and the material's density, which
// the materials part holds (a changed density is then reported once, as a material's).
FingerprintPart particles_part(const Particles& q) {
  FingerprintPart p{"particle sources", {}, 0, 1, "particles", {}};
  p.items.reserve(q.size());
  for (std::size_t i = 0; i < q.size(); ++i)
    p.items.push_back(hash_of(q.id[i], q.material[i], q.radius[i], q.charge[i], q.x[i], q.v[i], q.w[i], q.q[i], q.T[i],
                              q.fixed[i] != 0));
  p.label = [ids = q.id](std::size_t k) { return "particle id " + std::to_string(ids[k]); };
  return p;
}

FingerprintPart domain_part(const DomainParams& d) {
  KeyedPart k("domain");
  k.key("[domain] given or not", d.bounded);
  k.key("domain.min", d.bounded ? d.min : Vec3{});
  k.key("domain.max", d.bounded ? d.max : Vec3{});
  k.key("domain.periodic", d.periodic[0], d.periodic[1], d.periodic[2]);
  return k.finish();
}

void law_keys(KeyedPart& k, const std::string& kind, const ContactLawParams& c) {
  const std::string s = "contact." + kind + ".";
  k.key(s + "law", c.law);
  k.key(s + "cohesion", c.cohesion);
  // The law's own keys as one item, labelled by the keys given ("stiffness_normal/stiffness_tangential").
  std::string given;
  for (const auto& [name, value] : c.law_keys) given += (given.empty() ? "" : "/") + name;
  k.key(s + (given.empty() ? "law keys" : given), c.law_keys);
  k.key(s + "restitution", c.restitution);
  k.key(s + "damping_ratio", c.damping_ratio);
  k.key(s + "mu_static", c.mu_static);
  k.key(s + "mu_dynamic", c.mu_dynamic);
  k.key(s + "mu_rolling", c.mu_rolling);
  k.key(s + "tangential_damping", c.tangential_damping);
  k.key(s + "tangential_spring", c.tangential_spring);
}

// One liquid_bridge table's keys as one item, after `base` (the item it belongs to, or 0).
std::uint64_t bridge_hash(std::uint64_t base, const LiquidBridgeKeys& b) {
  return hash_of(base, b.model, b.surface_tension, b.contact_angle, b.volume, b.liquid_fraction, b.viscosity,
                 b.min_gap);
}

FingerprintPart contact_part(const ContactParams& c) {
  KeyedPart k("contact laws");
  law_keys(k, "particle_particle", c.particle_particle);
  law_keys(k, "particle_barrier", c.particle_barrier);
  // Only with bridges, so that the scenes without them keep their fingerprints.
  if (const auto& d = c.liquid_bridge.defaults) k.key("[liquid_bridge]", bridge_hash(0, *d), c.liquid_bridge.barriers);
  std::vector<std::string> labels;
  for (const ContactPairParams& e : c.pairs) {
    const std::uint64_t item = hash_of(e.material_a, e.material_b, e.particle_particle, e.particle_barrier, e.law,
                                       e.cohesion, e.law_keys, e.restitution, e.damping_ratio, e.mu_static,
                                       e.mu_dynamic, e.mu_rolling, e.tangential_damping, e.tangential_spring);
    k.part().items.push_back(e.liquid_bridge ? bridge_hash(item, *e.liquid_bridge) : item);
    labels.push_back("[[contact.pair]] '" + e.material_a + "'-'" + e.material_b + "'");
  }
  return k.finish("[[contact.pair]] entries", std::move(labels));
}

FingerprintPart physics_part(const Params& prm) {
  KeyedPart k("physics");
  k.key("analysis.rotation", prm.analysis.rotation);
  k.key("analysis.thermal", prm.analysis.thermal);
  k.key("gravity.vector", prm.fields.gravity);
  k.key("fields.electric", prm.fields.electric);
  k.key("fields.magnetic", prm.fields.magnetic);
  const NearFieldParams& nf = prm.near_field;
  k.key("near_field.empirical", nf.empirical);
  k.key("near_field.a1", nf.a1);
  k.key("near_field.b1", nf.b1);
  k.key("near_field.a2", nf.a2);
  k.key("near_field.b2", nf.b2);
  k.key("near_field.coulomb", nf.coulomb);
  k.key("near_field.permittivity", nf.permittivity);
  k.key("near_field.cutoff", nf.cutoff);
  const ThermalParams& th = prm.thermal;
  k.key("thermal.air_temperature", th.air_temperature);
  k.key("thermal.air_velocity", th.air_velocity);
  k.key("thermal.environment_temperature", th.environment_temperature);
  k.key("thermal.conduction", th.conduction);
  k.key("thermal.convection", th.convection);
  k.key("thermal.radiation", th.radiation);
  if (prm.fields.drag != 0.0) k.key("fields.drag", prm.fields.drag);  // keeps the others' fingerprints
  std::vector<std::string> labels;
  for (const NearFieldPair& e : nf.pairs) {
    k.part().items.push_back(hash_of(e.material_a, e.material_b, e.a1, e.b1, e.a2, e.b2));
    labels.push_back("[[near_field.pair]] '" + e.material_a + "'-'" + e.material_b + "'");
  }
  return k.finish("[[near_field.pair]] entries", std::move(labels));
}

// Every inlet and sink, one item each over all its keys (the end defaults to time.duration, which
// stays editable: an inlet without `end` follows a longer run).
FingerprintPart open_boundaries_part(const Params& prm) {
  FingerprintPart p{"inlets and sinks", {}, 0, 1, "[[inlet]] and [[sink]] entries", {}};
  std::vector<std::string> labels;
  const auto region_hash = [](Hash& h, const RegionSpec& r) {
    h.add(r.shape);
    h.add(r.min);
    h.add(r.max);
    h.add(r.base);
    h.add(r.axis);
    h.add(r.radius);
  };
  for (const InletSpec& s : prm.inlets) {
    Hash h;
    h.add(s.name);
    h.add(s.volume.shape);
    region_hash(h, s.volume.region);
    for (const Vec3& v : {s.volume.origin, s.volume.u, s.volume.v, s.volume.w, s.velocity}) h.add(v);
    for (const double v : {s.mass_rate, s.count_rate, s.start, s.interval, s.velocity_spread}) h.add(v);
    h.add(s.end);
    const RadiusDistribution& d = s.radius;
    h.add(d.law);
    for (const double v : {d.value, d.min, d.max, d.mean, d.std}) h.add(v);
    h.add(std::uint64_t{d.radii.size()});
    for (std::size_t k = 0; k < d.radii.size(); ++k) h.add(d.radii[k]);
    h.add(std::uint64_t{d.fractions.size()});
    for (std::size_t k = 0; k < d.fractions.size(); ++k) h.add(d.fractions[k]);
    h.add(d.mass_fractions);
    h.add(s.material);
    h.add(s.seed);
    h.add(std::uint64_t{s.max_attempts});
    for (std::size_t k = 0; k < s.clump.clumps.size(); ++k) {  // none for spheres: their fingerprint is kept
      h.add(std::int64_t{s.clump.clumps[k]});
      h.add(s.clump.fractions[k]);
    }
    p.items.push_back(h.value());
    labels.push_back("[[inlet]] '" + s.name + "'");
  }
  for (const SinkSpec& s : prm.sinks) {
    Hash h;
    h.add(s.name);
    region_hash(h, s.region);
    p.items.push_back(h.value());
    labels.push_back("[[sink]] '" + s.name + "'");
  }
  p.label = [labels = std::move(labels)](std::size_t k) { return labels[k]; };
  return p;
}

// The scheme decides what the checkpoint's contact history holds (the trapezoidal rule's
// step-start values) and what its dt means; the step lengths themselves stay editable.
FingerprintPart integration_part(const TimeParams& t) {
  KeyedPart k("time integration");
  k.key("time.integrator", t.integrator);
  k.key("time.phi", t.phi);
  k.key("time.adaptive", t.adaptive);
  return k.finish();
}

// [bonds] per key and each [[bonds.pair]] entry (only in a scene with bonds: the others keep
// their fingerprints).
FingerprintPart bonds_part(const BondParams& b) {
  KeyedPart k("bonds");
  const BondKeys& d = *b.defaults;
  k.key("bonds.radius_ratio", d.radius_ratio);
  k.key("bonds.young", d.young);
  k.key("bonds.stiffness_ratio", d.stiffness_ratio);
  k.key("bonds.tensile_strength", d.tensile_strength);
  k.key("bonds.shear_strength", d.shear_strength);
  k.key("bonds.damping", d.damping);
  k.key("bonds.gap", d.gap);
  const std::size_t keys = k.part().items.size();
  std::vector<std::string> labels;
  for (const BondPairParams& e : b.pairs) {
    const BondKeys& o = e.keys;
    k.part().items.push_back(hash_of(e.material_a, e.material_b, o.radius_ratio, o.young, o.stiffness_ratio,
                                     o.tensile_strength, o.shear_strength, o.damping, o.gap, o.bonded));
    labels.push_back("[[bonds.pair]] '" + e.material_a + "'-'" + e.material_b + "'");
  }
  FingerprintPart p = k.finish("[[bonds.pair]] entries", std::move(labels));
  p.fixed = keys;  // the entries follow the keys: a changed count is reported as such
  return p;
}

// The bond CSV's bonds, one item each, as id pairs (smaller id first) in ascending order: the
// same bonds listed in another order or orientation are the same scene.
FingerprintPart listed_bonds_part(const BondParams& b) {
  std::vector<std::pair<std::int64_t, std::int64_t>> ids;
  for (const ListedBond& l : b.listed) ids.push_back(std::minmax(l.id_i, l.id_j));
  std::sort(ids.begin(), ids.end());
  FingerprintPart p{"listed bonds", {}, 0, 1, "bonds in the bond CSV", {}};
  for (const auto& [i, j] : ids) p.items.push_back(hash_of(i, j));
  p.label = [ids = std::move(ids)](std::size_t k) {
    return "the bond between ids " + std::to_string(ids[k].first) + " and " + std::to_string(ids[k].second);
  };
  return p;
}

}  // namespace

SceneFingerprint fingerprint_scene(const Scene& scene) {
  const Params& prm = scene.model.params;
  SceneFingerprint f;
  f.parts.push_back(materials_part(scene.model.materials));
  f.parts.push_back(barriers_part(scene.barriers));
  f.parts.push_back(particles_part(scene.particles));
  f.parts.push_back(domain_part(prm.domain));
  f.parts.push_back(contact_part(prm.contact));
  f.parts.push_back(physics_part(prm));
  f.parts.push_back(integration_part(prm.time));
  f.parts.push_back(open_boundaries_part(prm));
  if (prm.bonds.enabled()) {
    f.parts.push_back(bonds_part(prm.bonds));
    f.parts.push_back(listed_bonds_part(prm.bonds));
  }
  return f;
}

}  // namespace mpdem
