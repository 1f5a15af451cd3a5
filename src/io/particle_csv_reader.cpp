// Particle CSV reader (docs/scene.md "Particle CSV").
#include "io/particle_csv_reader.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <limits>
#include <string_view>
#include <unordered_map>

#include "io/csv_table.hpp"
#include "core/input_error.hpp"
#include "model/derived_limits.hpp"
#include "model/material_variants.hpp"
#include "state/particle_columns.hpp"

namespace mpdem {

namespace {

// The columns the reader knows: the particle column table's input columns (state/particle_columns.hpp),
// the material constants a row may give for itself, then the columns a particle CSV snapshot
// writes only as output (docs/output.md: time, the force, a periodic run's image counts and
// unwrapped centre), which are skipped so that a snapshot seeds a new scene as it is.
constexpr std::array<std::string_view, 6> kMaterialColumns = {"density",       "young",        "poisson",
                                                              "heat_capacity", "conductivity", "emissivity"};

template <class Add>
constexpr void for_each_known_column(Add&& add) {
  for_each_particle_column([&](const auto& c) {
    if (c.csv_role == CsvRole::input)
      for (std::size_t k = 0; k < c.components; ++k) add(c.csv[k]);
  });
  for (std::string_view m : kMaterialColumns) add(m);
  add(kCsvTime);
  for_each_particle_column([&](const auto& c) {
    if (c.csv_role == CsvRole::output || c.csv_role == CsvRole::periodic)
      for (std::size_t k = 0; k < c.components; ++k) add(c.csv[k]);
  });
  for (std::string_view u : kCsvUnwrapped) add(u);
}

constexpr std::size_t known_column_count() {
  std::size_t n = 0;
  for_each_known_column([&n](std::string_view) { ++n; });
  return n;
}

constexpr auto known_columns() {
  std::array<std::string_view, known_column_count()> out{};
  std::size_t k = 0;
  for_each_known_column([&](std::string_view name) { out[k++] = name; });
  return out;
}
constexpr auto kColumns = known_columns();

// Column indices (-1 when absent), looked up once per file; the table's columns by their array.
struct Cols {
  int id, x, y, z, vx, vy, vz, wx, wy, wz, radius, material, density, young, poisson, charge, temperature,
      heat_capacity, conductivity, emissivity, fixed;
  explicit Cols(const CsvTable& t)
      : id(col(t, &Particles::id)), x(col(t, &Particles::x, 0)), y(col(t, &Particles::x, 1)),
        z(col(t, &Particles::x, 2)), vx(col(t, &Particles::v, 0)), vy(col(t, &Particles::v, 1)),
        vz(col(t, &Particles::v, 2)), wx(col(t, &Particles::w, 0)), wy(col(t, &Particles::w, 1)),
        wz(col(t, &Particles::w, 2)), radius(col(t, &Particles::radius)), material(col(t, &Particles::material)),
        density(t.column("density")), young(t.column("young")), poisson(t.column("poisson")),
        charge(col(t, &Particles::charge)), temperature(col(t, &Particles::T)),
        heat_capacity(t.column("heat_capacity")), conductivity(t.column("conductivity")),
        emissivity(t.column("emissivity")), fixed(col(t, &Particles::fixed)) {}

  template <class T>
  static int col(const CsvTable& t, std::vector<T> Particles::*array, std::size_t component = 0) {
    return t.column(csv_name(array, component));
  }
};

// The row's material: a name, or an integer index into the scene's [[material]] list.
int row_material(const CsvTable& t, const CsvRow& row, int col, const Model& model, int fallback) {
  if (t.missing(row, col)) return fallback;
  const std::string& s = t.text(row, col);
  if (const int m = model.material_index(s); m >= 0) return m;
  int idx = -1;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), idx);
  if (ec == std::errc() && ptr == s.data() + s.size() && idx >= 0 && idx < static_cast<int>(model.materials.size()))
    return idx;
  std::string known;
  for (const Material& m : model.materials) known += (known.empty() ? "" : ", ") + m.name;
  t.fail(row, col, "unknown material '" + s + "' (expected a material name or index; known: " + known + ")");
}

// Values each in range can still make the mass, the contact moduli or the time scales over- or
// underflow (model/derived_limits.hpp). Names the row's column where the culprit is the row's
// value, else the material's key.
void check_derived(const CsvTable& t, const CsvRow& row, const Cols& c, std::int64_t pid, double r, const Material& own,
                   bool thermal) {
  const auto fail = [&](int col, const char* key, const std::string& problem) {
    const std::string from = t.missing(row, col) ? " (the " + std::string(key) + " of material '" + own.name + "')"
                                                 : "";
    throw InputError(t.file(), row.line, key, "particle id " + std::to_string(pid) + ": " + problem + from);
  };
  const bool own_young = !t.missing(row, c.young);
  if (const std::string p = contact_moduli_problem(own.young, own.poisson); !p.empty()) {
    if (own_young || t.missing(row, c.poisson)) fail(c.young, "young", p);
    else fail(c.poisson, "poisson", p);
  }
  if (const std::string p = mass_problem(r, own.density); !p.empty()) {
    if (radius_powers_usable(r)) fail(c.density, "density", p);  // the radius alone is fine
    else fail(c.radius, "radius", p);
  }
  if (const std::string p = time_scale_problem(r, own.density, own.young, own.poisson); !p.empty()) {
    if (own_young) fail(c.young, "young", p);
    else fail(c.radius, "radius", p);
  }
  if (thermal)
    if (const std::string p = thermal_mass_problem(r, own.density, own.heat_capacity); !p.empty())
      fail(c.heat_capacity, "heat_capacity", p);
}

// The row's `fixed` flag: exactly 0 or 1 (an empty field or no column: 0). Anything else - 2,
// "yes", "1.0" - is refused rather than read as true, so a misspelt flag cannot pin a particle.
std::uint8_t row_fixed(const CsvTable& t, const CsvRow& row, int col) {
  if (t.missing(row, col)) return 0;
  const std::string& s = t.text(row, col);
  if (s == "0" || s == "1") return s == "1" ? 1 : 0;
  t.fail(row, col, "expected 0 (free) or 1 (fixed: moves with its given velocity), got '" + s + "'");
}

// Value of an optional numeric column, else `fallback` (velocities default to rest).
double value_or(const CsvTable& t, const CsvRow& row, int col, double fallback) {
  return t.missing(row, col) ? fallback : t.number(row, col);
}

}  // namespace

void read_particle_csv(const std::filesystem::path& file, Model& model, int default_material, Particles& out) {
  const CsvTable t = CsvTable::read(file, kColumns.size());
  t.check_known(kColumns);
  for (std::size_t k = 0; k < 3; ++k) t.require(csv_name(&Particles::x, k));
  t.require(csv_name(&Particles::radius, 0));
  if (model.materials.empty())
    throw InputError(t.file(), 0, "", "no [[material]] is defined, so particles have no default properties");
  if (default_material < 0 || default_material >= static_cast<int>(model.materials.size())) default_material = 0;
  const Cols c(t);
  MaterialVariants variants(model, t.file());

  // Ids must be unique across all files; rows without one continue after the largest seen.
  // Clump members read so far carry no id yet (assign_member_ids numbers them after every free
  // sphere), so only the free spheres' ids are taken.
  std::unordered_map<std::int64_t, std::size_t> seen;  // id -> line in this file (0 = earlier file)
  std::int64_t next_id = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out.body[i] != kNoBody) continue;
    seen.emplace(out.id[i], 0);
    next_id = std::max(next_id, out.id[i] + 1);
  }

  for (const CsvRow& row : t.rows()) {
    const int mat = row_material(t, row, c.material, model, default_material);
    const Material m = model.materials[mat];  // a copy: variants.find may add materials
    std::int64_t pid = next_id;
    if (!t.missing(row, c.id)) {
      pid = t.integer(row, c.id);
      if (const auto it = seen.find(pid); it != seen.end())
        t.fail(row, c.id,
               "duplicate particle id " + std::to_string(pid) +
                   (it->second > 0 ? " (first on line " + std::to_string(it->second) + ")"
                                   : " (already used by an earlier particle file)"));
    }
    // The largest int64 would leave no "next free id" (and overflow computing it).
    if (pid == std::numeric_limits<std::int64_t>::max())
      t.fail(row, c.id,
             "particle id " + std::to_string(pid) + " leaves no next free id; expected ids < " + std::to_string(pid));
    seen.emplace(pid, row.line);
    next_id = std::max(next_id, pid + 1);

    const double r = t.number(row, c.radius, kPositive, "a radius");
    const double rho = t.number_or(row, c.density, m.density, kPositive, "a density");
    const double E = t.number_or(row, c.young, m.young, kPositive, "a Young's modulus");
    const double nu = t.number_or(row, c.poisson, m.poisson, kPoissonRange, "a Poisson ratio");
    const double cap = t.number_or(row, c.heat_capacity, m.heat_capacity, kPositive, "a heat capacity");
    const double k = t.number_or(row, c.conductivity, m.conductivity, kNonNegative, "a conductivity");
    const double eps = t.number_or(row, c.emissivity, m.emissivity, kUnitInterval, "an emissivity");
    const double T = t.number_or(row, c.temperature, m.temperature, kNonNegative, "a temperature");
    const double q = t.number_or(row, c.charge, m.charge, kAnyValue, "a charge");

    const Vec3 pos{t.number(row, c.x), t.number(row, c.y), t.number(row, c.z)};
    const Vec3 vel{value_or(t, row, c.vx, 0.0), value_or(t, row, c.vy, 0.0), value_or(t, row, c.vz, 0.0)};
    // The row's own constants, where it gives any, make a variant of its material.
    Material own = m;
    own.density = rho, own.young = E, own.poisson = nu, own.heat_capacity = cap, own.conductivity = k;
    own.emissivity = eps;
    check_derived(t, row, c, pid, r, own, model.params.analysis.thermal);
    out.add(pid, variants.find(mat, own), r, rho, pos, vel);
    const std::size_t i = out.size() - 1;
    out.w[i] = {value_or(t, row, c.wx, 0.0), value_or(t, row, c.wy, 0.0), value_or(t, row, c.wz, 0.0)};
    out.charge[i] = q;
    out.T[i] = T;
    out.q[i] = Quat{};
    out.force[i] = Vec3{};
    out.torque[i] = Vec3{};
    out.heat[i] = 0.0;
    out.fixed[i] = row_fixed(t, row, c.fixed);
  }
}

}  // namespace mpdem
