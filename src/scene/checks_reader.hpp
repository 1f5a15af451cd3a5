#pragma once
// The [checks] table (docs/scene.md "[checks]"): the instability checks' limits and the contacts'
// energy ledger they need.
#include "io/toml_section.hpp"
#include "model/params.hpp"

namespace mpdem {

// Reads [checks] of `root` into `c`. Without the ledger (energy_ledger = false) the energy checks
// have nothing to check: their defaults become 0, and a non-zero one given in the file is refused
// (InputError at its line), since it would silently check nothing.
void read_checks(const TomlSection& root, CheckParams& c);

}  // namespace mpdem
