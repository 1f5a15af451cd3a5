// The particle column table (state/particle_columns.hpp) drives the particle CSV header and rows,
// the reader's input columns, the VTU's point arrays and the Python names: each format checked
// against the table, row by row. Values compare exactly (the writers print round-trip digits).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/particle_csv_reader.hpp"
#include "io/particle_csv_writer.hpp"
#include "io/pvtu_writer.hpp"
#include "io/vtu_writer.hpp"
#include "state/particle_columns.hpp"
#include "support/output_folder.hpp"
#include "support/sample_particles.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using namespace mpdem::test::output;  // OutputTest, lines_of, split
using mpdem::test::make_particles;

namespace {

// make_particles uses materials 0, 1 and 2; the reader needs them to exist, nothing more.
Model three_materials() {
  Model m;
  m.materials.resize(3);
  return m;
}

// Sample particles with every table array set to distinct values (make_particles sets the others).
Particles sample() {
  Particles p = make_particles(5);
  for (std::size_t k = 0; k < p.size(); ++k) {
    const double s = static_cast<double>(k) + 1.0;
    p.torque[k] = {1.0 / (7.0 * s), -3.0e-9 * s, s / 13.0};
    p.fixed[k] = k % 2 == 0 ? 1 : 0;
    p.image[k] = {static_cast<std::int32_t>(k), -2, 3 * static_cast<std::int32_t>(k)};
  }
  return p;
}

}  // namespace

// The header: `time`, every CSV column of the table in table order (the periodic one, the image
// counts, only with a periodic axis, followed by the unwrapped centre); the writer writes it.
TEST_F(OutputTest, CsvHeaderIsTheTablesColumns) {
  for (const bool periodic : {false, true}) {
    std::vector<std::string> expected{kCsvTime};
    for_each_particle_column([&](const auto& c) {
      const bool written = c.csv_role == CsvRole::input || c.csv_role == CsvRole::output ||
                           (periodic && c.csv_role == CsvRole::periodic);
      if (written)
        for (std::size_t k = 0; k < c.components; ++k) expected.emplace_back(c.csv[k]);
      if (written && c.csv_role == CsvRole::periodic)
        for (const char* u : kCsvUnwrapped) expected.emplace_back(u);
    });
    EXPECT_EQ(split(particle_csv_header(periodic), ','), expected);

    const fs::path f = dir / "p.csv";
    write_particles_csv(f, sample(), 0.25, periodic ? Vec3{0.5, 0.0, 0.0} : Vec3{});
    const std::vector<std::string> lines = lines_of(slurp(f));
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0], particle_csv_header(periodic));
    for (std::size_t k = 1; k < lines.size(); ++k) EXPECT_EQ(split(lines[k], ',').size(), expected.size()) << k;
  }
}

// Every input column of the table is read back as written (so a row marked input is one the
// reader reads), whatever the output-only columns around it; the particles come back in id order.
TEST_F(OutputTest, EveryInputColumnRoundTripsThroughTheReader) {
  Model m = three_materials();
  const Particles p = sample();  // ids ascending: rows and particles in the same order
  for (const Vec3& period : {Vec3{}, Vec3{0.5, 0.0, 0.25}}) {
    const fs::path f = dir / "seed.csv";
    write_particles_csv(f, p, 0.25, period);
    Particles in;
    read_particle_csv(f, m, 0, in);
    ASSERT_EQ(in.size(), p.size());
    std::size_t inputs = 0;
    for_each_particle_column([&](const auto& c) {
      if (c.csv_role != CsvRole::input) return;
      ++inputs;
      for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t k = 0; k < c.components; ++k)
          EXPECT_EQ(component((in.*c.array)[i], k), component((p.*c.array)[i], k)) << c.name << " particle " << i;
      }
    });
    EXPECT_GE(inputs, 8u);  // id, position, velocity, angular velocity, radius, material, ..., fixed
    for (std::size_t i = 0; i < in.size(); ++i) {
      EXPECT_EQ(in.image[i], (std::array<std::int32_t, 3>{0, 0, 0}));  // output only: not read
      EXPECT_EQ(in.force[i], Vec3{});
    }
  }
}

// The VTU's point arrays: the table's columns with a VTU slot, in slot order, named as in Python,
// scalars without components, vectors with their count.
TEST(ParticleColumns, VtuArraysAreTheTablesColumnsInSlotOrder) {
  const auto arrays = particle_point_arrays();
  std::size_t in_vtu = 0;
  for_each_particle_column([&](const auto& c) {
    if (c.vtu < 0) return;
    ++in_vtu;
    ASSERT_LT(static_cast<std::size_t>(c.vtu), arrays.size()) << c.name;
    const VtuArray& a = arrays[static_cast<std::size_t>(c.vtu)];
    EXPECT_EQ(std::string_view(a.name), c.name);
    EXPECT_EQ(a.components, c.components == 1 ? 0 : static_cast<int>(c.components)) << c.name;
  });
  EXPECT_EQ(in_vtu, arrays.size());
}

// The table names each Particles array once (for_each_array lists them all).
TEST(ParticleColumns, EveryParticlesArrayHasOneColumn) {
  Particles p;
  std::size_t arrays = 0, columns = 0;
  p.for_each_array([&](const char*, auto&) { ++arrays; });
  for_each_particle_column([&](const auto&) { ++columns; });
  EXPECT_EQ(columns, arrays);
}

// The torque row (N m, 3 components, output only) puts the torque sums into the particle CSV
// (tx, ty, tz after the last column), the particle VTU (array "torque") and the PVTU's declarations,
// every value exact; a snapshot with it reads back as input (torque skipped, zero until the
// first evaluation).
TEST_F(OutputTest, TorqueIsInTheCsvTheVtuAndThePvtu) {
  const Particles p = sample();  // ids ascending: rows in storage order

  const fs::path csv = dir / "p.csv";
  write_particles_csv(csv, p, 0.25);
  const std::vector<std::string> lines = lines_of(slurp(csv));
  const std::vector<std::string> header = split(lines.at(0), ',');
  const auto at = [&header](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(at("tz"), header.size());
  EXPECT_EQ(at("tx"), at("fixed") + 1);  // after the last column: the earlier ones keep their place
  EXPECT_EQ(at("ty"), at("tx") + 1);
  EXPECT_EQ(at("tz"), at("ty") + 1);
  ASSERT_EQ(lines.size(), p.size() + 1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::vector<std::string> row = split(lines[i + 1], ',');
    EXPECT_EQ(std::stod(row.at(at("tx"))), p.torque[i].x) << i;
    EXPECT_EQ(std::stod(row.at(at("ty"))), p.torque[i].y) << i;
    EXPECT_EQ(std::stod(row.at(at("tz"))), p.torque[i].z) << i;
  }

  Model m = three_materials();
  Particles in;
  read_particle_csv(csv, m, 0, in);
  ASSERT_EQ(in.size(), p.size());
  for (std::size_t i = 0; i < in.size(); ++i) EXPECT_EQ(in.torque[i], Vec3{}) << i;

  const fs::path vtu = dir / "p.vtu";
  write_particles_vtu(vtu, p, 0.25, {VtkFormat::Ascii, {}});
  const std::string text = slurp(vtu);
  const std::string decl = R"(<DataArray type="Float64" Name="torque" NumberOfComponents="3")";
  const std::size_t open = text.find(decl);
  ASSERT_NE(open, std::string::npos) << text.substr(0, 2000);
  const std::size_t begin = text.find('>', open) + 1;
  std::istringstream values(text.substr(begin, text.find("</DataArray>", begin) - begin));
  std::vector<double> got;
  for (std::string token; values >> token;) got.push_back(std::stod(token));
  ASSERT_EQ(got.size(), 3 * p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(got[3 * i], p.torque[i].x) << i;
    EXPECT_EQ(got[3 * i + 1], p.torque[i].y) << i;
    EXPECT_EQ(got[3 * i + 2], p.torque[i].z) << i;
  }

  fs::create_directories(dir / "particles");
  write_particles_pvtu(dir, 0, 2);
  EXPECT_NE(
      slurp(dir / particle_pvtu_name(0)).find(R"(<PDataArray type="Float64" Name="torque" NumberOfComponents="3"/>)"),
      std::string::npos);
}
