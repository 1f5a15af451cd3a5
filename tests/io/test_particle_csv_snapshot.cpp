// Particle CSV snapshots (docs/output.md): rows in ascending id order whatever the storage
// order, and a snapshot, periodic or not, read back by the particle CSV reader as the particles
// it was written from (its output-only columns skipped).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/particle_csv_writer.hpp"
#include "io/particle_csv_reader.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using mpdem::test::TempDir;

namespace {

Model two_materials() {
  Model m;
  m.materials.resize(2);
  m.materials[0].name = "glass";
  m.materials[1].name = "steel";
  m.materials[1].density = 7800.0;
  return m;
}

// Five particles stored out of id order (as the engine stores them after a spatial reorder),
// with distinct values in every column a snapshot writes; two of them carry periodic images.
Particles scrambled(const Model& m) {
  Particles p;
  const std::int64_t ids[] = {42, 3, 17, 0, 9};
  for (int k = 0; k < 5; ++k) {
    const int mat = k % 2;
    p.add(ids[k], mat, 1e-3 * (1.0 + 0.1 * k), m.materials[static_cast<std::size_t>(mat)].density,
          {0.01 * k + 1e-17, 0.1 / 3.0 * k, 0.3 - 0.01 * k}, {0.1 * k, -0.2, 1.0 / 7.0});
    const auto i = static_cast<std::size_t>(k);
    p.w[i] = {1.0 * k, 2.0 / 3.0, -k * 0.5};
    p.T[i] = 293.15 + k;
    p.charge[i] = k * 1e-12;
    p.force[i] = {1e-3 * k, -2e-3, 3e-3};
    p.fixed[i] = k == 2 ? 1 : 0;
    p.image[i] = {k == 1 ? -2 : 0, 0, k == 4 ? 1 : 0};
  }
  return p;
}

std::vector<std::string> lines_of(const fs::path& f) {
  std::ifstream in(f);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::int64_t id_of_row(const std::string& line) {  // the second column
  std::istringstream s(line);
  std::string time, id;
  std::getline(s, time, ',');
  std::getline(s, id, ',');
  return std::stoll(id);
}

}  // namespace

TEST(ParticleCsvSnapshot, RowsAreInAscendingIdOrder) {
  TempDir d("mpdem_snap");
  const Model m = two_materials();
  const Particles p = scrambled(m);
  for (const Vec3& period : {Vec3{}, Vec3{0.1, 0.0, 0.2}}) {
    const fs::path f = d.path / "particles_000000.csv";
    write_particles_csv(f, p, 0.5, period);
    const std::vector<std::string> lines = lines_of(f);
    ASSERT_EQ(lines.size(), 6u);
    std::vector<std::int64_t> ids;
    for (std::size_t k = 1; k < lines.size(); ++k) ids.push_back(id_of_row(lines[k]));
    EXPECT_EQ(ids, (std::vector<std::int64_t>{0, 3, 9, 17, 42}));
  }
}

// The snapshot of a periodic run (with time, force, image and unwrapped columns) and of a
// bounded one seed a scene: the particles read back are those written, value for value (the
// snapshot prints round-trip digits), in id order; the image counts start again at 0.
TEST(ParticleCsvSnapshot, SeedsANewSceneAsItIs) {
  TempDir d("mpdem_snap");
  Model m = two_materials();
  const Particles p = scrambled(m);
  for (const Vec3& period : {Vec3{0.1, 0.0, 0.2}, Vec3{}}) {
    const fs::path f = d.path / "seed.csv";
    write_particles_csv(f, p, 0.5, period);
    Particles in;
    read_particle_csv(f, m, 0, in);
    ASSERT_EQ(in.size(), p.size());
    for (std::size_t k = 0; k < in.size(); ++k) {
      std::size_t i = 0;  // the written particle with the k-th smallest id
      while (p.id[i] != in.id[k]) ++i;
      if (k > 0) {
        EXPECT_LT(in.id[k - 1], in.id[k]);
      }
      EXPECT_EQ(in.x[k], p.x[i]);
      EXPECT_EQ(in.v[k], p.v[i]);
      EXPECT_EQ(in.w[k], p.w[i]);
      EXPECT_EQ(in.radius[k], p.radius[i]);
      EXPECT_EQ(in.material[k], p.material[i]);
      EXPECT_EQ(in.mass[k], p.mass[i]);
      EXPECT_EQ(in.T[k], p.T[i]);
      EXPECT_EQ(in.charge[k], p.charge[i]);
      EXPECT_EQ(in.fixed[k], p.fixed[i]);
      EXPECT_EQ(in.image[k], (std::array<std::int32_t, 3>{0, 0, 0}));
    }
  }
}
