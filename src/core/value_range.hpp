#pragma once
// Range: an interval of allowed input values, with the text that error messages use to state
// the expectation ("> 0", "in [0, 0.5)"). Shared by the TOML scene reader and the CSV readers.
#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace mpdem {

// Shortest text that reads back as exactly `v` ("0.001", "1e-08"), for messages.
inline std::string number_text(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_closed = false, hi_closed = false;

  bool contains(double v) const { return (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi); }
  std::string text() const {
    const bool lo_inf = std::isinf(lo), hi_inf = std::isinf(hi);
    if (lo_inf && hi_inf) return "";
    if (hi_inf) return (lo_closed ? ">= " : "> ") + number_text(lo);
    if (lo_inf) return (hi_closed ? "<= " : "< ") + number_text(hi);
    return std::string("in ") + (lo_closed ? "[" : "(") + number_text(lo) + ", " + number_text(hi) +
           (hi_closed ? "]" : ")");
  }
};

inline constexpr Range kAnyValue{};
inline constexpr Range kPositive{0.0, std::numeric_limits<double>::infinity(), false, false};
inline constexpr Range kNonNegative{0.0, std::numeric_limits<double>::infinity(), true, false};
inline constexpr Range kUnitInterval{0.0, 1.0, true, true};   // [0, 1]
inline constexpr Range kPoissonRange{0.0, 0.5, true, false};  // [0, 0.5)

}  // namespace mpdem
