#pragma once
// The scene keys that only the generalised trapezoidal rule reads ([time] phi, adaptive, dt_min,
// dt_max, desired_iterations, p, max_iterations and the [tolerance] table). Velocity Verlet is
// the default integrator, so a scene written for the trapezoidal rule that does not name its
// integrator would run Verlet and ignore them: the reader refuses them instead.
#include <array>
#include <string_view>

#include "io/toml_section.hpp"

namespace mpdem {

// The [tolerance] table's keys (read_tolerance reads them, all of them the trapezoidal rule's).
inline constexpr std::array<std::string_view, 10> kToleranceKeys = {
    "position",       "velocity",       "rotation",       "angular_velocity",       "temperature",
    "position_floor", "velocity_floor", "rotation_floor", "angular_velocity_floor", "temperature_floor"};

// Throws InputError at the first such key (by line) when the integrator is Verlet; `time` is
// the [time] table of `root`.
void refuse_trapezoidal_keys(const TomlSection& root, const TomlSection& time);

}  // namespace mpdem
