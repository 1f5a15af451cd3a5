#pragma once
// Where a neighbour rebuild's large arrays come from (glibc's malloc; docs/benchmark.md "Memory").
//
// glibc serves a block above its mmap threshold from a mapping of its own, returned to the system
// when freed; below it, from the heap, where a freed block's pages stay resident for reuse. Its
// default threshold grows to the size of the largest mapped block freed (up to 32 MiB), so after
// the first rebuild every list, grid and spring array comes from the heap, and the holes a rebuild
// leaves there raise the peak resident memory (docs/benchmark.md). Mappings of their own
// cost a page fault per fresh page instead: worth it for a rebuild that comes
// rarely (a settled bed: every few hundred steps), not for one every few dozen steps (a flow),
// where the heap's reuse is faster.
#include <cstddef>
#include <cstdint>

namespace mpdem {

// Decides, before each rebuild, where its large blocks come from (process-wide: the threshold
// is malloc's). Does nothing where malloc is not glibc's, under the sanitizers (their own
// allocator), or when MALLOC_MMAP_THRESHOLD_ is set in the environment (the user's choice).
class RebuildHeapPolicy {
 public:
  // A rebuild at least this many steps after the previous one is rare (the first one is too).
  static constexpr std::uint64_t kRareAfterSteps = 200;
  // Blocks from this size on get mappings of their own for a rare rebuild (bytes).
  static constexpr std::size_t kRareThreshold = std::size_t{256} << 10;
  // ... and for a frequent one (bytes): glibc's largest dynamic threshold, i.e. the heap.
  static constexpr std::size_t kFrequentThreshold = std::size_t{32} << 20;

  void step() { ++steps_; }  // once per time step
  // Called at the start of every rebuild; returns the threshold it set (0: left alone).
  std::size_t before_rebuild();
  // True when a rebuild now would be rare.
  bool rare() const { return !built_ || steps_ - last_build_ >= kRareAfterSteps; }

 private:
  std::uint64_t steps_ = 0;       // steps taken
  std::uint64_t last_build_ = 0;  // steps_ at the last rebuild
  bool built_ = false;
};

// False where the policy leaves malloc alone: not glibc's malloc, a sanitizer's allocator, or
// MALLOC_MMAP_THRESHOLD_ set in the environment (read once).
bool heap_policy_active();

// Sets glibc's mmap threshold (bytes), and its trim threshold to twice that (as glibc's own
// adjustment does), when heap_policy_active(); true when it did.
bool set_mmap_threshold(std::size_t bytes);

}  // namespace mpdem
