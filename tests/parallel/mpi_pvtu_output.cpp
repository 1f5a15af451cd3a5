// Particle snapshots on several ranks as ParaView pieces and .pvtu indexes (docs/output.md,
// "Particle snapshots on several ranks"), against the one-rank .vtu of the same run (ctest runs
// this under mpirun -np 1, 2, 3, 4). A rolling thermal cluster in a box runs 600 steps with
// output on all ranks, then on rank 0 alone; the files are read back here (a small parser of
// mpdem's own ASCII VTK XML) and by tests/parallel/check_pvtu.py (meshio):
//  - particles.pvd lists one .pvtu per snapshot (one rank: one .vtu, byte for byte the one-rank
//    run's), at the one-rank run's times;
//  - each .pvtu declares the arrays its pieces hold and lists one piece per rank;
//  - the union of the pieces is the one-rank snapshot: the same ids, each in one piece, ids
//    ascending within a piece, every array equal to 1e-10 of its largest magnitude (the
//    rank-count round-off of docs/parallel.md), integer arrays and the time exactly;
//  - each piece holds its rank's particles: in every snapshot within a skin of the rank's brick,
//    in the last exactly the ones the rank owns at the end;
//  - the particle CSV snapshots stay gathered: the one-rank run's rows, in id order.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "neighbor/neighbor_search.hpp"
#include "parallel/communicator.hpp"
#include "parallel/halo_exchange.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 2e-6;  // s
constexpr int kSteps = 600;

// 6 x 6 x 5 spheres (r = 1-1.05 mm) in an open box, rolling and conducting heat, with charges
// (no field: they only fill the array); particle VTU every 200 steps, CSV and barriers every 300.
Scene cluster() {
  Scene s = dense_scene(6, 6, 5, 1e-3, 0.05, 2.12e-3, 0.15, 5, kDt);
  Params& prm = s.model.params;
  prm.time.duration = kSteps * kDt;
  prm.analysis.thermal = true;
  for (ContactLawParams* c : {&prm.contact.particle_particle, &prm.contact.particle_barrier}) c->mu_rolling = 0.05;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    s.particles.T[i] = 290.0 + static_cast<double>(s.particles.id[i] % 21);
    s.particles.charge[i] = 1e-12 * static_cast<double>(s.particles.id[i] % 7);
  }
  prm.output.particles_every = 200 * kDt;
  prm.output.format = VtkFormat::Ascii;  // the pieces are parsed as text here (and by check_pvtu.py)
  prm.output.particle_csv_every = 300 * kDt;
  prm.output.barriers_every = 300 * kDt;
  return s;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// --- a reader of mpdem's own ASCII VTK XML (not a general XML parser) ---

// The value of attribute `name` of a tag ("" when absent).
std::string attr(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = tag.find(key);
  if (at == std::string::npos) return "";
  const auto begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

// The opening tags `<element ...>` in text, in order.
std::vector<std::string> tags(const std::string& text, const std::string& element) {
  std::vector<std::string> out;
  for (auto at = text.find("<" + element + " "); at != std::string::npos; at = text.find("<" + element + " ", at + 1))
    out.push_back(text.substr(at, text.find('>', at) - at));
  return out;
}

// The text between `<element` and `</element>`.
std::string section(const std::string& text, const std::string& element) {
  const auto begin = text.find("<" + element);
  const auto end = text.find("</" + element + ">");
  return begin == std::string::npos || end == std::string::npos ? "" : text.substr(begin, end - begin);
}

struct Decl {  // a (P)DataArray's declaration
  std::string name, type;
  int components;
  bool operator==(const Decl&) const = default;
};
std::vector<Decl> declared(const std::string& text, const std::string& element) {
  std::vector<Decl> out;
  for (const std::string& t : tags(text, element)) {
    const std::string c = attr(t, "NumberOfComponents");
    out.push_back({attr(t, "Name"), attr(t, "type"), c.empty() ? 0 : std::stoi(c)});
  }
  return out;
}

struct Vtu {
  double time = 0;                                    // s
  std::vector<Decl> arrays;                           // PointData's, then the Points
  std::map<std::string, std::vector<double>> values;  // by name, tuple after tuple
  std::map<std::string, int> components;              // by name, 1 for a scalar
  std::size_t points = 0;
};
Vtu read_vtu(const fs::path& f) {
  const std::string text = slurp(f);
  Vtu v;
  v.points = std::stoul(attr(tags(text, "Piece").at(0), "NumberOfPoints"));
  v.arrays = declared(section(text, "PointData"), "DataArray");
  for (const Decl& d : declared(section(text, "Points"), "DataArray")) v.arrays.push_back(d);
  for (auto at = text.find("<DataArray "); at != std::string::npos; at = text.find("<DataArray ", at + 1)) {
    const auto open_end = text.find('>', at);
    const std::string tag = text.substr(at, open_end - at);
    std::istringstream in(text.substr(open_end + 1, text.find("</DataArray>", open_end) - open_end - 1));
    std::vector<double>& out = v.values[attr(tag, "Name")];
    for (std::string tok; in >> tok;) out.push_back(std::strtod(tok.c_str(), nullptr));
    const std::string c = attr(tag, "NumberOfComponents");
    v.components[attr(tag, "Name")] = c.empty() ? 1 : std::stoi(c);
  }
  v.time = v.values.at("TimeValue").at(0);
  return v;
}

// particles.pvd: (time, file relative to the output folder) per snapshot.
std::vector<std::pair<double, std::string>> read_pvd(const fs::path& f) {
  std::vector<std::pair<double, std::string>> out;
  for (const std::string& t : tags(slurp(f), "DataSet"))
    out.emplace_back(std::stod(attr(t, "timestep")), attr(t, "file"));
  return out;
}

// Row of particle `id` in v; throws when it is absent.
std::size_t row_of(const Vtu& v, double id) {
  const std::vector<double>& ids = v.values.at("id");
  const auto it = std::find(ids.begin(), ids.end(), id);
  if (it == ids.end()) throw std::runtime_error("id " + std::to_string(id) + " missing");
  return static_cast<std::size_t>(it - ids.begin());
}

// The union of a .pvtu's pieces compared with the one-rank .vtu, by id; returns the largest
// deviation relative to each array's largest magnitude (EXPECTs the rest).
double compare_with_one_rank(const fs::path& pvtu, const Vtu& one, int ranks) {
  const std::string index = slurp(pvtu);
  std::vector<Decl> promised = declared(section(index, "PPointData"), "PDataArray");
  for (const Decl& d : declared(section(index, "PPoints"), "PDataArray")) promised.push_back(d);
  EXPECT_EQ(promised, one.arrays) << pvtu;
  const std::vector<std::string> pieces = tags(index, "Piece");
  EXPECT_EQ(pieces.size(), static_cast<std::size_t>(ranks)) << pvtu;
  std::map<double, int> seen;  // id -> pieces holding it
  double worst = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::string source = attr(pieces[k], "Source");
    const std::string stem = pvtu.stem().string();
    EXPECT_EQ(source, stem + "_p" + std::to_string(k) + ".vtu");
    const Vtu piece = read_vtu(pvtu.parent_path() / source);
    EXPECT_EQ(piece.arrays, one.arrays) << source;
    EXPECT_EQ(piece.time, one.time) << source;
    const std::vector<double>& ids = piece.values.at("id");
    EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end())) << source;
    for (std::size_t i = 0; i < piece.points; ++i) {
      ++seen[ids[i]];
      const std::size_t j = row_of(one, ids[i]);
      for (const Decl& d : one.arrays) {
        const int c = std::max(d.components, 1);
        const std::vector<double>& a = piece.values.at(d.name);
        const std::vector<double>& b = one.values.at(d.name);
        double scale = 0;
        for (double x : b) scale = std::max(scale, std::abs(x));
        for (int m = 0; m < c; ++m) {
          const double dev = std::abs(a.at(i * c + m) - b.at(j * c + m));
          if (d.type != "Float64") EXPECT_EQ(dev, 0.0) << source << " " << d.name;
          else if (scale > 0) worst = std::max(worst, dev / scale);
          EXPECT_LE(dev, 1e-10 * scale) << source << " id " << ids[i] << " " << d.name;
        }
      }
    }
  }
  EXPECT_EQ(seen.size(), one.points) << pvtu;
  for (const auto& [id, n] : seen) EXPECT_EQ(n, 1) << pvtu << " id " << id;
  return worst;
}

// (id, time) of each row of a particle CSV snapshot (its columns time, id, ...).
std::vector<std::pair<long long, std::string>> csv_keys(const fs::path& f) {
  std::istringstream in(slurp(f));
  std::vector<std::pair<long long, std::string>> keys;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    keys.emplace_back(std::stoll(line.substr(comma + 1)), line.substr(0, comma));
  }
  return keys;
}

// Rank 0's fresh temporary folder, on every rank.
fs::path shared_folder(const Communicator& world) {
  std::string name = (fs::temp_directory_path() / ("mpdem_pvtu_" + std::to_string(::getpid()))).string();
  std::vector<std::byte> bytes(name.size());
  std::transform(name.begin(), name.end(), bytes.begin(), [](char c) { return static_cast<std::byte>(c); });
  world.broadcast(bytes, 0);
  name.assign(bytes.size(), ' ');
  std::transform(bytes.begin(), bytes.end(), name.begin(), [](std::byte b) { return static_cast<char>(b); });
  if (world.rank() == 0) {
    fs::remove_all(name);
    fs::create_directories(name);
  }
  world.barrier();
  return name;
}

}  // namespace

TEST(PvtuOutput, PiecesOfEveryRankMakeTheOneRankSnapshot) {
  const Communicator& world = Communicator::world();
  const int ranks = world.size(), rank = world.rank();
  const fs::path root = shared_folder(world), many_dir = root / "ranks", one_dir = root / "one";
  Simulation many(cluster(), RunOptions{many_dir, false, true, &world});
  many.run();
  world.barrier();  // rank 0 has listed the last snapshot
  const auto listed = read_pvd(many_dir / "particles.pvd");
  ASSERT_EQ(listed.size(), 4u);  // t = 0, 200, 400 and 600 steps

  // Each rank's pieces: its particles. Within a skin of its brick in every snapshot (a particle
  // leaves its brick by less than half a skin before a rebuild sends it to its new owner)...
  if (ranks > 1) {
    const BrickGrid& grid = many.interactions().search().halo()->grid();
    const double skin = 0.2e-3;  // m, 0.1 x the smallest diameter (the default)
    double outside = 0;          // m, the farthest a particle of this rank's pieces lies outside its brick
    for (const auto& [t, file] : listed) {
      const fs::path pvtu = many_dir / file;
      EXPECT_EQ(pvtu.extension(), ".pvtu");
      const Vtu piece = read_vtu(pvtu.parent_path() / (pvtu.stem().string() + "_p" + std::to_string(rank) + ".vtu"));
      const std::vector<double>& x = piece.values.at("Points");
      for (std::size_t i = 0; i < piece.points; ++i)
        for (int c = 0; c < 3; ++c)
          outside = std::max({outside, grid.lower(rank, c) - x[3 * i + c], x[3 * i + c] - grid.upper(rank, c)});
    }
    EXPECT_LT(outside, skin) << "rank " << rank;
    // ... and in the last, exactly the particles it owns at the end.
    const fs::path last = many_dir / listed.back().second;
    const Vtu piece = read_vtu(last.parent_path() / (last.stem().string() + "_p" + std::to_string(rank) + ".vtu"));
    std::vector<double> mine;
    for (std::size_t i = 0; i < many.particles().size(); ++i)
      mine.push_back(static_cast<double>(many.particles().id[i]));
    std::sort(mine.begin(), mine.end());
    EXPECT_EQ(piece.values.at("id"), mine) << "rank " << rank;
    EXPECT_GT(piece.points, 0u) << "rank " << rank;
  }
  world.barrier();

  if (rank == 0) {
    Simulation one(cluster(), RunOptions{one_dir, false, true, &Communicator::single()});
    one.run();
    const auto reference = read_pvd(one_dir / "particles.pvd");
    ASSERT_EQ(reference.size(), listed.size());
    double worst = 0;
    for (std::size_t s = 0; s < listed.size(); ++s) {
      EXPECT_EQ(listed[s].first, reference[s].first);
      const Vtu one_vtu = read_vtu(one_dir / reference[s].second);
      EXPECT_EQ(one_vtu.points, one.particles().size());
      if (ranks == 1) {  // one rank: the one-rank files, byte for byte
        EXPECT_EQ(listed[s].second, reference[s].second);
        EXPECT_EQ(slurp(many_dir / listed[s].second), slurp(one_dir / reference[s].second));
      } else {
        EXPECT_EQ(listed[s].second, "particles/particles_" + std::string(6 - std::to_string(s).size(), '0') +
                                        std::to_string(s) + ".pvtu");
        worst = std::max(worst, compare_with_one_rank(many_dir / listed[s].second, one_vtu, ranks));
      }
    }
    // The CSV snapshots, gathered on rank 0: the same times and ids as one rank's, in the same
    // order, ascending ids (one rank's storage order is spatial, not by id).
    std::size_t csv = 0;
    for (const auto& e : fs::directory_iterator(one_dir / "particles_csv")) {
      const auto a = csv_keys(many_dir / "particles_csv" / e.path().filename()), b = csv_keys(e.path());
      EXPECT_TRUE(std::is_sorted(b.begin(), b.end())) << e.path();
      EXPECT_EQ(a, b) << e.path();
      EXPECT_EQ(b.size(), one.particles().size());
      ++csv;
    }
    EXPECT_EQ(csv, 3u);  // t = 0, 300 and 600 steps
    EXPECT_TRUE(fs::exists(many_dir / "barriers.pvd"));
    std::printf("[%d ranks] %zu snapshots: largest relative deviation from the one-rank .vtu %.2e\n", ranks,
                listed.size(), worst);

    // The same comparison by meshio.
    const std::string cmd = std::string("/usr/bin/python3 '") + MPDEM_SOURCE_DIR + "/tests/parallel/check_pvtu.py' '" +
                            (many_dir / "particles.pvd").string() + "' '" + (one_dir / "particles.pvd").string() +
                            "' 2>&1";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string out;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    const int status = ::pclose(pipe);
    std::printf("%s", out.c_str());
    EXPECT_EQ(status, 0) << out;
  }
  world.barrier();
  if (rank == 0) fs::remove_all(root);
}
