// Helpers of the validation oracles (case_support.hpp).
#include "validate/case_support.hpp"

#include <stdexcept>

namespace mpdem::validate {

std::size_t index_of_id(const Particles& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) return i;
  throw std::runtime_error(fmt::format("validation scene has no particle id {}", id));
}

double first_rise(const std::vector<double>& t, const std::vector<double>& y) {
  for (std::size_t k = 1; k < y.size(); ++k)
    if (y[k - 1] <= 0.0 && y[k] > 0.0) return t[k] - (t[k] - t[k - 1]) * y[k] / (y[k] - y[k - 1]);
  return -1.0;
}

double last_fall(const std::vector<double>& t, const std::vector<double>& y) {
  if (y.size() < 2) return -1.0;
  for (std::size_t k = y.size() - 1; k >= 1; --k)
    if (y[k - 1] > 0.0 && y[k] <= 0.0) return t[k - 1] + (t[k] - t[k - 1]) * y[k - 1] / (y[k - 1] - y[k]);
  return -1.0;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    mx += std::log(x[k]) / n;
    my += std::log(y[k]) / n;
  }
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sxy += (std::log(x[k]) - mx) * (std::log(y[k]) - my);
    sxx += (std::log(x[k]) - mx) * (std::log(x[k]) - mx);
  }
  return sxy / sxx;
}

}  // namespace mpdem::validate
