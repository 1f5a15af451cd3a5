// Barrier CSV reader (docs/scene.md "Barrier CSV").
#include "io/barrier_csv.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string_view>
#include <unordered_map>

#include "io/csv_log.hpp"
#include "io/csv_table.hpp"
#include "core/input_error.hpp"
#include "geometry/triangle_check.hpp"
#include "model/derived_limits.hpp"

namespace mpdem {

namespace {

constexpr std::array<std::string_view, 25> kColumns = {
    "id", "x1", "y1", "z1", "x2", "y2", "z2", "x3", "y3", "z3", "group", "young",      "poisson",
    "ax", "ay", "az", "Ax", "Ay", "Az", "w1", "Bx", "By", "Bz", "w2",    "temperature"};

// Column index of every name in kColumns, in that order (-1 when absent).
std::array<int, kColumns.size()> column_indices(const CsvTable& t) {
  std::array<int, kColumns.size()> c{};
  for (std::size_t k = 0; k < kColumns.size(); ++k) c[k] = t.column(kColumns[k]);
  return c;
}
enum Col {
  ID,
  X1,
  Y1,
  Z1,
  X2,
  Y2,
  Z2,
  X3,
  Y3,
  Z3,
  GROUP,
  YOUNG,
  POISSON,
  AX,
  AY,
  AZ,
  AAX,
  AAY,
  AAZ,
  W1,
  BX,
  BY,
  BZ,
  W2,
  TEMPERATURE
};

// A Vec3 from three optional columns, each falling back to its own component of `v`.
Vec3 vec_or(const CsvTable& t, const CsvRow& row, const std::array<int, kColumns.size()>& c, int first, const Vec3& v) {
  const auto comp = [&](int k, double fallback) { return t.missing(row, c[k]) ? fallback : t.number(row, c[k]); };
  return {comp(first, v.x), comp(first + 1, v.y), comp(first + 2, v.z)};
}

}  // namespace

void read_barrier_csv(const std::filesystem::path& file, const BarrierSource& source, const Model& model,
                      Barriers& out) {
  const CsvTable t = CsvTable::read(file, kColumns.size());
  t.check_known(kColumns);
  for (std::string_view req : {"x1", "y1", "z1", "x2", "y2", "z2", "x3", "y3", "z3"}) t.require(req);
  const auto c = column_indices(t);

  // Element defaults: the source's material, else the first material, else Material's defaults.
  Material mat;
  int mat_index = model.material_index(source.material);  // -1 without materials
  if (mat_index < 0 && !model.materials.empty()) mat_index = 0;
  if (mat_index >= 0) mat = model.materials[mat_index];
  const std::string default_group = source.group.empty() ? file.stem().string() : source.group;
  const double default_temperature = source.temperature.value_or(std::numeric_limits<double>::quiet_NaN());

  std::unordered_map<std::int64_t, std::size_t> seen;  // id -> line in this file (0 = earlier file)
  std::int64_t next_id = 0;
  for (const std::int64_t bid : out.id) {
    seen.emplace(bid, 0);
    next_id = std::max(next_id, bid + 1);
  }

  for (const CsvRow& row : t.rows()) {
    std::int64_t bid = next_id;
    if (!t.missing(row, c[ID])) {
      bid = t.integer(row, c[ID]);
      if (const auto it = seen.find(bid); it != seen.end())
        t.fail(row, c[ID],
               "duplicate barrier id " + std::to_string(bid) +
                   (it->second > 0 ? " (first on line " + std::to_string(it->second) + ")"
                                   : " (already used by an earlier barrier file)"));
    }
    // The largest int64 would leave no "next free id" (and overflow computing it).
    if (bid == std::numeric_limits<std::int64_t>::max())
      t.fail(row, c[ID],
             "barrier id " + std::to_string(bid) + " leaves no next free id; expected ids < " + std::to_string(bid));
    seen.emplace(bid, row.line);
    next_id = std::max(next_id, bid + 1);

    const Vec3 p1{t.number(row, c[X1]), t.number(row, c[Y1]), t.number(row, c[Z1])};
    const Vec3 p2{t.number(row, c[X2]), t.number(row, c[Y2]), t.number(row, c[Z2])};
    const Vec3 p3{t.number(row, c[X3]), t.number(row, c[Y3]), t.number(row, c[Z3])};
    const std::string& group = t.missing(row, c[GROUP]) ? default_group : t.text(row, c[GROUP]);
    if (!is_column_name(group))  // the default was checked with the [[barriers]] entry
      t.fail(row, c[GROUP], "the group name names log columns: expected a name without ',', '\"' or line breaks");
    // A rigid element has no elastic constants of its own: a row's value would be ignored.
    for (const Col k : {YOUNG, POISSON})
      if (source.rigid && !t.missing(row, c[k]))
        t.fail(row, c[k], "a rigid barrier ([[barriers]] rigid = true) takes no young or poisson values");
    const double E = source.rigid ? kRigidYoung : t.number_or(row, c[YOUNG], mat.young, kPositive, "a Young's modulus");
    const double nu = t.number_or(row, c[POISSON], mat.poisson, kPoissonRange, "a Poisson ratio");
    double temp = default_temperature;
    if (!t.missing(row, c[TEMPERATURE])) temp = t.number(row, c[TEMPERATURE], kNonNegative, "a temperature");

    // Motion columns override the source's law component by component.
    MotionLaw law = source.motion;
    law.a = vec_or(t, row, c, AX, law.a);
    law.A = vec_or(t, row, c, AAX, law.A);
    law.B = vec_or(t, row, c, BX, law.B);
    if (!t.missing(row, c[W1])) law.w1 = t.number(row, c[W1]);
    if (!t.missing(row, c[W2])) law.w2 = t.number(row, c[W2]);

    // Finite coordinates can still overflow an edge, the centroid or the area (|x| ~ 1e77 and
    // up), leaving no usable normal; the coordinate of largest magnitude is named.
    const Vec3 p[3] = {p1, p2, p3};
    if (const TriangleCheck tc = check_triangle(p1, p2, p3); tc.fault == TriangleFault::NonFinite) {
      const double x[9] = {p1.x, p1.y, p1.z, p2.x, p2.y, p2.z, p3.x, p3.y, p3.z};  // the columns X1..Z3
      int worst = 0;
      for (int k = 1; k < 9; ++k)
        if (std::abs(x[k]) > std::abs(x[worst])) worst = k;
      t.fail(row, c[X1 + worst], "triangle too large: " + tc.what + "; expected coordinates whose area is finite");
    }
    // The motion law moves the element by B at t = 0: the moved vertices must stay finite.
    for (int k = 0; k < 3; ++k)
      if (!isfinite(p[k] + law.displacement(0.0))) {
        const int col = !t.missing(row, c[BX]) ? c[BX] : (!t.missing(row, c[BY]) ? c[BY] : c[BZ]);
        const std::string what = "vertex " + std::to_string(k + 1) + " " + vec_text(p[k]) +
                                 " moved by B = " + vec_text(law.B) + " at t = 0 overflows; expected finite positions";
        if (t.missing(row, col)) throw InputError(t.file(), row.line, "", what + " (B of [[barriers]] motion)");
        t.fail(row, col, what);
      }
    // Over the run (the source's own law was checked by the scene reader): a row's columns.
    if (std::string key, why = law.limit_problem(model.params.time.duration, key); !why.empty()) {
      const Col first = key == "a" ? AX : key == "A" ? AAX : key == "B" ? BX : key == "w1" ? W1 : W2;
      int col = -1;
      for (const Col k : {first, AX, AAX, BX, W1, W2})
        for (int j = 0; j < (k == W1 || k == W2 ? 1 : 3) && col < 0; ++j)
          if (!t.missing(row, c[k + j])) col = c[k + j];
      if (col < 0) throw InputError(t.file(), row.line, "", why + " ([[barriers]] motion)");
      t.fail(row, col, why);
    }
    if (!source.rigid)
      if (const std::string pr = contact_moduli_problem(E, nu); !pr.empty())
        t.fail(row, !t.missing(row, c[YOUNG]) || t.missing(row, c[POISSON]) ? c[YOUNG] : c[POISSON], pr);
    const int g = out.group_index(group);
    if (!out.add(bid, p1, p2, p3, g, E, nu, law, source.thickness, temp))
      throw InputError(t.file(), row.line, "", "degenerate triangle (zero area: its three vertices are collinear)");
    out.material.back() = mat_index;
  }
}

}  // namespace mpdem
