#include "state/motion_law.hpp"

#include <fmt/core.h>

#include <array>
#include <utility>

namespace mpdem {

namespace {

// "" when the terms' sum is finite, else "<what> overflows ..." naming the largest term.
std::string sum_problem(const std::array<std::pair<const char*, double>, 3>& terms, const char* what, const char* unit,
                        std::string& key) {
  double sum = 0.0;
  std::size_t worst = 0;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    sum += terms[k].second;
    if (!(terms[k].second <= terms[worst].second)) worst = k;
  }
  if (std::isfinite(sum)) return "";
  key = terms[worst].first;
  return fmt::format("{} overflows ({} {}, from the term of {})", what, sum, unit, key);
}

}  // namespace

std::string MotionLaw::limit_problem(double duration, std::string& key) const {
  const double T = duration;  // s, law_time(t) <= t
  std::string p;
  for (int c = 0; c < 3 && p.empty(); ++c) {  // per component: the positions are
    p = sum_problem({{{"a", std::abs(a[c]) * T}, {"A", std::abs(A[c])}, {"B", std::abs(B[c])}}},
                    "the displacement bound |a| T + |A| + |B| over the run", "m", key);
    if (p.empty())
      p = sum_problem({{{"a", std::abs(a[c])}, {"w1", std::abs(A[c] * w1)}, {"w2", std::abs(B[c] * w2)}}},
                      "the velocity bound |a| + |A| |w1| + |B| |w2|", "m/s", key);
  }
  if (p.empty() && rotation) {
    double fastest = std::abs(rotation->omega);  // rad/s
    for (const auto& row : rotation->omega_table) fastest = std::max(fastest, std::abs(row[1]));
    p = sum_problem({{{"omega", fastest * T}, {"omega", 0.0}, {"omega", 0.0}}}, "the rotation angle bound |omega| T",
                    "rad", key);
  }
  if (p.empty()) return "";
  return fmt::format("{} with time.duration = {} s; expected a motion that stays finite over the run", p, T);
}

}  // namespace mpdem
