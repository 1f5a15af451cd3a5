#pragma once
// Binary streams for checkpoints: trivially copyable values and vectors of them, native byte
// order (a checkpoint is resumed on the machine kind that wrote it), each vector prefixed by its
// length. Reading checks every length against the bytes left before allocating, and every bool
// for 0 or 1, so a truncated or corrupted file gives an error rather than a crash or undefined
// behaviour.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace mpdem {

class BinaryWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&v, sizeof(T));
  }
  template <class T>
  void vector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value<std::uint64_t>(v.size());
    if (v.empty()) return;  // an empty vector's data() may be null
    append(v.data(), v.size() * sizeof(T));
  }
  void string(const std::string& s) { vector(std::vector<char>(s.begin(), s.end())); }
  const std::vector<char>& bytes() const { return bytes_; }

 private:
  void append(const void* data, std::size_t n) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + n);
    std::memcpy(bytes_.data() + at, data, n);
  }
  std::vector<char> bytes_;
};

class BinaryReader {
 public:
  BinaryReader(const char* data, std::size_t size) : p_(data), end_(data + size) {}
  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    // Every byte pattern must be a valid T: a bool holds only 0 or 1 (another byte loaded as a
    // bool is undefined behaviour), so it is read as a byte and checked. (An enum would need its
    // range checked the same way; none is read.)
    need(sizeof(T));
    if constexpr (std::is_same_v<T, bool>) {
      unsigned char b = 0;
      std::memcpy(&b, p_, 1);
      if (b > 1) throw std::runtime_error("corrupted data (a flag is neither 0 nor 1)");
      p_ += 1;
      return b == 1;
    } else {
      T v;
      std::memcpy(&v, p_, sizeof(T));
      p_ += sizeof(T);
      return v;
    }
  }
  template <class T>
  std::vector<T> vector() {
    static_assert(!std::is_same_v<T, bool>, "a vector of flags: read them one by one with value<bool>()");
    const auto n = value<std::uint64_t>();
    if (n > static_cast<std::uint64_t>(end_ - p_) / sizeof(T)) throw std::runtime_error("truncated or corrupted data");
    std::vector<T> v(n);
    if (n > 0) std::memcpy(v.data(), p_, n * sizeof(T));  // an empty vector's data() may be null
    p_ += n * sizeof(T);
    return v;
  }
  std::string string() {
    const auto v = vector<char>();
    return {v.begin(), v.end()};
  }
  bool at_end() const { return p_ == end_; }
  std::vector<char> rest() {  // everything not read yet
    std::vector<char> v(p_, end_);
    p_ = end_;
    return v;
  }

 private:
  void need(std::size_t n) const {
    if (static_cast<std::size_t>(end_ - p_) < n) throw std::runtime_error("truncated or corrupted data");
  }
  const char* p_;
  const char* end_;
};

}  // namespace mpdem
