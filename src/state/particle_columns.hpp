#pragma once
// The particle columns: what each Particles array is called, measured in and shaped like outside
// the engine. This one table drives the particle VTU (its PointData and Points) and the PVTU's
// declarations (io/vtu_writer.hpp), the particle CSV snapshot's header and rows
// (io/particle_csv_writer.hpp), the particle CSV reader's accepted and skipped columns
// (io/particle_csv_reader.hpp) and the Python arrays sim.particles.<name> (python/particle_arrays.hpp).
// Adding an output column is one row here (docs/architecture.md, "Add an output column").
// It lives in state/ beside the arrays it names, below io/ and python/, which both read it; the
// formats' own spellings (VTK type names, number printing) stay with their writers.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "state/particles.hpp"

namespace mpdem {

// What the particle CSV does with a column.
enum class CsvRole : std::uint8_t {
  none,      // not in the CSV
  input,     // written, and read back as input (docs/scene.md "Particle CSV")
  output,    // written, skipped on read: a snapshot seeds a new scene as it is
  periodic,  // written by a run with a periodic axis only, skipped on read: the image counts,
             // which the unwrapped centre (kCsvUnwrapped) follows
};

// A column's place in the particle VTU: 0, 1, ... its position among the PointData arrays (their
// file order; the slots form 0 .. n-1, checked where the VTU is written), or one of these.
inline constexpr int kNotInVtu = -1;
inline constexpr int kVtuPointsSlot = -2;  // the VTU's Points, not a PointData array

// Components of one entry of an array of T: 1 (scalars), 3 (vectors, image counters), 4 (quaternions).
template <class T>
inline constexpr std::size_t kComponents = 1;
template <>
inline constexpr std::size_t kComponents<Vec3> = 3;
template <>
inline constexpr std::size_t kComponents<Quat> = 4;
template <>
inline constexpr std::size_t kComponents<std::array<std::int32_t, 3>> = 3;

// Component c of one entry: x, y, z of a vector, w, x, y, z of a quaternion, the value itself.
template <class T>
constexpr auto component(const T& v, std::size_t c) {
  if constexpr (std::is_same_v<T, Vec3>) return c == 0 ? v.x : c == 1 ? v.y : v.z;
  else if constexpr (std::is_same_v<T, Quat>) return c == 0 ? v.w : c == 1 ? v.x : c == 2 ? v.y : v.z;
  else if constexpr (std::is_same_v<T, std::array<std::int32_t, 3>>) return v[c];
  else return v;
}

template <class T>
struct ParticleColumn {
  using Value = T;                   // one particle's entry
  const char* name;                  // Python attribute sim.particles.<name>, VTU array name
  std::vector<T> Particles::*array;  // the Particles array
  const char* unit;                  // SI unit, "-" for none
  const char* about;                 // what it is, a few words (Python docstrings)
  std::array<const char*, 3> csv{};  // CSV column of each component; unused with CsvRole::none
  CsvRole csv_role = CsvRole::none;  // what the particle CSV does with it
  int vtu = kNotInVtu;               // its VTU slot, kNotInVtu or kVtuPointsSlot
  bool settable = false;             // Python may assign it between steps

  static constexpr std::size_t components = kComponents<T>;
};

// The table. Its order is the CSV's column order (after `time`) and the order of Python's
// particle_arrays; the VTU orders its PointData by the `vtu` slots. A new CSV column goes after
// the last one (the image counts) and a new VTU array takes the next slot, so that every earlier
// column keeps its position in the files.
inline constexpr auto kParticleColumns = std::tuple{
    ParticleColumn<std::int64_t>{"id", &Particles::id, "-", "the particles' ids, ascending", {"id"}, CsvRole::input, 0},
    ParticleColumn<Vec3>{
        "position", &Particles::x, "m", "centres", {"x", "y", "z"}, CsvRole::input, kVtuPointsSlot, true},
    ParticleColumn<Vec3>{"velocity", &Particles::v, "m/s", "velocity", {"vx", "vy", "vz"}, CsvRole::input, 4, true},
    ParticleColumn<Vec3>{
        "angular_velocity", &Particles::w, "rad/s", "angular velocity", {"wx", "wy", "wz"}, CsvRole::input, 5, true},
    ParticleColumn<double>{"radius", &Particles::radius, "m", "radius", {"radius"}, CsvRole::input, 1},
    ParticleColumn<int>{
        "material", &Particles::material, "-", "index into the scene's materials", {"material"}, CsvRole::input, 2},
    ParticleColumn<double>{"temperature", &Particles::T, "K", "temperature", {"temperature"}, CsvRole::input, 7, true},
    ParticleColumn<double>{"charge", &Particles::charge, "C", "charge", {"charge"}, CsvRole::input, 8},
    ParticleColumn<Vec3>{
        "force", &Particles::force, "N", "total force of the last evaluation", {"fx", "fy", "fz"}, CsvRole::output, 6},
    ParticleColumn<std::uint8_t>{"fixed", &Particles::fixed, "-", "1: prescribed motion", {"fixed"}, CsvRole::input, 3},
    ParticleColumn<std::array<std::int32_t, 3>>{"image",
                                                &Particles::image,
                                                "-",
                                                "periodic image counters (unwrapped = position + image * period)",
                                                {"ix", "iy", "iz"},
                                                CsvRole::periodic},
    ParticleColumn<Vec3>{"torque",
                         &Particles::torque,
                         "N m",
                         "total torque about the centre of the last evaluation",
                         {"tx", "ty", "tz"},
                         CsvRole::output,
                         10},
    ParticleColumn<Quat>{
        "orientation", &Particles::q, "-", "unit quaternion (w, x, y, z), body to world", {}, CsvRole::none, 9},
    ParticleColumn<double>{"mass", &Particles::mass, "kg", "mass"},
    ParticleColumn<double>{"inertia", &Particles::inertia, "kg m^2", "moment of inertia"},
    ParticleColumn<double>{"heat", &Particles::heat, "W", "heat flow into the particle of the last evaluation"},
    ParticleColumn<std::int64_t>{"body",
                                 &Particles::body,
                                 "-",
                                 "id of the clump body the sphere is a member of, -1 for a free sphere",
                                 {"body"},
                                 CsvRole::output,
                                 11},
    ParticleColumn<std::uint32_t>{"member", &Particles::member, "-",
                                  "index among its body's members (template order), 0 for a free sphere"},
};

// The CSV columns that are not a Particles array: the snapshot's time (s) first, and with a
// periodic axis the unwrapped centre position + image * period (m) right after the image counts.
inline constexpr const char* kCsvTime = "time";
inline constexpr std::array<const char*, 3> kCsvUnwrapped = {"xu", "yu", "zu"};

// f(column) for every row, in table order.
template <class F>
constexpr void for_each_particle_column(F&& f) {
  std::apply([&f](const auto&... c) { (f(c), ...); }, kParticleColumns);
}

// Every CSV column has a name per component; Python names and CSV names are unique; the one
// periodic column is the image counts (the unwrapped centre is computed from them).
consteval bool particle_columns_valid() {
  std::vector<std::string_view> names, csv;
  bool ok = true;
  int periodic = 0;
  for_each_particle_column([&](const auto& c) {
    names.push_back(c.name);
    if constexpr (std::is_same_v<typename std::decay_t<decltype(c)>::Value, std::array<std::int32_t, 3>>)
      periodic += c.csv_role == CsvRole::periodic && c.array == &Particles::image ? 1 : 0;
    if (c.csv_role == CsvRole::periodic) --periodic;
    if (c.csv_role == CsvRole::none) return;
    ok = ok && c.components <= c.csv.size();
    for (std::size_t k = 0; ok && k < c.components; ++k) {
      ok = ok && c.csv[k] != nullptr;
      if (ok) csv.push_back(c.csv[k]);
    }
  });
  csv.push_back(kCsvTime);
  for (const char* u : kCsvUnwrapped) csv.push_back(u);
  for (const auto* list : {&names, &csv})
    for (std::size_t a = 0; a < list->size(); ++a)
      for (std::size_t b = a + 1; b < list->size(); ++b) ok = ok && (*list)[a] != (*list)[b];
  return ok && periodic == 0;
}
static_assert(particle_columns_valid(), "particle_columns.hpp: a CSV column without a name, a name used twice, or a "
                                        "periodic column other than the image counts");

// The CSV name of `array`'s component c (the reader looks its input columns up by the array).
template <class T>
constexpr std::string_view csv_name(std::vector<T> Particles::*array, std::size_t c) {
  std::string_view out;
  for_each_particle_column([&](const auto& col) {
    if constexpr (std::is_same_v<typename std::decay_t<decltype(col)>::Value, T>)
      if (col.array == array && col.csv_role != CsvRole::none) out = col.csv[c];
  });
  return out;
}

}  // namespace mpdem
