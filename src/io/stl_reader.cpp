// STL reader (docs/scene.md "[[barriers]]", docs/tools.md "STL").
#include "io/stl_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/input_error.hpp"
#include "core/input_file.hpp"
#include "core/value_range.hpp"
#include "geometry/mesh_transform.hpp"
#include "geometry/triangle_check.hpp"

namespace mpdem {

namespace {

std::string read_all(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), 0, "", "cannot open STL file");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

float read_float(const char* p) {
  float f;
  std::memcpy(&f, p, 4);  // STL is little-endian, as is every platform mpdem targets
  return f;
}

// Keeps triangle `number` (at `line` of an ASCII file), or counts it when its area is zero; an
// area that overflows is an error.
void keep(const std::string& name, StlMesh& out, const std::array<Vec3, 3>& t, std::size_t number, std::size_t line) {
  const TriangleCheck c = check_triangle(t[0], t[1], t[2]);
  if (c.fault == TriangleFault::NonFinite)  // finite coordinates, yet an edge or the area overflowed
    throw InputError(name, line, "", "triangle " + std::to_string(number) + ": " + c.what);
  if (c.fault == TriangleFault::ZeroArea || is_degenerate_triangle(t[0], t[1], t[2])) {
    ++out.degenerate;
    return;
  }
  out.triangles.push_back(t);
  out.number.push_back(number);
  out.line.push_back(line);
}

StlMesh read_binary(const std::string& name, const std::string& data) {
  std::uint32_t n = 0;
  std::memcpy(&n, data.data() + 80, 4);
  StlMesh out;
  out.binary = true;
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = data.data() + 84 + 50 * static_cast<std::size_t>(t);
    std::array<Vec3, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const char* v = rec + 12 + 12 * k;  // the first 12 bytes are the stored normal
      tri[k] = {read_float(v), read_float(v + 4), read_float(v + 8)};
      if (!isfinite(tri[k]))
        throw InputError(name, 0, "",
                         "binary STL triangle " + std::to_string(t + 1) + ": vertex " + std::to_string(k + 1) +
                             " has a non-finite coordinate");
    }
    keep(name, out, tri, t + 1, 0);
  }
  return out;
}

// ASCII STL as a stream of whitespace-separated tokens, each with its line number.
class Tokens {
 public:
  Tokens(const std::string& name, const std::string& text) : name_(name), text_(text) {}

  bool done() {
    skip_space();
    return pos_ >= text_.size();
  }
  std::size_t line() const { return line_; }
  std::string next(const char* expected) {
    if (done()) fail(std::string("unexpected end of file, expected '") + expected + "'");
    const std::size_t b = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    return text_.substr(b, pos_ - b);
  }
  // Next token, lower-cased, must equal `kw` (STL keywords are case-insensitive in practice).
  void expect(const char* kw) {
    const std::size_t at = (skip_space(), line_);
    std::string t = next(kw);
    for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (t != kw) throw InputError(name_, at, "", "expected keyword '" + std::string(kw) + "', got '" + t + "'");
  }
  double number(const char* what) {
    const std::size_t at = (skip_space(), line_);
    const std::string t = next(what);
    double v = 0.0;
    const char* b = t.data() + (t.size() > 1 && t[0] == '+' ? 1 : 0);
    const auto [p, ec] = std::from_chars(b, t.data() + t.size(), v);
    if (ec != std::errc() || p != t.data() + t.size())
      throw InputError(name_, at, "", std::string("expected a number (") + what + "), got '" + t + "'");
    if (!std::isfinite(v)) throw InputError(name_, at, "", std::string("non-finite ") + what + " '" + t + "'");
    return v;
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  [[noreturn]] void fail(const std::string& msg) const { throw InputError(name_, line_, "", msg); }

 private:
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  const std::string& name_;
  const std::string& text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

StlMesh read_ascii(const std::string& name, const std::string& text) {
  StlMesh out;
  std::size_t facets = 0;
  Tokens tk(name, text);
  while (!tk.done()) {
    tk.expect("solid");
    tk.skip_line();  // the solid's name, if any
    for (;;) {
      const std::size_t at = (tk.done(), tk.line());
      std::string kw = tk.next("facet' or 'endsolid");
      for (char& c : kw) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (kw == "endsolid") {
        tk.skip_line();
        break;
      }
      if (kw != "facet") throw InputError(name, at, "", "expected keyword 'facet' or 'endsolid', got '" + kw + "'");
      tk.expect("normal");
      for (int k = 0; k < 3; ++k) tk.number("normal component");
      tk.expect("outer");
      tk.expect("loop");
      std::array<Vec3, 3> tri;
      for (int k = 0; k < 3; ++k) {
        tk.expect("vertex");
        const double x = tk.number("vertex coordinate");
        const double y = tk.number("vertex coordinate");
        tri[k] = {x, y, tk.number("vertex coordinate")};
      }
      tk.expect("endloop");
      tk.expect("endfacet");
      keep(name, out, tri, ++facets, at);
    }
  }
  return out;
}

}  // namespace

bool is_degenerate_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double longest2 = std::max({norm2(b - a), norm2(c - b), norm2(a - c)});
  return !(norm(cross(b - a, c - a)) > 1e-12 * longest2);
}

StlMesh read_stl(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (const std::string why = input_file_problem(file); !why.empty()) throw InputError(name, 0, "", "STL file " + why);
  std::string data = read_all(file);
  if (data.empty()) throw InputError(name, 0, "", "empty STL file");

  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    if (data.size() == 84 + 50 * static_cast<std::size_t>(n)) return read_binary(name, data);
  }
  // Not a well-sized binary file: ASCII if it starts with "solid", else a truncated binary. A
  // UTF-8 byte order mark (text editors add one) is no part of the text, as in TOML and CSV.
  const std::size_t text_start = data.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  std::size_t b = text_start;
  while (b < data.size() && std::isspace(static_cast<unsigned char>(data[b]))) ++b;
  std::string head = data.substr(b, 5);
  for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto text = data.begin() + static_cast<std::ptrdiff_t>(text_start);
  const bool printable = std::all_of(
      text, text + static_cast<std::ptrdiff_t>(std::min<std::size_t>(data.size() - text_start, 512)),
      [](char c) { return c == '\n' || c == '\r' || c == '\t' || (c >= 32 && c < 127); });
  if (head == "solid" && printable) {
    data.erase(0, text_start);
    StlMesh out = read_ascii(name, data);
    if (out.triangles.empty() && out.degenerate == 0) throw InputError(name, 0, "", "ASCII STL file holds no facets");
    return out;
  }
  if (data.size() < 84)
    throw InputError(name, 0, "",
                     "truncated binary STL: " + std::to_string(data.size()) + " bytes, less than the 84-byte header");
  std::uint32_t n = 0;
  std::memcpy(&n, data.data() + 80, 4);
  throw InputError(name, 0, "",
                   "truncated or malformed binary STL: the header announces " + std::to_string(n) + " triangles (" +
                       std::to_string(84 + 50 * static_cast<std::size_t>(n)) + " bytes) but the file has " +
                       std::to_string(data.size()) + " bytes");
}

}  // namespace mpdem

namespace mpdem {

// ---- STL barrier sources ----

void read_stl_barriers(const BarrierSource& src, const Model& model, Barriers& out) {
  const StlMesh stl = read_stl(src.stl);
  Material mat;
  int mat_index = model.material_index(src.material);  // -1 without materials
  if (mat_index < 0 && !model.materials.empty()) mat_index = 0;
  if (mat_index >= 0) mat = model.materials[mat_index];
  const int g = out.group_index(src.group.empty() ? src.stl.stem().string() : src.group);
  const double temp = src.temperature.value_or(std::numeric_limits<double>::quiet_NaN());
  std::int64_t next_id = 0;
  for (const std::int64_t bid : out.id) next_id = std::max(next_id, bid + 1);

  const std::string stl_name = src.stl.string();
  // A triangle that a placement step spoils: the step's key is to blame, at the scene's entry.
  const auto fail = [&](std::size_t j, const std::string& key, const std::string& step, const TriangleCheck& c) {
    const std::string what = c.fault == TriangleFault::ZeroArea ? "collapses to zero area" : c.what;
    const std::string at = stl.line[j] > 0 ? " (line " + std::to_string(stl.line[j]) + ")" : "";
    throw InputError(src.origin.empty() ? stl_name : src.origin, src.origin.empty() ? 0 : src.line, "barriers." + key,
                     "STL file '" + stl_name + "' triangle " + std::to_string(stl.number[j]) + at + ": " + what +
                         " after " + step + "; expected finite vertices and a non-zero, finite area");
  };
  const bool rotate = !(src.rotate_deg == Vec3{});
  const Vec3 offset = src.motion.displacement(0.0);
  for (std::size_t j = 0; j < stl.triangles.size(); ++j) {
    std::array<Vec3, 3> p = stl.triangles[j];
    // `step` is called only to word a failure.
    const auto check = [&](const char* key, const auto& step) {
      if (const TriangleCheck c = check_triangle(p[0], p[1], p[2]); c.fault != TriangleFault::None)
        fail(j, key, step(), c);
    };
    for (Vec3& v : p) v = v * src.scale;
    check("scale", [&] { return "scale = " + number_text(src.scale); });
    if (rotate) {
      for (Vec3& v : p) v = rotate_xyz_deg(v, src.rotate_deg);
      check("rotate_deg", [&] { return "rotate_deg = " + vec_text(src.rotate_deg); });
    }
    for (Vec3& v : p) v = v + src.translate;
    check("translate", [&] { return "translate = " + vec_text(src.translate); });
    // The motion law moves the element by B at t = 0: the moved vertices must stay finite.
    for (int k = 0; k < 3; ++k)
      if (!isfinite(p[k] + offset))
        fail(j, "motion.B", "the motion's offset B = " + vec_text(offset),
             {TriangleFault::NonFinite, "vertex " + std::to_string(k + 1) + " overflows"});
    if (!out.add(next_id, p[0], p[1], p[2], g, src.rigid ? kRigidYoung : mat.young, mat.poisson, src.motion,
                 src.thickness, temp))
      throw std::logic_error("read_stl_barriers: a checked triangle was refused");
    out.material.back() = mat_index;
    ++next_id;
  }
  if (stl.degenerate > 0)
    std::fprintf(stderr, "warning: %s: dropped %zu degenerate (zero-area) triangle(s) of %zu\n", stl_name.c_str(),
                 stl.degenerate, stl.triangles.size() + stl.degenerate);
  if (stl.triangles.empty()) throw InputError(src.stl.string(), 0, "", "STL file has no triangle with a non-zero area");
}

}  // namespace mpdem
