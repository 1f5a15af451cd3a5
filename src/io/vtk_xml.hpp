#pragma once
// A VTK XML file (.vtu, .vtp, .vti) assembled from markup and DataArrays, then written in one
// of three encodings (docs/output.md "VTK formats"):
//   ascii       values inline, 17 significant digits (doubles round-trip bit for bit);
//   binary      raw appended data: each array a UInt64 byte count and its little-endian bytes;
//   compressed  zlib-compressed appended data in VTK's vtkZLibDataCompressor layout: per array a
//               UInt64 header [blocks, block size, size of the partial last block (0: full),
//               compressed size of each block] followed by the blocks, each compressed alone.
// Arrays are referenced, not copied: their spans must stay valid until write() (names and other
// attributes are copied at once).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/rotation.hpp"
#include "core/vec3.hpp"
#include "model/params.hpp"

namespace mpdem {

// The declaration of one DataArray: what a .pvtu index repeats of its pieces' arrays.
struct VtuArray {
  const char* name;
  const char* type;  // VTK type: Float64, Int64, Int32, UInt8
  int components;    // 0: a scalar (written without NumberOfComponents)
};

// The points of every VTU file: m, 3 components.
inline constexpr VtuArray kVtuPoints{"Points", "Float64", 3};

// "ascii", "binary", "compressed": the [output] format key's values, and back (none for any
// other name).
const char* vtk_format_name(VtkFormat f);
std::optional<VtkFormat> vtk_format_from_name(std::string_view name);

class VtkXmlDocument {
 public:
  // Opens <VTKFile type="..."> with the attributes the format needs.
  VtkXmlDocument(VtkFormat format, std::string_view file_type);

  // Markup between arrays, written as given.
  void text(std::string_view xml);
  // A DataArray at the current place (indentation 8). extra: attributes added to its tag
  // (e.g. NumberOfTuples="1" for FieldData).
  void array(const VtuArray& decl, std::span<const double> v, std::string_view extra = {});
  void array(const VtuArray& decl, std::span<const Vec3> v);
  void array(const VtuArray& decl, std::span<const Quat> v);
  void array(const VtuArray& decl, std::span<const std::int64_t> v);
  void array(const VtuArray& decl, std::span<const std::int32_t> v, std::string_view extra = {});
  void array(const VtuArray& decl, std::span<const std::uint8_t> v);
  // The document keeps these values (for arrays the caller computes on the fly).
  void owned_array(const VtuArray& decl, const std::vector<double>& v);
  void owned_array(const VtuArray& decl, const std::vector<Vec3>& v);
  void owned_array(const VtuArray& decl, const std::vector<std::int64_t>& v);
  void owned_array(const VtuArray& decl, const std::vector<std::int32_t>& v);
  void owned_array(const VtuArray& decl, const std::vector<std::uint8_t>& v);

  // A FieldData value: one tuple (NumberOfTuples="1", which VTK's reader needs).
  void field(const char* name, double v);
  void field(const char* name, std::int32_t v);

  // The whole file: markup, arrays, the appended data (binary formats) and </VTKFile>.
  void write(std::ostream& os) const;

 private:
  enum class Kind : std::uint8_t { Float64, Int64, Int32, UInt8 };
  struct Item {
    std::string markup;               // text before the array (or the whole item when no array)
    const std::byte* data = nullptr;  // the array's bytes, little-endian
    std::size_t bytes = 0;            // its size
    Kind kind = Kind::Float64;
    int per_line = 1;  // values per line in ascii (a tuple)
    bool has_array = false;
  };
  void add(const VtuArray& decl, const void* data, std::size_t count, Kind kind, int per_line, std::string_view extra);
  void write_ascii(std::ostream& os, const Item& item) const;

  VtkFormat format_;
  std::vector<Item> items_;
  std::deque<std::vector<std::byte>> owned_;  // values of owned arrays (stable addresses)
};

// zlib-compressed VTK blocks of `bytes` (exposed for tests): the header and the blocks.
std::vector<std::byte> vtk_zlib_blocks(std::span<const std::byte> bytes);

}  // namespace mpdem
