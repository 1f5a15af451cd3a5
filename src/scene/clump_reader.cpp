#include "scene/clump_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/input_error.hpp"
#include "core/input_file.hpp"
#include "io/csv_log.hpp"
#include "io/csv_table.hpp"
#include "model/derived_limits.hpp"
#include "model/body_members.hpp"
#include "generate/generated_bodies.hpp"

namespace mpdem {

namespace {

constexpr std::array<std::string_view, 4> kMemberColumns = {"x", "y", "z", "radius"};

// Members from a CSV file with columns x, y, z, radius (m).
std::vector<ClumpMember> members_from_csv(const std::filesystem::path& file) {
  const CsvTable t = CsvTable::read(file, kMemberColumns.size());
  t.check_known(kMemberColumns);
  for (std::string_view c : kMemberColumns) t.require(c);
  const int cx = t.column("x"), cy = t.column("y"), cz = t.column("z"), cr = t.column("radius");
  std::vector<ClumpMember> out;
  for (const CsvRow& row : t.rows())
    out.push_back(
        {{t.number(row, cx), t.number(row, cy), t.number(row, cz)}, t.number(row, cr, kPositive, "a radius")});
  if (out.empty()) throw InputError(t.file(), t.header_line(), "", "expected at least one member row");
  return out;
}

// Members given inline: [[x, y, z, radius], ...] (m); a bad row is reported at its own line.
std::vector<ClumpMember> members_inline(const TomlSection& s) {
  static constexpr std::array<Range, 4> kRanges = {kAnyValue, kAnyValue, kAnyValue, kPositive};
  const auto rows = s.number_rows("members", kMemberColumns, kRanges,
                                  "[[0.0, -0.001, 0.0, 0.001], [0.0, 0.001, 0.0, 0.001]] (m), or the name of a CSV "
                                  "file with columns x,y,z,radius");
  std::vector<ClumpMember> out;
  for (const std::vector<double>& v : *rows) out.push_back({{v[0], v[1], v[2]}, v[3]});
  return out;
}

// The template's volume and principal moments per unit density must be usable: members of
// radius 1e200 m (or 1e-200 m) make them overflow (underflow).
void check_template_size(const TomlSection& s, const ClumpMassProperties& shape) {
  std::string why = usable_problem(shape.volume, "the volume of the union of the members", "m^3");
  for (int k = 0; k < 3 && why.empty(); ++k)
    why = usable_problem(shape.principal[k], "principal moment " + std::to_string(k + 1) + " per unit density", "m^5");
  if (!why.empty()) s.fail("members", why + "; expected member radii and positions of a usable size");
}

// The mass and principal moments of a body of template t and material mat must be usable.
std::string body_mass_problem(const ClumpTemplate& t, const Material& mat) {
  std::string why = usable_problem(t.body_mass(mat.density), "the body mass", "kg");
  const Vec3 I = t.body_inertia(mat.density);
  for (int k = 0; k < 3 && why.empty(); ++k)
    why = usable_problem(I[k], "principal moment I" + std::to_string(k + 1), "kg m^2");
  if (why.empty()) return "";
  return "clump '" + t.name + "' of material '" + mat.name + "' (density " + number_text(mat.density) +
         " kg/m^3): " + why + "; expected a mass and moments the run can divide by";
}

}  // namespace

// ": known clumps: a, b" (or that none is defined), for an unknown clump name.
std::string known_clumps(const Model& model) {
  if (model.clumps.empty()) return " (no [[clump]] is defined)";
  std::string out = " (known:";
  for (const ClumpTemplate& c : model.clumps) out += " " + c.name;
  return out + ")";
}

ClumpMix read_clump_mix(const TomlSection& s, std::string_view k, const Model& model) {
  ClumpMix mix;
  const toml::node* n = s.node(k);
  const auto index = [&](const std::string& name, std::size_t line, const std::string& key) {
    const int c = model.clump_index(name);
    if (c < 0) throw InputError(s.file(), line, key, "unknown clump '" + name + "'" + known_clumps(model));
    return c;
  };
  if (n->is_string()) {
    mix.clumps.push_back(index(*s.string(k), s.line_of(k), s.key(k)));
    mix.fractions.push_back(1.0);
    return mix;
  }
  const toml::table* t = n->as_table();
  constexpr const char* kExample = "a string (a clump name) or a table of clump names and number fractions, e.g. "
                                   "{ tetra = 0.7, dumbbell = 0.3 }";
  if (!t) s.fail(k, std::string("expected ") + kExample);
  if (t->empty()) s.fail(k, std::string("expected at least one clump name in the table: ") + kExample);
  // The names in the order written (a TOML table iterates by name): the order of the draw.
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (auto&& [name, value] : *t) entries.emplace_back(&name, &value);
  std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const toml::source_position pa = a.first->source().begin, pb = b.first->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  std::vector<std::string_view> names;
  names.reserve(entries.size());
  for (const auto& e : entries) names.push_back(e.first->str());
  const TomlSection table(s.file(), *t, s.key(k), names);
  double sum = 0.0;
  for (const std::string_view name : names) {
    mix.clumps.push_back(index(std::string(name), table.line_of(name), table.key(name)));
    mix.fractions.push_back(*table.number(name, kPositive));
    sum += mix.fractions.back();
  }
  if (!(std::abs(sum - 1.0) <= 1e-9))
    s.fail(k, "expected number fractions that sum to 1 (within 1e-9), got the sum " + number_text(sum));
  return mix;
}

std::string clump_mix_mass_problem(const ClumpMix& mix, const Model& model, int material) {
  const Material& mat = model.materials[static_cast<std::size_t>(material)];
  for (const int c : mix.clumps)
    if (std::string why = body_mass_problem(model.clumps[static_cast<std::size_t>(c)], mat); !why.empty()) return why;
  return "";
}

void read_clump_templates(const TomlSection& root, const std::filesystem::path& dir, Model& model) {
  for (const TomlSection& s : root.tables("clump", {"name", "members", "mass", "inertia"})) {
    ClumpTemplate t;
    t.origin = root.file();
    t.line = s.line();
    t.name = s.require(s.string("name"), "name");
    if (t.name.empty()) s.fail("name", "expected a template name, got an empty string");
    // The name is a field of the body CSV snapshots (io/body_csv_writer.hpp).
    if (!is_column_name(t.name))
      s.fail("name", "expected a template name without ',', '\"' or line breaks, got \"" + t.name + "\"");
    if (model.clump_index(t.name) >= 0) s.fail("name", "clump '" + t.name + "' is defined twice");
    if (!s.has("members")) s.fail("members", "missing required key");
    std::vector<ClumpMember> members;
    if (s.node("members")->is_string()) {
      const std::string name = *s.string("members");
      if (name.empty()) s.fail("members", "expected a CSV file name (columns x,y,z,radius), got an empty string");
      const std::filesystem::path p = (dir / std::filesystem::path(name)).lexically_normal();
      if (const std::string why = input_file_problem(p); !why.empty())
        s.fail("members", "file '" + p.string() + "' " + why);
      members = members_from_csv(p);
    } else {
      members = members_inline(s);
    }
    try {
      t.shape = clump_mass_properties(members);
    } catch (const std::invalid_argument& e) {
      s.fail("members", e.what());
    }
    check_template_size(s, t.shape);
    if (s.has("mass")) t.mass = s.number("mass", kPositive);
    if (s.has("inertia")) {
      const std::vector<double> I = *s.numbers("inertia", 3, 3);
      for (double v : I)
        if (!(v > 0.0) || !std::isfinite(v)) s.fail("inertia", "expected three principal moments > 0 (kg m^2)");
      // The principal moments of a rigid body obey the triangle inequality.
      const double sum = I[0] + I[1] + I[2], largest = std::max({I[0], I[1], I[2]});
      if (largest > 0.5 * sum * (1.0 + 1e-12))
        s.fail("inertia", "no rigid body has these principal moments: the largest exceeds the sum of the other two");
      t.inertia = Vec3{I[0], I[1], I[2]};
    }
    model.clumps.push_back(std::move(t));
  }
}

void read_clump_bodies(const std::filesystem::path& file, const Model& model, int material, int clump, Particles& out) {
  // The columns read (by position in this list: col[] below), then the ones accepted and ignored:
  // `radius` (a sphere CSV's), and a body CSV snapshot's descriptive columns (io/body_csv_writer.hpp:
  // time, the template's name, the mass and principal moments, which the template and material give),
  // so that a snapshot seeds a new scene as it is.
  static constexpr std::array<std::string_view, 24> kColumns = {
      "id", "x",  "y",     "z",           "q0",     "q1",     "q2",   "q3",    "vx",   "vy", "vz", "wx",
      "wy", "wz", "fixed", "temperature", "charge", "radius", "time", "clump", "mass", "I1", "I2", "I3"};
  const CsvTable t = CsvTable::read(file, kColumns.size());
  t.check_known(kColumns);
  for (std::string_view c : {"id", "x", "y", "z"}) t.require(c);
  std::array<int, kColumns.size()> col{};
  for (std::size_t c = 0; c < kColumns.size(); ++c) col[c] = t.column(kColumns[c]);
  const bool with_q = col[4] >= 0 || col[5] >= 0 || col[6] >= 0 || col[7] >= 0;
  if (with_q)
    for (std::size_t c = 4; c < 8; ++c)
      if (col[c] < 0)
        throw InputError(t.file(), t.header_line(), std::string(kColumns[c]),
                         "missing column: the orientation takes all of q0, q1, q2, q3 (unit quaternion w, x, y, z) "
                         "or none (identity)");
  const Material& mat = model.materials[static_cast<std::size_t>(material)];
  if (const std::string why = body_mass_problem(model.clumps[static_cast<std::size_t>(clump)], mat); !why.empty())
    throw InputError(t.file(), t.header_line(), "", why);
  // Body ids are unique across all body files: the ids read before this file, and this file's
  // ids with their lines.
  const std::set<std::int64_t> earlier(out.bodies.id.begin(), out.bodies.id.end());
  std::map<std::int64_t, std::size_t> here;
  for (const CsvRow& row : t.rows()) {
    const auto num = [&](std::size_t c, double fallback) {
      return t.number_or(row, col[c], fallback, kAnyValue, "a number");
    };
    BodyInit init;
    init.id = t.integer(row, col[0]);
    if (init.id < 0) t.fail(row, col[0], "expected a body id >= 0, got " + std::to_string(init.id));
    if (earlier.count(init.id))
      t.fail(row, col[0],
             "body id " + std::to_string(init.id) + " is given twice (also by an earlier [[particles]] entry)");
    if (const auto [at, fresh] = here.emplace(init.id, row.line); !fresh)
      t.fail(row, col[0],
             "body id " + std::to_string(init.id) + " is given twice (also at line " + std::to_string(at->second) +
                 ")");
    init.x = {t.number(row, col[1]), t.number(row, col[2]), t.number(row, col[3])};
    init.v = {num(8, 0.0), num(9, 0.0), num(10, 0.0)};
    init.w = {num(11, 0.0), num(12, 0.0), num(13, 0.0)};
    init.T = t.number_or(row, col[15], mat.temperature, kPositive, "a temperature > 0 (K)");
    init.charge = num(16, mat.charge);
    if (!t.missing(row, col[14])) {
      const std::int64_t f = t.integer(row, col[14]);
      if (f != 0 && f != 1) t.fail(row, col[14], "expected 0 or 1");
      init.fixed = f == 1;
    }
    if (with_q) {
      const Quat q{t.number(row, col[4]), t.number(row, col[5]), t.number(row, col[6]), t.number(row, col[7])};
      const double n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
      if (std::abs(n2 - 1.0) > 1e-6)
        t.fail(row, col[4],
               "expected a unit quaternion (q0^2 + q1^2 + q2^2 + q3^2 = 1 within 1e-6), got norm^2 " +
                   std::to_string(n2));
      init.q = quat_normalized(q);
    }
    add_body(model, material, clump, init, out);
  }
  if (t.rows().empty()) throw InputError(t.file(), t.header_line(), "", "expected at least one body row");
}

void generate_clump_bodies(const GenerateSpec& spec, const Model& model, int material, const ClumpMix& mix,
                           Particles& out) {
  if (!spec.material.empty()) material = model.material_index(spec.material);  // checked when read
  if (const std::string why = clump_mix_mass_problem(mix, model, material); !why.empty())
    throw InputError(spec.origin, spec.line, "particles.generate", why);
  add_generated_bodies(spec, model, material, mix, out);
}

void assign_member_ids(Particles& p, const std::string& origin) {
  Bodies& B = p.bodies;
  if (B.empty()) return;
  std::map<std::int64_t, std::size_t> seen;
  for (std::size_t b = 0; b < B.size(); ++b)
    if (!seen.emplace(B.id[b], b).second)  // the body CSV reader names the row; this guards bodies added in code
      throw InputError(origin, 0, "particles", "clump body id " + std::to_string(B.id[b]) + " is given twice");
  std::int64_t next = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.body[i] == kNoBody) next = std::max(next, p.id[i] + 1);
  B.index_members(p);
  for (std::size_t b = 0; b < B.size(); ++b)
    for (std::uint32_t s = B.first[b]; s < B.first[b + 1]; ++s) p.id[B.index[s]] = next++;
}

}  // namespace mpdem
