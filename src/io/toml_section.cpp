#include "io/toml_section.hpp"

#include <array>
#include <cmath>

#include "core/closest_name.hpp"
#include "core/input_error.hpp"

namespace mpdem {

namespace {

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    default: return "a date/time";
  }
}

}  // namespace

TomlSection::TomlSection(const std::string& file, const toml::table& table, std::string path,
                         std::initializer_list<std::string_view> known)
    : TomlSection(file, table, std::move(path), std::span<const std::string_view>(known.begin(), known.size())) {}

TomlSection::TomlSection(const std::string& file, const toml::table& table, std::string path,
                         std::span<const std::string_view> known)
    : file_(&file), table_(&table), path_(std::move(path)) {
  for (auto&& [k, v] : table) {
    bool ok = false;
    for (std::string_view name : known) ok = ok || k.str() == name;
    if (!ok) {
      const std::string prefix = path_.empty() ? "" : path_ + ".";
      throw InputError(*file_, k.source().begin.line, key(k.str()),
                       "unknown key" + did_you_mean(k.str(), known, prefix));
    }
  }
}

std::size_t TomlSection::line() const { return table_->source().begin.line; }

std::string TomlSection::key(std::string_view k) const {
  return path_.empty() ? std::string(k) : path_ + "." + std::string(k);
}

std::size_t TomlSection::line_of(std::string_view k) const {
  const toml::node* n = node(k);
  return n ? n->source().begin.line : line();
}

void TomlSection::fail(std::string_view k, const std::string& message) const {
  throw InputError(*file_, line_of(k), key(k), message);
}

std::optional<double> TomlSection::number(std::string_view k, Range r) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const std::string want = r.text().empty() ? "a number" : "a number " + r.text();
  double v = 0.0;
  if (const auto* i = n->as_integer()) v = static_cast<double>(i->get());  // integers are accepted
  else if (const auto* f = n->as_floating_point()) v = f->get();
  else fail(k, "expected " + want + ", got " + type_name(*n));
  if (!std::isfinite(v)) fail(k, "expected a finite number, got " + number_text(v));
  if (!r.contains(v)) fail(k, "expected " + want + ", got " + number_text(v));
  return v;
}

std::optional<std::int64_t> TomlSection::integer(std::string_view k, std::int64_t min, std::int64_t max) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const auto* i = n->as_integer();
  std::string want = "an integer >= " + std::to_string(min);
  if (max != std::numeric_limits<int>::max() && max != std::numeric_limits<std::int64_t>::max())
    want = "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (!i) fail(k, "expected " + want + ", got " + type_name(*n));
  if (i->get() < min || i->get() > max) fail(k, "expected " + want + ", got " + std::to_string(i->get()));
  return i->get();
}

std::optional<bool> TomlSection::boolean(std::string_view k) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  if (const auto* b = n->as_boolean()) return b->get();
  fail(k, "expected a boolean (true or false), got " + type_name(*n));
}

std::optional<std::string> TomlSection::string(std::string_view k) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  if (const auto* s = n->as_string()) return s->get();
  fail(k, "expected a string, got " + type_name(*n));
}

std::optional<Vec3> TomlSection::vec3(std::string_view k) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const auto* a = n->as_array();
  const std::string want = "expected an array of 3 numbers [x, y, z]";
  if (!a) fail(k, want + ", got " + type_name(*n));
  if (a->size() != 3) fail(k, want + ", got an array of " + std::to_string(a->size()) + " elements");
  double c[3] = {};
  for (std::size_t j = 0; j < 3; ++j) {
    const toml::node& e = *a->get(j);
    if (const auto* i = e.as_integer()) c[j] = static_cast<double>(i->get());
    else if (const auto* f = e.as_floating_point()) c[j] = f->get();
    else fail(k, want + ", element " + std::to_string(j + 1) + " is " + type_name(e));
    if (!std::isfinite(c[j])) fail(k, want + ", element " + std::to_string(j + 1) + " is not finite");
  }
  return Vec3{c[0], c[1], c[2]};
}

std::optional<std::vector<std::string>> TomlSection::strings(std::string_view k, std::size_t min_count,
                                                             std::size_t max_count) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const auto* a = n->as_array();
  const std::string want = "expected an array of " +
                           (min_count == max_count ? std::to_string(min_count)
                                                   : std::to_string(min_count) + " to " + std::to_string(max_count)) +
                           " strings";
  if (!a) fail(k, want + ", got " + type_name(*n));
  if (a->size() < min_count || a->size() > max_count)
    fail(k, want + ", got an array of " + std::to_string(a->size()) + " elements");
  std::vector<std::string> out;
  for (std::size_t j = 0; j < a->size(); ++j) {
    const toml::node& e = *a->get(j);
    const auto* str = e.as_string();
    if (!str) fail(k, want + ", element " + std::to_string(j + 1) + " is " + type_name(e));
    out.push_back(str->get());
  }
  return out;
}

std::optional<std::vector<double>> TomlSection::numbers(std::string_view k, std::size_t min_count,
                                                        std::size_t max_count) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const auto* a = n->as_array();
  const std::string count = min_count == max_count
                                ? std::to_string(min_count)
                                : std::to_string(min_count) + (min_count + 1 == max_count ? " or " : " to ") +
                                      std::to_string(max_count);
  const std::string want = "expected an array of " + count + " numbers";
  if (!a) fail(k, want + ", got " + type_name(*n));
  if (a->size() < min_count || a->size() > max_count)
    fail(k, want + ", got an array of " + std::to_string(a->size()) + " elements");
  std::vector<double> out;
  for (std::size_t j = 0; j < a->size(); ++j) {
    const toml::node& e = *a->get(j);
    double v = 0.0;
    if (const auto* i = e.as_integer()) v = static_cast<double>(i->get());
    else if (const auto* f = e.as_floating_point()) v = f->get();
    else fail(k, want + ", element " + std::to_string(j + 1) + " is " + type_name(e));
    if (!std::isfinite(v)) fail(k, want + ", element " + std::to_string(j + 1) + " is not finite");
    out.push_back(v);
  }
  return out;
}

std::optional<std::vector<std::array<double, 2>>> TomlSection::number_pairs(std::string_view k) const {
  static constexpr std::array<std::string_view, 2> kColumns = {"a", "b"};
  const auto rows = number_rows(k, kColumns, {}, "[[0.0, 0.0], [1.0, 2.0]]");
  if (!rows) return std::nullopt;
  std::vector<std::array<double, 2>> out;
  for (const std::vector<double>& r : *rows) out.push_back({r[0], r[1]});
  return out;
}

std::optional<std::vector<std::vector<double>>> TomlSection::number_rows(std::string_view k,
                                                                         std::span<const std::string_view> columns,
                                                                         std::span<const Range> ranges,
                                                                         std::string_view example) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const auto* a = n->as_array();
  std::string want = "expected an array of [";
  for (std::size_t c = 0; c < columns.size(); ++c) want += (c ? ", " : "") + std::string(columns[c]);
  want += "] rows of numbers, e.g. " + std::string(example);
  if (!a) fail(k, want + ", got " + type_name(*n));
  if (a->empty()) fail(k, want + ", got an empty array");
  std::vector<std::vector<double>> out;
  for (std::size_t j = 0; j < a->size(); ++j) {
    const toml::node& row = *a->get(j);
    const std::string at = ", row " + std::to_string(j + 1);
    const auto bad = [&](const std::string& why) {
      std::string message = want;
      message += at;
      message += ' ';
      message += why;
      throw InputError(*file_, row.source().begin.line, key(k), message);
    };
    const auto* r = row.as_array();
    if (!r) bad("is " + type_name(row));
    if (r->size() != columns.size()) bad("has " + std::to_string(r->size()) + " elements");
    std::vector<double> v(columns.size());
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const toml::node& e = *r->get(c);
      const std::string element = "element " + std::to_string(c + 1);
      if (const auto* i = e.as_integer()) v[c] = static_cast<double>(i->get());
      else if (const auto* f = e.as_floating_point()) v[c] = f->get();
      else bad(element + " is " + type_name(e));
      if (!std::isfinite(v[c])) bad(element + " is not finite");
      if (!ranges.empty() && !ranges[c].contains(v[c]))
        bad(element + " (" + std::string(columns[c]) + ") is " + number_text(v[c]) + ", expected " + ranges[c].text());
    }
    out.push_back(std::move(v));
  }
  return out;
}

std::optional<TomlSection> TomlSection::table(std::string_view k, std::initializer_list<std::string_view> known) const {
  return table(k, std::span<const std::string_view>(known.begin(), known.size()));
}

std::optional<TomlSection> TomlSection::table(std::string_view k, std::span<const std::string_view> known) const {
  const toml::node* n = node(k);
  if (!n) return std::nullopt;
  const auto* t = n->as_table();
  if (!t) fail(k, "expected a table, got " + type_name(*n));
  return TomlSection(*file_, *t, key(k), known);
}

std::vector<TomlSection> TomlSection::tables(std::string_view k, std::initializer_list<std::string_view> known) const {
  return tables(k, std::span<const std::string_view>(known.begin(), known.size()));
}

std::vector<TomlSection> TomlSection::tables(std::string_view k, std::span<const std::string_view> known) const {
  std::vector<TomlSection> out;
  const toml::node* n = node(k);
  if (!n) return out;
  const auto* a = n->as_array();
  const std::string want = "expected an array of tables [[" + key(k) + "]]";
  if (!a) fail(k, want + ", got " + type_name(*n));
  for (const toml::node& e : *a) {
    const auto* t = e.as_table();
    if (!t) fail(k, want + ", got an element that is " + type_name(e));
    out.emplace_back(*file_, *t, key(k), known);
  }
  return out;
}

void TomlSection::get(std::string_view k, double& out, Range r) const {
  if (auto v = number(k, r)) out = *v;
}
void TomlSection::get(std::string_view k, int& out, int min, int max) const {
  if (auto v = integer(k, min, max)) out = static_cast<int>(*v);
}
void TomlSection::get(std::string_view k, bool& out) const {
  if (auto v = boolean(k)) out = *v;
}
void TomlSection::get(std::string_view k, std::string& out) const {
  if (auto v = string(k)) out = *v;
}
void TomlSection::get(std::string_view k, Vec3& out) const {
  if (auto v = vec3(k)) out = *v;
}

}  // namespace mpdem
