#include "scene/checks_reader.hpp"

#include <string>
#include <string_view>

namespace mpdem {

void read_checks(const TomlSection& root, CheckParams& c) {
  const auto s = root.table("checks", {"max_overlap", "energy_jump", "energy_drift", "energy_ledger"});
  if (!s) return;
  s->get("max_overlap", c.max_overlap, kNonNegative);
  s->get("energy_jump", c.energy_jump, kNonNegative);
  s->get("energy_drift", c.energy_drift, kNonNegative);  // checked once, at the end of the run
  s->get("energy_ledger", c.energy_ledger);
  if (c.energy_ledger) return;
  for (const std::string_view k : {"energy_jump", "energy_drift"}) {
    double& limit = k == "energy_jump" ? c.energy_jump : c.energy_drift;
    if (s->has(k) && limit > 0.0)
      s->fail(k, std::string("the energy checks need the contacts' energy ledger, which this scene switches off "
                             "(energy_ledger = false): set this key to 0 or remove it, or keep the ledger"));
    limit = 0.0;
  }
}

}  // namespace mpdem
