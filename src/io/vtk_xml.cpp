#include "io/vtk_xml.hpp"

#include <libdeflate.h>

#include <bit>
#include <charconv>
#include <cstring>
#include <stdexcept>

namespace mpdem {

static_assert(std::endian::native == std::endian::little, "the VTK writers declare LittleEndian");
static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Quat) == 4 * sizeof(double),
              "Vec3 and Quat arrays are written as their doubles");

namespace {

// VTK's default block size for compressed data (vtkXMLWriter), bytes before compression.
constexpr std::size_t kBlockBytes = std::size_t{1} << 15;
// Fastest deflate level: the compressed format saves disk space at a bounded write cost.
constexpr int kDeflateLevel = 1;
// Compressed size / size of an array's first block above which the array is stored (level 0).
constexpr double kStoreAbove = 0.92;

// Buffers formatted text and hands it to the stream in large chunks; std::to_chars is locale
// independent and, at 17 digits, exact for doubles.
class TextSink {
 public:
  explicit TextSink(std::ostream& os) : os_(os) { buf_.reserve(kChunk + 64); }
  ~TextSink() { drain(); }
  TextSink(const TextSink&) = delete;
  TextSink& operator=(const TextSink&) = delete;
  void text(std::string_view s) {
    buf_ += s;
    if (buf_.size() >= kChunk) drain();
  }
  void number(double v) {
    char tmp[32];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, v, std::chars_format::general, 17);
    buf_.append(tmp, r.ptr);
  }
  void number(std::int64_t v) {
    char tmp[24];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
    buf_.append(tmp, r.ptr);
  }
  void drain() {
    os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 16;
  std::ostream& os_;
  std::string buf_;
};

template <class T>
T load(const std::byte* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

}  // namespace

const char* vtk_format_name(VtkFormat f) {
  switch (f) {
    case VtkFormat::Ascii: return "ascii";
    case VtkFormat::Binary: return "binary";
    case VtkFormat::Compressed: return "compressed";
  }
  return "?";
}

std::optional<VtkFormat> vtk_format_from_name(std::string_view name) {
  for (const VtkFormat f : {VtkFormat::Ascii, VtkFormat::Binary, VtkFormat::Compressed})
    if (name == vtk_format_name(f)) return f;
  return std::nullopt;
}

std::vector<std::byte> vtk_zlib_blocks(std::span<const std::byte> bytes) {
  const std::size_t blocks = (bytes.size() + kBlockBytes - 1) / kBlockBytes;
  // Each block is a complete zlib stream, as VTK reads them (libdeflate writes the zlib format).
  // Arrays whose first block hardly compresses (velocities, forces: random mantissas) are stored
  // in uncompressed deflate blocks: deflate would spend most of the time for a few percent.
  int level = kDeflateLevel;
  if (blocks > 1) {
    libdeflate_compressor* c = libdeflate_alloc_compressor(kDeflateLevel);
    if (c == nullptr) throw std::runtime_error("libdeflate could not allocate a compressor");
    std::vector<std::byte> trial(libdeflate_zlib_compress_bound(c, kBlockBytes));
    const std::size_t size = libdeflate_zlib_compress(c, bytes.data(), kBlockBytes, trial.data(), trial.size());
    libdeflate_free_compressor(c);
    if (static_cast<double>(size) > kStoreAbove * static_cast<double>(kBlockBytes)) level = 0;
  }
  // Blocks are independent, so the run's threads share them (the bytes do not depend on that).
  std::vector<std::vector<std::byte>> packed(blocks);
  bool failed = false;
#pragma omp parallel if (blocks > 8) reduction(|| : failed)
  {
    libdeflate_compressor* c = libdeflate_alloc_compressor(level);
    failed = c == nullptr;
    std::vector<std::byte> scratch(c ? libdeflate_zlib_compress_bound(c, kBlockBytes) : 0);
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < blocks; ++k) {
      if (c == nullptr) continue;
      const std::size_t begin = k * kBlockBytes;
      const std::size_t n = std::min(kBlockBytes, bytes.size() - begin);
      const std::size_t size = libdeflate_zlib_compress(c, bytes.data() + begin, n, scratch.data(), scratch.size());
      failed = failed || size == 0;
      packed[k].assign(scratch.begin(), scratch.begin() + static_cast<std::ptrdiff_t>(size));
    }
    if (c) libdeflate_free_compressor(c);
  }
  if (failed) throw std::runtime_error("libdeflate could not compress a block");
  std::vector<std::uint64_t> header{blocks, kBlockBytes, bytes.size() % kBlockBytes};
  for (const auto& b : packed) header.push_back(b.size());
  std::size_t total = 8 * header.size();
  for (const auto& b : packed) total += b.size();
  std::vector<std::byte> out(total);
  std::memcpy(out.data(), header.data(), 8 * header.size());
  std::size_t at = 8 * header.size();
  for (const auto& b : packed) {
    if (!b.empty()) std::memcpy(out.data() + at, b.data(), b.size());
    at += b.size();
  }
  return out;
}

VtkXmlDocument::VtkXmlDocument(VtkFormat format, std::string_view file_type) : format_(format) {
  std::string head = "<?xml version=\"1.0\"?>\n<VTKFile type=\"";
  head += file_type;
  head += "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"";
  if (format == VtkFormat::Compressed) head += " compressor=\"vtkZLibDataCompressor\"";
  head += ">\n";
  text(head);
}

void VtkXmlDocument::text(std::string_view xml) {
  if (items_.empty() || items_.back().has_array) items_.emplace_back();
  items_.back().markup += xml;
}

void VtkXmlDocument::add(const VtuArray& decl, const void* data, std::size_t count, Kind kind, int per_line,
                         std::string_view extra) {
  static constexpr std::size_t kSize[] = {8, 8, 4, 1};
  std::string tag = "        <DataArray type=\"";
  tag += decl.type;
  tag += "\" Name=\"";
  tag += decl.name;
  tag += "\"";
  if (decl.components > 0) tag += " NumberOfComponents=\"" + std::to_string(decl.components) + "\"";
  if (!extra.empty()) {
    tag += " ";
    tag += extra;
  }
  text(tag);
  Item& it = items_.back();
  it.has_array = true;
  it.data = static_cast<const std::byte*>(data);
  it.bytes = count * kSize[static_cast<int>(kind)];
  it.kind = kind;
  it.per_line = per_line;
}

void VtkXmlDocument::array(const VtuArray& d, std::span<const double> v, std::string_view extra) {
  add(d, v.data(), v.size(), Kind::Float64, 1, extra);
}
void VtkXmlDocument::array(const VtuArray& d, std::span<const Vec3> v) {
  add(d, v.data(), 3 * v.size(), Kind::Float64, 3, {});
}
void VtkXmlDocument::array(const VtuArray& d, std::span<const Quat> v) {
  add(d, v.data(), 4 * v.size(), Kind::Float64, 4, {});
}
void VtkXmlDocument::array(const VtuArray& d, std::span<const std::int64_t> v) {
  add(d, v.data(), v.size(), Kind::Int64, 1, {});
}
void VtkXmlDocument::array(const VtuArray& d, std::span<const std::int32_t> v, std::string_view extra) {
  add(d, v.data(), v.size(), Kind::Int32, 1, extra);
}
void VtkXmlDocument::array(const VtuArray& d, std::span<const std::uint8_t> v) {
  add(d, v.data(), v.size(), Kind::UInt8, 1, {});
}

namespace {
template <class T>
std::vector<std::byte> as_bytes(const std::vector<T>& v) {
  std::vector<std::byte> b(v.size() * sizeof(T));
  if (!v.empty()) std::memcpy(b.data(), v.data(), b.size());
  return b;
}
}  // namespace

void VtkXmlDocument::owned_array(const VtuArray& d, const std::vector<double>& v) {
  const std::size_t n = v.size();
  add(d, owned_.emplace_back(as_bytes(v)).data(), n, Kind::Float64, 1, {});
}
void VtkXmlDocument::owned_array(const VtuArray& d, const std::vector<Vec3>& v) {
  const std::size_t n = v.size();
  add(d, owned_.emplace_back(as_bytes(v)).data(), 3 * n, Kind::Float64, 3, {});
}
void VtkXmlDocument::owned_array(const VtuArray& d, const std::vector<std::int64_t>& v) {
  const std::size_t n = v.size();
  add(d, owned_.emplace_back(as_bytes(v)).data(), n, Kind::Int64, 1, {});
}
void VtkXmlDocument::owned_array(const VtuArray& d, const std::vector<std::int32_t>& v) {
  const std::size_t n = v.size();
  add(d, owned_.emplace_back(as_bytes(v)).data(), n, Kind::Int32, 1, {});
}
void VtkXmlDocument::owned_array(const VtuArray& d, const std::vector<std::uint8_t>& v) {
  const std::size_t n = v.size();
  add(d, owned_.emplace_back(as_bytes(v)).data(), n, Kind::UInt8, 1, {});
}

void VtkXmlDocument::field(const char* name, double v) {
  const std::size_t n = 1;
  add({name, "Float64", 0}, owned_.emplace_back(as_bytes(std::vector<double>{v})).data(), n, Kind::Float64, 1,
      "NumberOfTuples=\"1\"");
}
void VtkXmlDocument::field(const char* name, std::int32_t v) {
  const std::size_t n = 1;
  add({name, "Int32", 0}, owned_.emplace_back(as_bytes(std::vector<std::int32_t>{v})).data(), n, Kind::Int32, 1,
      "NumberOfTuples=\"1\"");
}

void VtkXmlDocument::write_ascii(std::ostream& os, const Item& it) const {
  TextSink s(os);
  s.text(it.markup);
  s.text(" format=\"ascii\">");
  const bool multi = it.per_line > 1;
  if (multi) s.text("\n");
  const std::size_t size = it.kind == Kind::Int32 ? 4 : (it.kind == Kind::UInt8 ? 1 : 8);
  const std::size_t n = it.bytes / size;
  for (std::size_t k = 0; k < n; ++k) {
    const std::byte* p = it.data + k * size;
    switch (it.kind) {
      case Kind::Float64: s.number(load<double>(p)); break;
      case Kind::Int64: s.number(load<std::int64_t>(p)); break;
      case Kind::Int32: s.number(std::int64_t{load<std::int32_t>(p)}); break;
      case Kind::UInt8: s.number(std::int64_t{load<std::uint8_t>(p)}); break;
    }
    // one tuple per line keeps vector arrays readable
    s.text(multi && (k + 1) % static_cast<std::size_t>(it.per_line) == 0 ? "\n" : " ");
  }
  s.text(multi ? "        </DataArray>\n" : "</DataArray>\n");
}

void VtkXmlDocument::write(std::ostream& os) const {
  if (format_ == VtkFormat::Ascii) {
    for (const Item& it : items_) {
      if (it.has_array) write_ascii(os, it);
      else os << it.markup;
    }
    os << "</VTKFile>\n";
    return;
  }
  // Appended: the markup with each array's offset into the appended block, then the block. The
  // block holds the arrays in reverse order of their tags: meshio re-labels the offsets as it
  // walks the block, and a re-labelled tag that came before the one it looks for could match.
  std::vector<const Item*> arrays;
  for (const Item& it : items_)
    if (it.has_array) arrays.push_back(&it);
  std::vector<std::vector<std::byte>> packed(arrays.size());  // compressed arrays (Compressed only)
  std::vector<std::uint64_t> offset(arrays.size());
  std::uint64_t at = 0;
  for (std::size_t k = arrays.size(); k-- > 0;) {
    offset[k] = at;
    if (format_ == VtkFormat::Compressed) {
      packed[k] = vtk_zlib_blocks({arrays[k]->data, arrays[k]->bytes});
      at += packed[k].size();
    } else {
      at += sizeof(std::uint64_t) + arrays[k]->bytes;
    }
  }
  std::size_t k = 0;
  for (const Item& it : items_) {
    os << it.markup;
    if (it.has_array) os << " format=\"appended\" offset=\"" << offset[k++] << "\"/>\n";
  }
  os << "  <AppendedData encoding=\"raw\">\n   _";
  for (std::size_t j = arrays.size(); j-- > 0;) {
    if (format_ == VtkFormat::Compressed) {
      os.write(reinterpret_cast<const char*>(packed[j].data()), static_cast<std::streamsize>(packed[j].size()));
    } else {
      const std::uint64_t bytes = arrays[j]->bytes;
      os.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
      os.write(reinterpret_cast<const char*>(arrays[j]->data), static_cast<std::streamsize>(bytes));
    }
  }
  os << "\n  </AppendedData>\n</VTKFile>\n";
}

}  // namespace mpdem
