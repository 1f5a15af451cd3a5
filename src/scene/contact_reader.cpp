#include "scene/contact_reader.hpp"

#include <algorithm>
#include <vector>

#include "contact/laws/law_list.hpp"
#include "core/value_range.hpp"
#include "physics/restitution.hpp"
#include "scene/liquid_bridge_reader.hpp"

namespace mpdem {

void check_material(const TomlSection& s, std::string_view k, const std::string& name, const Model& model) {
  if (model.material_index(name) >= 0) return;
  std::string known;
  for (const Material& m : model.materials) known += (known.empty() ? "" : ", ") + m.name;
  s.fail(k, "unknown material '" + name + "' (known: " + (known.empty() ? "none" : known) + ")");
}

namespace {

// The distinct values a law's `law` or `cohesion` key takes over the list, in list order.
template <class Member>
std::vector<std::string_view> law_values(Member member) {
  std::vector<std::string_view> out;
  for_each_law([&]<class L>(std::type_identity<L>, LawId) {
    if (std::find(out.begin(), out.end(), member(std::type_identity<L>{})) == out.end())
      out.push_back(member(std::type_identity<L>{}));
  });
  return out;
}
const std::vector<std::string_view>& law_names() {
  static const auto names = law_values([]<class L>(std::type_identity<L>) { return L::kLaw; });
  return names;
}
const std::vector<std::string_view>& cohesion_names() {
  static const auto names = law_values([]<class L>(std::type_identity<L>) { return L::kCohesion; });
  return names;
}

// "\"a\", \"b\" or \"c\"".
std::string quoted_choices(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    out.append(k == 0 ? "" : k + 1 == names.size() ? " or " : ", ");
    out.append(1, '"').append(names[k]).append(1, '"');
  }
  return out;
}

std::string read_choice(const TomlSection& s, std::string_view key, const std::vector<std::string_view>& names) {
  std::string name = *s.string(key);
  if (std::find(names.begin(), names.end(), name) == names.end())
    s.fail(key, "expected " + quoted_choices(names) + ", got \"" + name + "\"");
  return name;
}

// Every law's own key (law_list.hpp), once, in list order.
const std::vector<const LawKey*>& law_keys() {
  static const std::vector<const LawKey*> keys = [] {
    std::vector<const LawKey*> out;
    for_each_law([&]<class L>(std::type_identity<L>, LawId) {
      for (const LawKey& k : L::kKeys)
        if (std::none_of(out.begin(), out.end(), [&](const LawKey* o) { return o->name == k.name; })) out.push_back(&k);
    });
    return out;
  }();
  return keys;
}

// The keys of a [contact.*] table ([[contact.pair]]: with `materials` and `kind` first).
std::vector<std::string_view> contact_keys(bool pair) {
  std::vector<std::string_view> out;
  if (pair) out = {"materials", "kind", "liquid_bridge"};
  for (const std::string_view k : {"law", "cohesion", "restitution", "damping_ratio", "mu_static", "mu_dynamic",
                                   "mu_rolling", "tangential_damping", "tangential_spring"})
    out.push_back(k);
  for (const LawKey* k : law_keys()) out.push_back(k->name);
  return out;
}

void read_law_selection(const TomlSection& s, std::optional<std::string>& law, std::optional<std::string>& cohesion,
                        LawKeyValues& keys) {
  if (s.has("law")) law = read_choice(s, "law", law_names());
  if (s.has("cohesion")) cohesion = read_choice(s, "cohesion", cohesion_names());
  for (const LawKey* k : law_keys())
    if (const std::optional<double> v = s.number(k->name, k->range)) keys.insert_or_assign(std::string(k->name), *v);
}

// The law and cohesion must name a law of the list, and its required keys must be given.
void check_law(const TomlSection& s, const std::string& law, const std::string& cohesion, const LawKeyValues& keys) {
  const std::string_view at = s.has("law") || !s.has("cohesion") ? "law" : "cohesion";
  const LawId id = find_law(law, cohesion);
  if (id < 0) {
    std::vector<std::string_view> with;
    for_each_law([&]<class L>(std::type_identity<L>, LawId) {
      if (L::kCohesion == cohesion) with.push_back(L::kLaw);
    });
    s.fail(at, "cohesion = \"" + cohesion + "\" needs law = " + quoted_choices(with) + ", got law = \"" + law + "\"");
  }
  with_law(id, [&]<class L>(std::type_identity<L>) {
    for (const LawKey& k : L::kKeys)
      if (k.required && !keys.contains(k.name))
        s.fail(s.has(k.name) ? k.name : at,
               "law = \"" + law + "\"" + (cohesion == "none" ? "" : " with cohesion = \"" + cohesion + "\"") +
                   " needs " + std::string(k.name) + " (" + std::string(k.unit) + ", " + k.range.text() + ")");
  });
}

TangentialSpring read_spring_form(const TomlSection& s) {
  return read_choice(s, "tangential_spring", {"total", "incremental"}) == "total" ? TangentialSpring::Total
                                                                                  : TangentialSpring::Incremental;
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

void read_contact_law(const TomlSection& contact, std::string_view kind, ContactLawParams& c) {
  static const std::vector<std::string_view> kKeys = contact_keys(false);
  const auto s = contact.table(kind, kKeys);
  if (!s) return;
  std::optional<std::string> law, cohesion;
  read_law_selection(*s, law, cohesion, c.law_keys);
  c.law = law.value_or(c.law);
  c.cohesion = cohesion.value_or(c.cohesion);
  if (s->has("tangential_spring")) c.tangential_spring = read_spring_form(*s);
  c.restitution = read_restitution(*s);
  c.damping_ratio = s->number("damping_ratio", kNonNegative);
  if (c.restitution && c.damping_ratio) s->fail("damping_ratio", "give either restitution or damping_ratio, not both");
  s->get("mu_static", c.mu_static, kNonNegative);
  s->get("mu_dynamic", c.mu_dynamic, kNonNegative);
  s->get("mu_rolling", c.mu_rolling, kNonNegative);
  c.tangential_damping = s->number("tangential_damping", kNonNegative);
  check_friction_order(*s, c.mu_static, c.mu_dynamic);
  check_law(*s, c.law, c.cohesion, c.law_keys);
}

// [[contact.pair]] entries; their materials must exist (materials are read first).
void read_contact_pairs(const TomlSection& contact, const Model& model, ContactParams& c) {
  static const std::vector<std::string_view> kKeys = contact_keys(true);
  for (const TomlSection& s : contact.tables("pair", kKeys)) {
    ContactPairParams e;
    e.line = s.line();
    const std::vector<std::string> names = s.require(s.strings("materials", 2), "materials");
    for (const std::string& n : names) check_material(s, "materials", n, model);
    e.material_a = names[0];
    e.material_b = names[1];
    if (s.has("kind")) {
      const std::string k = read_choice(s, "kind", {"particle_particle", "particle_barrier"});
      e.particle_particle = k == "particle_particle";
      e.particle_barrier = k == "particle_barrier";
    }
    read_law_selection(s, e.law, e.cohesion, e.law_keys);
    if (s.has("tangential_spring")) e.tangential_spring = read_spring_form(s);
    e.restitution = read_restitution(s);
    e.damping_ratio = s.number("damping_ratio", kNonNegative);
    if (e.restitution && e.damping_ratio) s.fail("damping_ratio", "give either restitution or damping_ratio, not both");
    e.mu_static = s.number("mu_static", kNonNegative);
    e.mu_dynamic = s.number("mu_dynamic", kNonNegative);
    e.mu_rolling = s.number("mu_rolling", kNonNegative);
    e.tangential_damping = s.number("tangential_damping", kNonNegative);
    if (const auto b = s.table("liquid_bridge", liquid_bridge_keys()))
      e.liquid_bridge = read_pair_liquid_bridge(*b, c.liquid_bridge);
    // Checked against each default table the entry applies to.
    for (const bool pp : {true, false}) {
      if (pp ? !e.particle_particle : !e.particle_barrier) continue;
      const ContactLawParams& d = pp ? c.particle_particle : c.particle_barrier;
      check_friction_order(s, e.mu_static.value_or(d.mu_static), e.mu_dynamic.value_or(d.mu_dynamic));
      LawKeyValues keys = d.law_keys;
      for (const auto& [key, value] : e.law_keys) keys.insert_or_assign(key, value);
      check_law(s, e.law.value_or(d.law), e.cohesion.value_or(d.cohesion), keys);
    }
    c.pairs.push_back(e);
  }
}

}  // namespace

void read_contact(const TomlSection& root, const Model& model, ContactParams& c) {
  read_liquid_bridge(root, c);  // before the pairs, whose bridges override it
  const auto s = root.table("contact", {"particle_particle", "particle_barrier", "pair"});
  if (!s) return;
  read_contact_law(*s, "particle_particle", c.particle_particle);
  read_contact_law(*s, "particle_barrier", c.particle_barrier);
  read_contact_pairs(*s, model, c);
}

}  // namespace mpdem
