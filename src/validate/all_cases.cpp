// The validation cases in report order: mechanical, thermal, electromagnetic, time stepping.
#include "validate/validation_case.hpp"

namespace mpdem::validate {

std::vector<CaseSpec> all_cases() {
  std::vector<CaseSpec> all;
  for (auto family : {mechanical_cases, thermal_cases, electromagnetic_cases, time_stepping_cases})
    for (CaseSpec& c : family()) all.push_back(std::move(c));
  return all;
}

}  // namespace mpdem::validate
