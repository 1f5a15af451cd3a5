#include "core/heap_policy.hpp"

#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mpdem {

namespace {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kOwnAllocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kOwnAllocator = true;
#else
constexpr bool kOwnAllocator = false;
#endif
#else
constexpr bool kOwnAllocator = false;
#endif
}  // namespace

bool heap_policy_active() {
#if defined(__GLIBC__)
  // Read once: the environment is the user's choice for the whole run.
  static const bool user_set = std::getenv("MALLOC_MMAP_THRESHOLD_") != nullptr;
  return !kOwnAllocator && !user_set;
#else
  return false;
#endif
}

bool set_mmap_threshold(std::size_t bytes) {
#if defined(__GLIBC__)
  if (!heap_policy_active()) return false;
  // A threshold set here stops glibc's own adjustment, which also keeps the heap's top from being
  // trimmed below twice the threshold: without that, every frequent rebuild would hand its freed
  // top back to the system and fault it in again at the next one.
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(bytes)) == 1 &&
         mallopt(M_TRIM_THRESHOLD, static_cast<int>(2 * bytes)) == 1;
#else
  (void)bytes;
  return false;
#endif
}

std::size_t RebuildHeapPolicy::before_rebuild() {
  const std::size_t bytes = rare() ? kRareThreshold : kFrequentThreshold;
  built_ = true;
  last_build_ = steps_;
  return set_mmap_threshold(bytes) ? bytes : 0;
}

}  // namespace mpdem
