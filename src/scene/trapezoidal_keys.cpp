#include "scene/trapezoidal_keys.hpp"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace mpdem {

namespace {

// Keep in step with read_time (scene_reader.cpp); [tolerance] is all the trapezoidal rule's.
constexpr std::array<std::string_view, 7> kTimeKeys = {"phi", "adaptive",      "dt_min", "dt_max", "desired_iterations",
                                                       "p",   "max_iterations"};

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
