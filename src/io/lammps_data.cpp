#include "io/lammps_data.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <unordered_set>

#include "core/input_error.hpp"

namespace mpdem {

namespace {

// Whitespace-separated tokens of a line, with any `# comment` removed.
std::vector<std::string_view> tokens(std::string_view line) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

bool parse(std::string_view s, double& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

template <class Int>
bool parse_int(std::string_view s, Int& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

bool is_number(std::string_view s) {
  double v = 0.0;
  return parse(s, v);
}

}  // namespace

LammpsData read_lammps_data(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::ifstream in(file);
  if (!in) throw InputError(name, 0, "", "cannot open the LAMMPS data file");
  LammpsData d;
  std::size_t declared_atoms = 0;
  bool have_atoms_count = false;
  int have_bounds = 0;  // bit per axis
  std::string line;
  std::size_t lineno = 0;
  std::getline(in, line);  // first line: title, always skipped
  ++lineno;
  // Next non-blank line of the current block into t; false at the end of the file or at a
  // section keyword line (a line not starting with a number), whose keyword goes to `section`.
  std::string section;
  std::vector<std::string_view> t;
  auto next_row = [&] {
    while (std::getline(in, line)) {
      ++lineno;
      t = tokens(line);
      if (t.empty()) continue;
      if (is_number(t[0])) return true;
      section = std::string(t[0]);
      return false;
    }
    return false;
  };

  // Header: counts and bounds until the first section keyword.
  while (next_row()) {
    if (t.size() == 2 && t[1] == "atoms") {
      if (!parse_int(t[0], declared_atoms)) throw InputError(name, lineno, "atoms", "expected a count of atoms");
      have_atoms_count = true;
    } else if (t.size() == 3 && t[1] == "atom" && t[2] == "types") {
      if (!parse_int(t[0], d.atom_types)) throw InputError(name, lineno, "atom types", "expected a count");
    } else if (t.size() == 4 && (t[2] == "xlo" || t[2] == "ylo" || t[2] == "zlo")) {
      double lo = 0.0, hi = 0.0;
      if (!parse(t[0], lo) || !parse(t[1], hi) || !(lo < hi))
        throw InputError(name, lineno, std::string(t[2]), "expected two finite bounds lo < hi");
      const int axis = t[2][0] - 'x';
      (axis == 0 ? d.lo.x : axis == 1 ? d.lo.y : d.lo.z) = lo;
      (axis == 0 ? d.hi.x : axis == 1 ? d.hi.y : d.hi.z) = hi;
      have_bounds |= 1 << axis;
    }
    // Other header lines (bonds, tilt factors, ...) do not concern granular atoms.
  }
  if (!have_atoms_count) throw InputError(name, 0, "atoms", "the header has no 'N atoms' line");
  if (have_bounds != 7) throw InputError(name, 0, "xlo xhi", "the header needs xlo xhi, ylo yhi and zlo zhi bounds");

  // Sections: rows until the next keyword line; only Atoms is kept.
  bool seen_atoms = false;
  std::unordered_set<std::int64_t> ids;
  d.atoms.reserve(declared_atoms);
  while (!section.empty()) {
    const bool atoms = section == "Atoms";
    if (atoms) seen_atoms = true;
    section.clear();
    while (next_row()) {
      if (!atoms) continue;
      if (t.size() != 7 && t.size() != 10)
        throw InputError(name, lineno, "Atoms",
                         "expected 'id type diameter density x y z' (7 columns, or 10 with image flags)");
      LammpsAtom a;
      if (!parse_int(t[0], a.id)) throw InputError(name, lineno, "id", "expected an integer id");
      if (!parse_int(t[1], a.type) || a.type < 1) throw InputError(name, lineno, "type", "expected an atom type >= 1");
      if (!parse(t[2], a.diameter) || !(a.diameter > 0.0) || !std::isfinite(a.diameter))
        throw InputError(name, lineno, "diameter", "expected a positive diameter [m]");
      if (!parse(t[3], a.density) || !(a.density > 0.0) || !std::isfinite(a.density))
        throw InputError(name, lineno, "density", "expected a positive density [kg/m^3]");
      if (!parse(t[4], a.x.x) || !parse(t[5], a.x.y) || !parse(t[6], a.x.z) || !std::isfinite(a.x.x) ||
          !std::isfinite(a.x.y) || !std::isfinite(a.x.z))
        throw InputError(name, lineno, "x y z", "expected three finite coordinates [m]");
      if (!ids.insert(a.id).second) throw InputError(name, lineno, "id", "duplicate atom id " + std::to_string(a.id));
      d.atoms.push_back(a);
    }
  }
  if (!seen_atoms) throw InputError(name, 0, "Atoms", "the file has no Atoms section");
  if (d.atoms.size() != declared_atoms)
    throw InputError(name, 0, "atoms",
                     "the header declares " + std::to_string(declared_atoms) + " atoms but the Atoms section has " +
                         std::to_string(d.atoms.size()));
  return d;
}

}  // namespace mpdem
