#pragma once
// How the scene fingerprint (io/scene_fingerprint.hpp) hashes the values of its items, and a
// part of named keys with entries after them.
#include <bit>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"
#include "io/scene_fingerprint.hpp"
#include "model/params.hpp"

namespace mpdem::fingerprint {

// FNV-1a (64 bit) over the exact bytes of each value: any edit of a double, even in its last
// bit, changes the item. Strings add their length first, so that "ab" + "c" differs from "a" + "bc".
class Hash {
 public:
  void add(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) {
      h_ ^= (v >> (8 * k)) & 0xffu;
      h_ *= 0x100000001b3ull;
    }
  }
  void add(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }
  void add(int v) { add(static_cast<std::int64_t>(v)); }
  void add(bool v) { add(std::uint64_t{v}); }
  void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
  void add(const Vec3& v) {
    add(v.x);
    add(v.y);
    add(v.z);
  }
  void add(const Quat& q) {
    add(q.w);
    add(q.x);
    add(q.y);
    add(q.z);
  }
  void add(const std::string& s) {
    add(std::uint64_t{s.size()});
    for (const char c : s) {
      h_ ^= static_cast<unsigned char>(c);
      h_ *= 0x100000001b3ull;
    }
  }
  template <class T>
  void add(const std::optional<T>& v) {
    add(v.has_value());
    if (v) add(*v);
  }
  void add(const LawKeyValues& m) {
    add(std::uint64_t{m.size()});
    for (const auto& [k, v] : m) {
      add(k);
      add(v);
    }
  }
  template <class E>
  requires std::is_enum_v<E>
  void add(E e) { add(static_cast<std::int64_t>(e)); }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

template <class... T>
std::uint64_t hash_of(const T&... v) {
  Hash h;
  (h.add(v), ...);
  return h.value();
}

// A part made of named keys (fixed items), then entries labelled by `entry_label`.
class KeyedPart {
 public:
  explicit KeyedPart(std::string name) { part_.name = std::move(name); }
  template <class... T>
  void key(std::string k, const T&... v) {
    part_.items.push_back(hash_of(v...));
    keys_->push_back(std::move(k));
  }
  FingerprintPart finish(std::string entries = "", std::vector<std::string> entry_labels = {}) {
    part_.fixed = part_.items.size();
    part_.entries = std::move(entries);
    part_.label = [keys = keys_, entry_labels = std::move(entry_labels)](std::size_t k) {
      if (k < keys->size()) return (*keys)[k];
      k -= keys->size();
      return k < entry_labels.size() ? entry_labels[k] : "entry " + std::to_string(k + 1);
    };
    return std::move(part_);
  }
  FingerprintPart& part() { return part_; }

 private:
  FingerprintPart part_;
  std::shared_ptr<std::vector<std::string>> keys_ = std::make_shared<std::vector<std::string>>();
};

}  // namespace mpdem::fingerprint
