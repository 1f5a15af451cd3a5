#include "scene/trapezoidal_keys.hpp"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace mpdem {

namespace {

// Keep in step with read_time and read_tolerance (scene_reader.cpp).
constexpr std::array<std::string_view, 7> kTimeKeys = {"phi", "adaptive",      "dt_min", "dt_max", "desired_iterations",
                                                       "p",   "max_iterations"};
constexpr std::array<std::string_view, 10> kToleranceKeys = {
    "position",       "velocity",       "rotation",       "angular_velocity",       "temperature",
    "position_floor", "velocity_floor", "rotation_floor", "angular_velocity_floor", "temperature_floor"};

// The key of `keys` present in `s` on the earliest line, if any.
template <std::size_t N>
std::optional<std::string_view> first_present(const TomlSection& s, const std::array<std::string_view, N>& keys) {
  std::optional<std::string_view> first;
  for (std::string_view k : keys)
    if (s.has(k) && (!first || s.line_of(k) < s.line_of(*first))) first = k;
  return first;
}

}  // namespace

void refuse_trapezoidal_keys(const TomlSection& root, const TomlSection& time) {
  const std::string runs = time.has("integrator")
                               ? "[time] integrator = \"verlet\""
                               : "the default integrator is \"verlet\" when [time] integrator is not given";
  const std::string why = "only the trapezoidal rule reads this key, and this scene runs velocity Verlet (" + runs +
                          "); set [time] integrator = \"trapezoidal\" to use it, or remove the key";
  if (const auto k = first_present(time, kTimeKeys)) time.fail(*k, why);
  if (const auto tol = root.table("tolerance", std::span<const std::string_view>(kToleranceKeys))) {
    if (const auto k = first_present(*tol, kToleranceKeys)) tol->fail(*k, why);
  }
}

}  // namespace mpdem
