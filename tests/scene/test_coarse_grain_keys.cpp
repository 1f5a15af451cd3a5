// Tests of the [[coarse_grain]] keys and the new [output] keys (src/scene/coarse_grain_reader.cpp,
// scene_reader.cpp): every key lands in its field with the documented defaults, and a bad key or
// value is an InputError naming the file, the line and the key.
#include <gtest/gtest.h>

#include <string>

#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::TempDir;

namespace {

const char* kHead = R"([time]
duration = 1.0
dt = 1e-5
[domain]
min = [0.0, 0.0, 0.0]
max = [0.04, 0.03, 0.1]
)";

Scene parse(const TempDir& d, const std::string& body) {
  return parse_scene_file(d.write("scene.toml", std::string(kHead) + body));
}

std::string error(const std::string& body) {
  TempDir d("mpdem_cg_keys");
  return test::error_of([&] { parse(d, body); });
}

}  // namespace

TEST(CoarseGrainKeys, GridAndProfileMapEveryKey) {
  TempDir d("mpdem_cg_keys");
  const Scene s = parse(d, R"(
[output]
format = "compressed"
contacts_every = 0.01
[[coarse_grain]]
grid = { min = [0.0, 0.0, 0.0], max = [0.04, 0.04, 0.02], cells = [8, 8, 4] }
kernel = "lucy"
width = 0.002
every = 0.04
average = 0.01
samples = 5
[[coarse_grain]]
name = "height"
profile = { axis = "z", min = 0.0, max = 0.02, bins = 40 }
width = 0.001
every = 0.02
[[coarse_grain]]
name = "slab"
grid = { min = [0.0, 0.0, 0.0], max = [0.04, 0.03, 0.02], cells = [8, 5, 4], average_over = ["y"] }
width = 0.001
every = 0.02
)");
  const Params& p = s.model.params;
  EXPECT_EQ(p.output.format, VtkFormat::Compressed);
  EXPECT_EQ(p.output.contacts_every, 0.01);
  ASSERT_EQ(p.coarse_grain.size(), 3u);
  const CoarseGrainSpec& g = p.coarse_grain[0];
  EXPECT_EQ(g.name, "1");
  EXPECT_FALSE(g.profile);
  EXPECT_EQ(g.grid.cells, (std::array<int, 3>{8, 8, 4}));
  EXPECT_EQ(g.grid.max, (Vec3{0.04, 0.04, 0.02}));
  EXPECT_EQ(g.kernel, CgKernel::lucy);
  EXPECT_EQ(g.width, 0.002);
  EXPECT_EQ(g.every, 0.04);
  EXPECT_EQ(g.average, 0.01);
  EXPECT_EQ(g.samples, 5);
  const CoarseGrainSpec& z = p.coarse_grain[1];
  EXPECT_EQ(z.name, "height");
  EXPECT_TRUE(z.profile);
  EXPECT_EQ(z.axis, 2);
  EXPECT_EQ(z.kernel, CgKernel::gaussian);  // default
  EXPECT_EQ(z.average, 0.0);                // default
  EXPECT_EQ(z.samples, 20);                 // default
  EXPECT_EQ(z.grid.resolved, (std::array<bool, 3>{false, false, true}));
  EXPECT_EQ(z.grid.cells[2], 40);
  // The other axes are averaged over the domain.
  EXPECT_EQ(z.grid.min, (Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(z.grid.max, (Vec3{0.04, 0.03, 0.02}));
  const CoarseGrainSpec& slab = p.coarse_grain[2];
  EXPECT_EQ(slab.grid.resolved, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(slab.grid.cells[1], 1);
}

TEST(CoarseGrainKeys, DefaultFormatIsBinaryAndContactsOff) {
  TempDir d("mpdem_cg_keys");
  const Scene s = parse(d, "");
  EXPECT_EQ(s.model.params.output.format, VtkFormat::Binary);
  EXPECT_EQ(s.model.params.output.contacts_every, 0.0);
  EXPECT_TRUE(s.model.params.coarse_grain.empty());
  EXPECT_TRUE(s.model.params.output.mean_barrier_loads);
  const Scene sample = parse(d, "[output]\nbarrier_loads = \"sample\"\n");
  EXPECT_FALSE(sample.model.params.output.mean_barrier_loads);
}

TEST(CoarseGrainKeys, BadValuesNameTheKey) {
  EXPECT_NE(error("[output]\nformat = \"hdf5\"\n").find("output.format"), std::string::npos);
  EXPECT_NE(error("[output]\ncontacts_every = -1.0\n").find("output.contacts_every"), std::string::npos);
  EXPECT_NE(error("[output]\nbarrier_loads = \"peak\"\n").find("output.barrier_loads"), std::string::npos);
  const std::string grid =
      "[[coarse_grain]]\ngrid = { min = [0.0, 0.0, 0.0], max = [0.04, 0.04, 0.02], cells = [2, 2, 2] }\n";
  EXPECT_NE(error(grid + "every = 0.1\n").find("coarse_grain.width"), std::string::npos);
  EXPECT_NE(error(grid + "width = 0.001\n").find("coarse_grain.every"), std::string::npos);
  EXPECT_NE(error(grid + "width = 0.0\nevery = 0.1\n").find("coarse_grain.width"), std::string::npos);
  EXPECT_NE(error(grid + "width = 0.001\nevery = 0.1\nkernel = \"box\"\n").find("coarse_grain.kernel"),
            std::string::npos);
  EXPECT_NE(error(grid + "width = 0.001\nevery = 0.1\naverage = 0.2\n").find("coarse_grain.average"),
            std::string::npos);
  EXPECT_NE(error(grid + "width = 0.001\nevery = 0.1\nwidht = 1\n").find("coarse_grain.widht"), std::string::npos);
  EXPECT_NE(error("[[coarse_grain]]\ngrid = { min = [0.0, 0.0, 0.0], max = [0.04, 0.0, 0.02], cells = [2, 2, 2] }\n"
                  "width = 0.001\nevery = 0.1\n")
                .find("coarse_grain.grid.max"),
            std::string::npos);
  EXPECT_NE(error("[[coarse_grain]]\ngrid = { min = [0.0, 0.0, 0.0], max = [0.04, 0.04, 0.02], cells = [2, 0, 2] }\n"
                  "width = 0.001\nevery = 0.1\n")
                .find("coarse_grain.grid.cells"),
            std::string::npos);
  EXPECT_NE(error("[[coarse_grain]]\nprofile = { axis = \"w\", min = 0.0, max = 0.1, bins = 4 }\nwidth = 0.001\n"
                  "every = 0.1\n")
                .find("coarse_grain.profile.axis"),
            std::string::npos);
  EXPECT_NE(error("[[coarse_grain]]\nwidth = 0.001\nevery = 0.1\n").find("coarse_grain.grid"), std::string::npos);
  EXPECT_NE(error(grid + "profile = { axis = \"z\", min = 0.0, max = 0.1, bins = 4 }\nwidth = 0.001\nevery = 0.1\n")
                .find("coarse_grain.profile"),
            std::string::npos);
  EXPECT_NE(error(grid + "width = 0.001\nevery = 0.1\n" + grid + "width = 0.001\nevery = 0.1\nname = \"1\"\n")
                .find("coarse_grain.name"),
            std::string::npos);
}

TEST(CoarseGrainKeys, ProfileWithoutDomainNeedsAnExtent) {
  TempDir d("mpdem_cg_keys");
  const std::string body = R"([time]
duration = 1.0
dt = 1e-5
[[coarse_grain]]
profile = { axis = "x", min = 0.0, max = 0.1, bins = 4 }
width = 0.001
every = 0.1
)";
  const std::string msg = test::error_of([&] { parse_scene_file(d.write("s.toml", body)); });
  EXPECT_NE(msg.find("coarse_grain.profile.extent_min"), std::string::npos) << msg;
  EXPECT_NE(msg.find("s.toml:5"), std::string::npos) << msg;
  std::string with_extent = body;
  with_extent.replace(with_extent.find("bins = 4 }"), 10,
                      "bins = 4, extent_min = [0.0, -1.0, -2.0], extent_max = [1.0, 1.0, 2.0] }");
  const Scene s = parse_scene_file(d.write("t.toml", with_extent));
  const CgGrid& g = s.model.params.coarse_grain.at(0).grid;
  EXPECT_EQ(g.min, (Vec3{0.0, -1.0, -2.0}));
  EXPECT_EQ(g.max, (Vec3{0.1, 1.0, 2.0}));
  EXPECT_EQ(g.cells, (std::array<int, 3>{4, 1, 1}));
}

// Along a periodic axis the kernel reaches one image either side: a cutoff longer than the period
// is refused when the axis is resolved, and allowed when it is averaged.
TEST(CoarseGrainKeys, PeriodicAxisNeedsACutoffWithinThePeriod) {
  TempDir d("mpdem_cg_keys");
  const std::string head = R"([time]
duration = 1.0
dt = 1e-5
[domain]
min = [0.0, 0.0, 0.0]
max = [0.004, 0.03, 0.1]
periodic = ["x"]
[[coarse_grain]]
)";
  const std::string grid = "grid = { min = [0.0, 0.0, 0.0], max = [0.004, 0.03, 0.1], cells = [4, 3, 10] }\n";
  const std::string msg = test::error_of(
      [&] { parse_scene_file(d.write("s.toml", head + grid + "width = 0.002\nevery = 0.1\n")); });
  EXPECT_NE(msg.find("coarse_grain.width"), std::string::npos) << msg;
  EXPECT_NE(msg.find("exceeds the period 0.004 m along the periodic axis x"), std::string::npos) << msg;
  EXPECT_NE(msg.find("s.toml:10"), std::string::npos) << msg;
  // Cutoff 3 mm < 4 mm: accepted; averaged over x: any width.
  EXPECT_NO_THROW(parse_scene_file(d.write("t.toml", head + grid + "width = 0.001\nevery = 0.1\n")));
  const std::string slabs = "grid = { min = [0.0, 0.0, 0.0], max = [0.004, 0.03, 0.1], cells = [1, 3, 10], "
                            "average_over = [\"x\"] }\n";
  EXPECT_NO_THROW(parse_scene_file(d.write("u.toml", head + slabs + "width = 0.002\nevery = 0.1\n")));
}
