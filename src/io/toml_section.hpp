#pragma once
// TomlSection: typed, range-checked access to one table of the TOML scene file. Unknown keys are
// rejected on construction (with the closest known key suggested); every other problem - wrong
// type, out of range, missing - is an InputError naming the file, the line (from toml++'s
// source regions) and the dotted key.
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <span>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/vec3.hpp"
#include "core/value_range.hpp"

namespace mpdem {

class TomlSection {
 public:
  // `path` is the dotted name of the table ("" for the root, "contact.particle_particle").
  TomlSection(const std::string& file, const toml::table& table, std::string path,
              std::initializer_list<std::string_view> known);
  TomlSection(const std::string& file, const toml::table& table, std::string path,
              std::span<const std::string_view> known);

  const std::string& file() const { return *file_; }
  std::size_t line() const;                   // line of the table itself
  std::string key(std::string_view k) const;  // dotted name of key k
  bool has(std::string_view k) const { return table_->contains(k); }
  std::size_t line_of(std::string_view k) const;  // line of key k (the table's line if absent)

  std::optional<double> number(std::string_view k, Range r = kAnyValue) const;
  std::optional<std::int64_t> integer(std::string_view k, std::int64_t min, std::int64_t max) const;
  std::optional<bool> boolean(std::string_view k) const;
  std::optional<std::string> string(std::string_view k) const;
  std::optional<Vec3> vec3(std::string_view k) const;
  // An array of `count` strings ("expected an array of 2 strings" otherwise).
  std::optional<std::vector<std::string>> strings(std::string_view k, std::size_t count) const {
    return strings(k, count, count);
  }
  // An array of min_count to max_count strings.
  std::optional<std::vector<std::string>> strings(std::string_view k, std::size_t min_count,
                                                  std::size_t max_count) const;
  // An array of min_count to max_count finite numbers.
  std::optional<std::vector<double>> numbers(std::string_view k, std::size_t min_count, std::size_t max_count) const;
  // A non-empty array of [a, b] rows of finite numbers; a bad row is reported at its own line.
  std::optional<std::vector<std::array<double, 2>>> number_pairs(std::string_view k) const;
  // A non-empty array of rows of finite numbers, one element per name in `columns`, element c
  // within ranges[c] (ranges empty: any); a bad row is reported at its own line ("expected an
  // array of [x, y, z, radius] rows of numbers, e.g. EXAMPLE, row 2 has 3 elements").
  std::optional<std::vector<std::vector<double>>> number_rows(std::string_view k,
                                                              std::span<const std::string_view> columns,
                                                              std::span<const Range> ranges,
                                                              std::string_view example) const;
  // Sub-table (standard or inline); "expected a table" when k holds anything else.
  std::optional<TomlSection> table(std::string_view k, std::initializer_list<std::string_view> known) const;
  std::optional<TomlSection> table(std::string_view k, std::span<const std::string_view> known) const;
  // Array of tables ([[k]]); "expected an array of tables [[k]]" otherwise. Empty when absent.
  std::vector<TomlSection> tables(std::string_view k, std::initializer_list<std::string_view> known) const;
  std::vector<TomlSection> tables(std::string_view k, std::span<const std::string_view> known) const;

  // Assign-if-present forms, so a default stays in place when the key is absent.
  void get(std::string_view k, double& out, Range r = kAnyValue) const;
  void get(std::string_view k, int& out, int min, int max = std::numeric_limits<int>::max()) const;
  void get(std::string_view k, bool& out) const;
  void get(std::string_view k, std::string& out) const;
  void get(std::string_view k, Vec3& out) const;

  // Value of a required key or "missing required key".
  template <class T>
  T require(std::optional<T> v, std::string_view k) const {
    if (!v) fail(k, "missing required key");
    return *v;
  }
  // Throws InputError at key k's line (or the table's line when k is absent).
  [[noreturn]] void fail(std::string_view k, const std::string& message) const;
  // The raw value of key k (null when absent), for shapes the typed getters do not cover (an
  // array of rows); the caller reports its problems with fail(k, ...).
  const toml::node* node(std::string_view k) const { return table_->get(k); }

 private:
  const std::string* file_;
  const toml::table* table_;
  std::string path_;
};

}  // namespace mpdem
