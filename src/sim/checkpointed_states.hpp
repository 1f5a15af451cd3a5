#pragma once
// The per-entry states of the inlets and sinks in their checkpoint sections ("inlets", "sinks"):
// one vector of trivially copyable records, which must hold one record per scene entry.
#include <fmt/core.h>

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "core/binary_stream.hpp"

namespace mpdem {

// Reads the records of `section`; throws std::runtime_error unless there are `entries` of them.
template <class State>
std::vector<State> read_states(BinaryReader& r, std::size_t entries, const char* section) {
  std::vector<State> s = r.vector<State>();
  if (s.size() != entries)
    throw std::runtime_error(
        fmt::format("the section '{}' holds {} entries, the scene has {}", section, s.size(), entries));
  return s;
}

}  // namespace mpdem
