#include "io/pvd_index.hpp"

#include <charconv>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/atomic_file.hpp"

namespace mpdem {

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string xml_unescape(const std::string& s) {
  static const std::pair<const char*, char> table[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool replaced = false;
    if (s[i] == '&') {
      for (const auto& [entity, ch] : table) {
        const std::string_view e(entity);
        if (s.compare(i, e.size(), e) == 0) {
          out += ch;
          i += e.size();
          replaced = true;
          break;
        }
      }
    }
    if (!replaced) out += s[i++];
  }
  return out;
}

std::string format_time(double t) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, t, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}

// Value of attribute `name` in one tag of our own output (double-quoted, no spaces around '=').
bool attribute(const std::string& tag, const std::string& name, std::string& value) {
  const std::string key = " " + name + "=\"";
  const auto at = tag.find(key);
  if (at == std::string::npos) return false;
  const auto begin = at + key.size();
  const auto end = tag.find('"', begin);
  if (end == std::string::npos) return false;
  value = xml_unescape(tag.substr(begin, end - begin));
  return true;
}

}  // namespace

PvdIndex::PvdIndex(std::filesystem::path pvd_file) : file_(std::move(pvd_file)) { write(); }

PvdIndex::PvdIndex(std::filesystem::path pvd_file, double keep_until) : file_(std::move(pvd_file)) {
  if (std::filesystem::exists(file_)) {
    std::ifstream in(file_);
    if (!in) throw std::runtime_error("cannot read '" + file_.string() + "'");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    // Only the DataSet tags written by write() are parsed; this is not a general XML reader.
    for (std::size_t pos = text.find("<DataSet"); pos != std::string::npos; pos = text.find("<DataSet", pos + 1)) {
      const auto end = text.find("/>", pos);
      if (end == std::string::npos) break;
      const std::string tag = text.substr(pos, end - pos);
      std::string t, f;
      if (!attribute(tag, "timestep", t) || !attribute(tag, "file", f))
        throw std::runtime_error("'" + file_.string() + "': DataSet without timestep or file");
      double time = 0.0;
      const auto r = std::from_chars(t.data(), t.data() + t.size(), time);
      if (r.ec != std::errc() || r.ptr != t.data() + t.size())
        throw std::runtime_error("'" + file_.string() + "': bad timestep '" + t + "'");
      if (time <= keep_until) entries_.push_back({time, f});
    }
  }
  write();
}

void PvdIndex::add(double time, const std::string& relative_vtu_name) {
  entries_.push_back({time, relative_vtu_name});
  try {
    write();
  } catch (...) {
    entries_.pop_back();  // keep memory and file in agreement
    throw;
  }
}

void PvdIndex::write() const {
  write_file_atomically(
      file_,
      [this](std::ostream& os) {
        os << "<?xml version=\"1.0\"?>\n"
              "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
              "  <Collection>\n";
        for (const Entry& e : entries_)
          os << "    <DataSet timestep=\"" << format_time(e.time) << "\" group=\"\" part=\"0\" file=\""
             << xml_escape(e.file) << "\"/>\n";
        os << "  </Collection>\n"
              "</VTKFile>\n";
      },
      Durability::kill);
}

}  // namespace mpdem
