#include "scene/contact_reader.hpp"

#include "core/value_range.hpp"
#include "physics/restitution.hpp"

namespace mpdem {

void check_material(const TomlSection& s, std::string_view k, const std::string& name, const Model& model) {
  if (model.material_index(name) >= 0) return;
  std::string known;
  for (const Material& m : model.materials) known += (known.empty() ? "" : ", ") + m.name;
  s.fail(k, "unknown material '" + name + "' (known: " + (known.empty() ? "none" : known) + ")");
}

namespace {

ContactLawKind read_law_kind(const TomlSection& s) {
  const std::string name = *s.string("law");
  if (name == "hertz") return ContactLawKind::Hertz;
  if (name == "linear") return ContactLawKind::Linear;
  s.fail("law", "expected \"hertz\" or \"linear\", got \"" + name + "\"");
}

TangentialSpring read_spring_form(const TomlSection& s) {
  const std::string name = *s.string("tangential_spring");
  if (name == "total") return TangentialSpring::Total;
  if (name == "incremental") return TangentialSpring::Incremental;
  s.fail("tangential_spring", "expected \"total\" or \"incremental\", got \"" + name + "\"");
}

// e in [kMinRestitution, 1]; a smaller e is refused saying why, since it is a plausible input
// (a "perfectly plastic" contact) the calibration cannot serve.
std::optional<double> read_restitution(const TomlSection& s) {
  constexpr Range kRange{kMinRestitution, 1.0, true, true};
  const std::optional<double> e = s.number("restitution");
  if (!e || kRange.contains(*e)) return e;
  std::string why = "expected a number " + kRange.text() + ", got " + number_text(*e);
  if (*e < kMinRestitution)
    why += ": the Hertz damping calibration (physics.md section 5) accepts e >= " + number_text(kMinRestitution) +
           ", since no finite damping ratio gives e = 0 (strongly damped, e falls like 0.2 / xi^2; xi = 14.3 at "
           "e = 0.001); for strongly damped contacts give damping_ratio instead";
  s.fail("restitution", why);
}

// mu_dynamic <= mu_static, naming the key the user gave (or the default).
void check_friction_order(const TomlSection& s, double mu_s, double mu_d) {
  if (mu_d > mu_s)
    s.fail(s.has("mu_dynamic") ? "mu_dynamic" : "mu_static",
           "expected mu_dynamic <= mu_static, got mu_dynamic = " + number_text(mu_d) +
               (s.has("mu_dynamic") ? "" : " (default)") + " > mu_static = " + number_text(mu_s));
}

// The linear law needs its stiffness; the Hertz law takes E and nu from the materials instead.
void check_linear_stiffness(const TomlSection& s, ContactLawKind law, double k_n) {
  if (law == ContactLawKind::Linear && !(k_n > 0.0))
    s.fail(s.has("stiffness_normal") ? "stiffness_normal" : "law",
           "law = \"linear\" needs stiffness_normal (N/m, > 0)");
}

void read_contact_law(const TomlSection& contact, std::string_view kind, ContactLawParams& c) {
  const auto s = contact.table(kind,
                               {"law", "restitution", "damping_ratio", "mu_static", "mu_dynamic", "mu_rolling",
                                "tangential_damping", "stiffness_normal", "stiffness_tangential", "tangential_spring"});
  if (!s) return;
  if (s->has("law")) c.law = read_law_kind(*s);
  if (s->has("tangential_spring")) c.tangential_spring = read_spring_form(*s);
  c.restitution = read_restitution(*s);
  c.damping_ratio = s->number("damping_ratio", kNonNegative);
  if (c.restitution && c.damping_ratio) s->fail("damping_ratio", "give either restitution or damping_ratio, not both");
  s->get("mu_static", c.mu_static, kNonNegative);
  s->get("mu_dynamic", c.mu_dynamic, kNonNegative);
  s->get("mu_rolling", c.mu_rolling, kNonNegative);
  c.tangential_damping = s->number("tangential_damping", kNonNegative);
  s->get("stiffness_normal", c.stiffness_normal, kPositive);
  c.stiffness_tangential = s->number("stiffness_tangential", kNonNegative);
  check_friction_order(*s, c.mu_static, c.mu_dynamic);
  check_linear_stiffness(*s, c.law, c.stiffness_normal);
}

// [[contact.pair]] entries; their materials must exist (materials are read first).
void read_contact_pairs(const TomlSection& contact, const Model& model, ContactParams& c) {
  for (const TomlSection& s : contact.tables(
           "pair", {"materials", "kind", "law", "restitution", "damping_ratio", "mu_static", "mu_dynamic", "mu_rolling",
                    "tangential_damping", "stiffness_normal", "stiffness_tangential", "tangential_spring"})) {
    ContactPairParams e;
    e.line = s.line();
    const std::vector<std::string> names = s.require(s.strings("materials", 2), "materials");
    for (const std::string& n : names) check_material(s, "materials", n, model);
    e.material_a = names[0];
    e.material_b = names[1];
    if (const auto k = s.string("kind")) {
      if (*k != "particle_particle" && *k != "particle_barrier")
        s.fail("kind", "expected \"particle_particle\" or \"particle_barrier\", got \"" + *k + "\"");
      e.particle_particle = *k == "particle_particle";
      e.particle_barrier = *k == "particle_barrier";
    }
    if (s.has("law")) e.law = read_law_kind(s);
    if (s.has("tangential_spring")) e.tangential_spring = read_spring_form(s);
    e.restitution = read_restitution(s);
    e.damping_ratio = s.number("damping_ratio", kNonNegative);
    if (e.restitution && e.damping_ratio) s.fail("damping_ratio", "give either restitution or damping_ratio, not both");
    e.mu_static = s.number("mu_static", kNonNegative);
    e.mu_dynamic = s.number("mu_dynamic", kNonNegative);
    e.mu_rolling = s.number("mu_rolling", kNonNegative);
    e.tangential_damping = s.number("tangential_damping", kNonNegative);
    e.stiffness_normal = s.number("stiffness_normal", kPositive);
    e.stiffness_tangential = s.number("stiffness_tangential", kNonNegative);
    // Checked against each default table the entry applies to.
    for (const bool pp : {true, false}) {
      if (pp ? !e.particle_particle : !e.particle_barrier) continue;
      const ContactLawParams& d = pp ? c.particle_particle : c.particle_barrier;
      check_friction_order(s, e.mu_static.value_or(d.mu_static), e.mu_dynamic.value_or(d.mu_dynamic));
      check_linear_stiffness(s, e.law.value_or(d.law), e.stiffness_normal.value_or(d.stiffness_normal));
    }
    c.pairs.push_back(e);
  }
}

}  // namespace

void read_contact(const TomlSection& root, const Model& model, ContactParams& c) {
  const auto s = root.table("contact", {"particle_particle", "particle_barrier", "pair"});
  if (!s) return;
  read_contact_law(*s, "particle_particle", c.particle_particle);
  read_contact_law(*s, "particle_barrier", c.particle_barrier);
  read_contact_pairs(*s, model, c);
}

}  // namespace mpdem
