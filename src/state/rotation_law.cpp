#include "state/rotation_law.hpp"

namespace mpdem {

namespace {

// rad, integral of the table's rate from its first row's time to t (negative before it).
double antiderivative(const std::vector<std::array<double, 2>>& tab, double t) {
  if (t <= tab.front()[0]) return tab.front()[1] * (t - tab.front()[0]);
  double a = 0.0;  // rad, up to row i
  for (std::size_t i = 0; i + 1 < tab.size(); ++i) {
    const double t0 = tab[i][0], w0 = tab[i][1], t1 = tab[i + 1][0], w1 = tab[i + 1][1];
    if (t <= t1) {
      const double h = t - t0;  // s, into the segment; the rate there is w0 + (w1 - w0) h / (t1 - t0)
      return a + h * (w0 + 0.5 * (w1 - w0) * h / (t1 - t0));
    }
    a += 0.5 * (w0 + w1) * (t1 - t0);
  }
  return a + tab.back()[1] * (t - tab.back()[0]);
}

}  // namespace

double RotationLaw::rate(double t) const {
  if (since != 0.0) {
    if (t < since) return 0.0;
    t -= since;
  }
  if (omega_table.empty()) return omega;
  const auto& tab = omega_table;
  if (t <= tab.front()[0]) return tab.front()[1];
  for (std::size_t i = 0; i + 1 < tab.size(); ++i)
    if (t <= tab[i + 1][0])
      return tab[i][1] + (tab[i + 1][1] - tab[i][1]) * (t - tab[i][0]) / (tab[i + 1][0] - tab[i][0]);
  return tab.back()[1];
}

double RotationLaw::angle(double t) const {
  if (since != 0.0) {
    if (t < since) return 0.0;
    t -= since;
  }
  if (omega_table.empty()) return omega * t;
  return antiderivative(omega_table, t) - antiderivative(omega_table, 0.0);
}

bool RotationLaw::turns() const {
  bool any = omega != 0.0 && omega_table.empty();
  for (const auto& row : omega_table) any = any || row[1] != 0.0;
  return any;
}

}  // namespace mpdem
