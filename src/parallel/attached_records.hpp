#pragma once
// AttachedRecords: fixed-size records that travel with a particle when it migrates to another
// rank (its contact history, parallel/halo_exchange.hpp): record r belongs to the particle whose
// id is anchor[r] and follows it.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace mpdem {

struct AttachedRecords {
  std::size_t bytes = 0;             // per record
  std::vector<std::int64_t> anchor;  // [R] particle ids
  std::vector<std::byte> data;       // [R x bytes]

  template <class T>
  static AttachedRecords of() {
    static_assert(std::is_trivially_copyable_v<T>);
    AttachedRecords a;
    a.bytes = sizeof(T);
    return a;
  }
  template <class T>
  void push(std::int64_t id, const T& r) {
    anchor.push_back(id);
    const std::size_t at = data.size();
    data.resize(at + sizeof(T));
    std::memcpy(data.data() + at, &r, sizeof(T));
  }
  template <class T>
  T get(std::size_t r) const {
    T v;
    std::memcpy(&v, data.data() + r * sizeof(T), sizeof(T));
    return v;
  }
  std::size_t size() const { return anchor.size(); }
};

}  // namespace mpdem
