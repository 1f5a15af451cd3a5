// The CSV log and the particle CSV snapshots (io/csv_log.hpp, io/particle_csv_writer.hpp), read back through std::stod:
// with 17 significant digits every double must come back bit for bit (tolerance: exact).
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "io/csv_log.hpp"
#include "io/particle_csv_writer.hpp"
#include "state/particles.hpp"
#include "support/output_folder.hpp"
#include "support/sample_particles.hpp"

namespace fs = std::filesystem;
using namespace mpdem;
using namespace mpdem::test::output;  // OutputTest, slurp, split, lines_of, files_in
using mpdem::test::make_particles;

TEST_F(OutputTest, CsvLogHeaderAndRowsRoundTrip) {
  const fs::path file = dir / "log.csv";
  const std::vector<std::vector<double>> rows = {{0.1, 3.0, 1.0 / 3.0},
                                                 {1e-300, 9007199254740991.0, 9007199254740992.0},  // 2^53 - 1 and 2^53
                                                 {-2.5, 1e20, -0.0}};
  {
    CsvLog log(file, {"time", "step", "energy"});
    EXPECT_EQ(slurp(file), "time,step,energy\n");  // header at once
    log.row(rows[0]);
    EXPECT_EQ(slurp(file), "time,step,energy\n");  // rows are buffered
    log.flush();
    EXPECT_EQ(lines_of(slurp(file)).size(), 2u);
    log.row(rows[1]);
    EXPECT_THROW(log.row(std::vector<double>{1.0, 2.0}), std::logic_error);
    EXPECT_THROW(log.row(std::vector<double>{1.0, 2.0, 3.0, 4.0}), std::logic_error);
    log.row(rows[2]);
  }  // destructor flushes
  const auto lines = lines_of(slurp(file));
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "time,step,energy");
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto f = split(lines[r + 1], ',');
    ASSERT_EQ(f.size(), 3u) << lines[r + 1];
    for (std::size_t c = 0; c < 3; ++c) EXPECT_EQ(std::stod(f[c]), rows[r][c]) << lines[r + 1];
  }
  // Integral values below 2^53 are plain integers; others keep the 17-digit form.
  EXPECT_EQ(split(lines[1], ',')[1], "3");
  EXPECT_EQ(split(lines[2], ',')[1], "9007199254740991");
  EXPECT_EQ(split(lines[3], ',')[1].find_first_of("eE") != std::string::npos, true);  // 1e20
}

TEST_F(OutputTest, CsvLogAppendContinuesAndDropsCutLine) {
  const fs::path file = dir / "log.csv";
  {
    CsvLog log(file, {"t", "x"});
    log.row(std::vector<double>{1.0, 0.5});
  }
  append_complete_lines(file, "2,0.7");  // a line cut by a kill: no newline
  {
    CsvLog log(file, {"t", "x"}, CsvLog::Open::append);
    log.row(std::vector<double>{2.0, 0.75});
  }
  EXPECT_EQ(slurp(file), "t,x\n1,0.5\n2,0.75\n");
  EXPECT_THROW(CsvLog(file, {"t", "y"}, CsvLog::Open::append), std::runtime_error);
  EXPECT_EQ(slurp(file), "t,x\n1,0.5\n2,0.75\n");
  EXPECT_THROW(CsvLog(dir / "bad.csv", {"a,b"}), std::invalid_argument);
}

TEST_F(OutputTest, ParticleCsvSnapshotRoundTrips) {
  const Particles p = make_particles(4);
  const double time = 1.0 / 7.0;
  const fs::path file = dir / "particles_000001.csv";
  write_particles_csv(file, p, time);
  EXPECT_EQ(files_in(dir), std::vector<fs::path>{"particles_000001.csv"});
  const auto lines = lines_of(slurp(file));
  ASSERT_EQ(lines.size(), p.size() + 1);
  EXPECT_EQ(lines[0],
            "time,id,x,y,z,vx,vy,vz,wx,wy,wz,radius,material,temperature,charge,fx,fy,fz,fixed,tx,ty,tz,body");
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto f = split(lines[i + 1], ',');
    ASSERT_EQ(f.size(), 23u) << lines[i + 1];
    EXPECT_EQ(f[18], "0");  // free (tests/io/test_fixed_particle_input.cpp writes fixed ones)
    const double expected[18] = {time,     0.0,      p.x[i].x,    p.x[i].y,     p.x[i].z,     p.v[i].x,
                                 p.v[i].y, p.v[i].z, p.w[i].x,    p.w[i].y,     p.w[i].z,     p.radius[i],
                                 0.0,      p.T[i],   p.charge[i], p.force[i].x, p.force[i].y, p.force[i].z};
    for (std::size_t c = 0; c < 18; ++c) {
      if (c == 1) EXPECT_EQ(std::stoll(f[c]), p.id[i]);
      else if (c == 12) EXPECT_EQ(std::stoll(f[c]), p.material[i]);
      else EXPECT_EQ(std::stod(f[c]), expected[c]) << "column " << c << " of " << lines[i + 1];
    }
  }
}
