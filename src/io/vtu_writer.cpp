#include "io/vtu_writer.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "io/atomic_file.hpp"

namespace mpdem {

namespace {

// Buffers formatted text and hands it to the stream in large chunks; formatting with
// std::to_chars is locale independent and, at 17 digits, exact for doubles.
class TextSink {
 public:
  explicit TextSink(std::ostream& os) : os_(os) { buf_.reserve(kChunk + 64); }
  ~TextSink() { drain(); }
  TextSink(const TextSink&) = delete;
  TextSink& operator=(const TextSink&) = delete;

  void text(std::string_view s) {
    if (s.empty()) return;
    buf_ += s;
    last_ = s.back();
    if (buf_.size() >= kChunk) drain();
  }
  // A number followed by a space: the separator of values inside a DataArray.
  void value(double v) {
    number(v);
    text(" ");
  }
  void value(std::int64_t v) {
    number(v);
    text(" ");
  }
  // A bare number, for attributes.
  void number(double v) {
    char tmp[32];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, v, std::chars_format::general, 17);
    put(tmp, r.ptr);
  }
  void number(std::int64_t v) {
    char tmp[24];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
    put(tmp, r.ptr);
  }
  bool at_line_start() const { return last_ == '\n'; }
  void drain() {
    os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 16;
  void put(const char* b, const char* e) {
    buf_.append(b, e);
    last_ = e[-1];
    if (buf_.size() >= kChunk) drain();
  }
  std::ostream& os_;
  std::string buf_;
  char last_ = '\0';  // last character written, survives drain()
};

// Opening tag of a DataArray; `components` = 0 omits NumberOfComponents (scalar).
void open_array(TextSink& s, const VtuArray& a) {
  s.text("        <DataArray type=\"");
  s.text(a.type);
  s.text("\" Name=\"");
  s.text(a.name);
  s.text("\"");
  if (a.components > 0) {
    s.text(" NumberOfComponents=\"");
    s.number(std::int64_t{a.components});
    s.text("\"");
  }
  s.text(" format=\"ascii\">\n");
}
void close_array(TextSink& s) {
  if (!s.at_line_start()) s.text("\n");
  s.text("        </DataArray>\n");
}

void scalar_array(TextSink& s, const VtuArray& a, std::span<const double> v) {
  open_array(s, a);
  for (double x : v) s.value(x);
  close_array(s);
}
void int_array(TextSink& s, const VtuArray& a, std::span<const int> v) {
  open_array(s, a);
  for (int x : v) s.value(std::int64_t{x});
  close_array(s);
}
void id_array(TextSink& s, const VtuArray& a, std::span<const std::int64_t> v) {
  open_array(s, a);
  for (std::int64_t x : v) s.value(x);
  close_array(s);
}
void vector_array(TextSink& s, const VtuArray& a, std::span<const Vec3> v) {
  open_array(s, a);
  for (const Vec3& x : v) {
    s.value(x.x);
    s.value(x.y);
    s.value(x.z);
    s.text("\n");  // one tuple per line keeps the file readable
  }
  close_array(s);
}

void header(TextSink& s, double time, std::size_t points, std::size_t cells) {
  s.text("<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
         "    <FieldData>\n"
         "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">");
  s.number(time);
  s.text("</DataArray>\n"
         "    </FieldData>\n"
         "    <Piece NumberOfPoints=\"");
  s.number(static_cast<std::int64_t>(points));
  s.text("\" NumberOfCells=\"");
  s.number(static_cast<std::int64_t>(cells));
  s.text("\">\n");
}

// Cells that each use `per_cell` consecutive points of their own, all of one VTK type.
void cells(TextSink& s, std::size_t count, int per_cell, int vtk_type) {
  s.text("      <Cells>\n");
  open_array(s, {"connectivity", "Int64", 0});
  const auto n = static_cast<std::int64_t>(count) * per_cell;
  for (std::int64_t k = 0; k < n; ++k) s.value(k);
  close_array(s);
  open_array(s, {"offsets", "Int64", 0});
  for (std::int64_t c = 1; c <= static_cast<std::int64_t>(count); ++c) s.value(c * per_cell);
  close_array(s);
  open_array(s, {"types", "UInt8", 0});
  for (std::size_t c = 0; c < count; ++c) s.value(std::int64_t{vtk_type});
  close_array(s);
  s.text("      </Cells>\n");
}

void footer(TextSink& s) {
  s.text("    </Piece>\n"
         "  </UnstructuredGrid>\n"
         "</VTKFile>\n");
}

constexpr int kVtkVertex = 1;
constexpr int kVtkTriangle = 5;

// The particle point arrays; write_particles_vtu writes each by its index here, in this order.
enum ParticleArray : std::size_t {
  kId,
  kRadius,
  kMaterial,
  kFixed,
  kVelocity,
  kAngularVelocity,
  kForce,
  kTemperature,
  kCharge,
  kOrientation,
  kParticleArrayCount
};
constexpr std::array<VtuArray, kParticleArrayCount> kParticleArrays{{
    {"id", "Int64", 0},                  // -
    {"radius", "Float64", 0},            // m
    {"material", "Int32", 0},            // index into the scene's materials
    {"fixed", "UInt8", 0},               // 1: prescribed motion
    {"velocity", "Float64", 3},          // m/s
    {"angular_velocity", "Float64", 3},  // rad/s
    {"force", "Float64", 3},             // N
    {"temperature", "Float64", 0},       // K
    {"charge", "Float64", 0},            // C
    {"orientation", "Float64", 4},       // unit quaternion (w, x, y, z), body -> world
}};

}  // namespace

std::span<const VtuArray> particle_point_arrays() { return kParticleArrays; }

void write_particles_vtu(const std::filesystem::path& file, const Particles& p, double time) {
  write_file_atomically(file, [&](std::ostream& os) {
    TextSink s(os);
    const std::size_t n = p.size();  // the owned particles: ghosts (periodic images) are not written
    const auto owned = [n](const auto& a) { return std::span(a.data(), n); };
    const auto& a = kParticleArrays;  // names, types, units
    header(s, time, n, n);
    s.text("      <PointData Scalars=\"");
    s.text(kParticleActiveScalars);
    s.text("\" Vectors=\"");
    s.text(kParticleActiveVectors);
    s.text("\">\n");
    id_array(s, a[kId], owned(p.id));
    scalar_array(s, a[kRadius], owned(p.radius));
    int_array(s, a[kMaterial], owned(p.material));
    int_array(s, a[kFixed], std::vector<int>(p.fixed.begin(), p.fixed.begin() + static_cast<std::ptrdiff_t>(n)));
    vector_array(s, a[kVelocity], owned(p.v));
    vector_array(s, a[kAngularVelocity], owned(p.w));
    vector_array(s, a[kForce], owned(p.force));
    scalar_array(s, a[kTemperature], owned(p.T));
    scalar_array(s, a[kCharge], owned(p.charge));
    open_array(s, a[kOrientation]);
    for (const Quat& q : owned(p.q)) {
      s.value(q.w);
      s.value(q.x);
      s.value(q.y);
      s.value(q.z);
      s.text("\n");
    }
    close_array(s);
    s.text("      </PointData>\n"
           "      <Points>\n");
    open_array(s, kVtuPoints);  // m, centres
    for (const Vec3& x : owned(p.x)) {
      s.value(x.x);
      s.value(x.y);
      s.value(x.z);
      s.text("\n");
    }
    close_array(s);
    s.text("      </Points>\n");
    cells(s, n, 1, kVtkVertex);
    footer(s);
  });
}

void write_barriers_vtu(const std::filesystem::path& file, const Barriers& b, double time) {
  write_file_atomically(file, [&](std::ostream& os) {
    TextSink s(os);
    const std::size_t m = b.size();
    header(s, time, 3 * m, m);
    s.text("      <CellData Scalars=\"pressure\" Vectors=\"force\">\n");
    id_array(s, {"id", "Int64", 0}, b.id);                    // -
    int_array(s, {"group", "Int32", 0}, b.group);             // index into group_names
    vector_array(s, {"force", "Float64", 3}, b.force);        // N
    vector_array(s, {"moment", "Float64", 3}, b.moment);      // N m, about the element centre
    scalar_array(s, {"pressure", "Float64", 0}, b.pressure);  // Pa
    // Elements with an activity window are all written (at their law's place); 0 marks the
    // switched-off ones, whose loads are zero.
    if (b.timed()) int_array(s, {"active", "UInt8", 0}, std::vector<int>(b.active.begin(), b.active.end()));
    // A rotating element's normal turns and its velocity varies over it: the one at its centre.
    if (b.rotating()) {
      std::vector<Vec3> normal(m), velocity(m);  // [M] -, m/s
      for (std::size_t e = 0; e < m; ++e) {
        normal[e] = b.current_normal(e);
        velocity[e] = b.surface_velocity(e, b.centre(e));
      }
      vector_array(s, {"normal", "Float64", 3}, normal);
      vector_array(s, {"velocity", "Float64", 3}, velocity);
    } else {
      vector_array(s, {"normal", "Float64", 3}, b.normal);      // -, unit
      vector_array(s, {"velocity", "Float64", 3}, b.velocity);  // m/s
    }
    s.text("      </CellData>\n"
           "      <Points>\n");
    open_array(s, kVtuPoints);  // m, current vertex positions
    for (std::size_t e = 0; e < m; ++e)
      for (int k = 0; k < 3; ++k) {
        const Vec3 v = b.vertex(e, k);
        s.value(v.x);
        s.value(v.y);
        s.value(v.z);
        s.text("\n");
      }
    close_array(s);
    s.text("      </Points>\n");
    cells(s, m, 3, kVtkTriangle);
    footer(s);
  });
}

}  // namespace mpdem
