#pragma once
// Frees a vector's storage. `v = {}` does not: it picks operator=(initializer_list), which, like
// clear(), keeps the capacity - a large scratch array then stays resident until its owner dies.
#include <vector>

namespace mpdem {

template <class T, class A>
void release(std::vector<T, A>& v) {
  std::vector<T, A>().swap(v);
}

}  // namespace mpdem
