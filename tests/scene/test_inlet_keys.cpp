// Tests of the [[inlet]] and [[sink]] keys (src/scene/inlet_reader.cpp): every key lands in its
// field with the documented defaults, the face regions become the documented volumes, and a bad
// key or value is an InputError naming the file, the line and the key.
#include <gtest/gtest.h>

#include <string>

#include "model/scene.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;
using mpdem::test::TempDir;

namespace {

// Two materials as an array of inline tables (the same as two [[material]] tables; a root key, so
// before the first table): 4 lines.
const char* kHead = R"(material = [{ name = "glass", density = 2500 }, { name = "steel", density = 7800 }]
[time]
duration = 1.0
dt = 1e-5
)";

Scene parse(const TempDir& d, const std::string& body) {
  return parse_scene_file(d.write("scene.toml", std::string(kHead) + body));
}

// The message of the InputError parsing `body` raises.
std::string error(const std::string& body) {
  TempDir d("mpdem_inlet_keys");
  return test::error_of([&] { parse(d, body); });
}

}  // namespace

TEST(InletKeys, BoxInletMapsEveryKey) {
  TempDir d("mpdem_inlet_keys");
  const Scene s = parse(d, R"(
[[inlet]]
name = "feed"
region = "box"
min = [0.0, 0.0, 0.05]
max = [0.05, 0.05, 0.06]
mass_rate = 0.01
start = 0.1
end = 0.9
interval = 0.002
radius = { distribution = "uniform", min = 0.001, max = 0.0015 }
material = "steel"
velocity = [0.0, 0.0, -0.5]
velocity_spread = 0.05
seed = 11
max_attempts = 50
)");
  ASSERT_EQ(s.model.params.inlets.size(), 1u);
  const InletSpec& in = s.model.params.inlets[0];
  EXPECT_EQ(in.name, "feed");
  EXPECT_EQ(in.volume.shape, "box");
  EXPECT_EQ(in.volume.region.shape, RegionShape::Box);
  EXPECT_EQ(in.volume.region.min, (Vec3{0.0, 0.0, 0.05}));
  EXPECT_EQ(in.volume.region.max, (Vec3{0.05, 0.05, 0.06}));
  EXPECT_EQ(in.mass_rate, 0.01);
  EXPECT_EQ(in.count_rate, 0.0);
  EXPECT_EQ(in.start, 0.1);
  ASSERT_TRUE(in.end.has_value());
  EXPECT_EQ(*in.end, 0.9);
  EXPECT_EQ(in.interval, 0.002);
  EXPECT_EQ(in.radius.law, RadiusLaw::Uniform);
  EXPECT_EQ(in.radius.max, 0.0015);
  EXPECT_EQ(in.material, "steel");
  EXPECT_EQ(in.velocity, (Vec3{0.0, 0.0, -0.5}));
  EXPECT_EQ(in.velocity_spread, 0.05);
  EXPECT_EQ(in.seed, 11u);
  EXPECT_EQ(in.max_attempts, 50u);
}

TEST(InletKeys, DefaultsAndSinks) {
  TempDir d("mpdem_inlet_keys");
  const Scene s = parse(d, R"(
[[inlet]]
count_rate = 100
radius = 0.001
region = "cylinder"
axis = [0, 0, 0.02]
base = [0, 0, 0]
cylinder_radius = 0.01

[[sink]]
region = "box"
min = [-1.0, -1.0, -1.0]
max = [1.0, 1.0, -0.5]

[[sink]]
name = "drain"
region = "cylinder"
base = [0, 0, -2]
axis = [0, 0, 0.5]
cylinder_radius = 0.2
)");
  const InletSpec& in = s.model.params.inlets.at(0);
  EXPECT_EQ(in.name, "inlet1");
  EXPECT_EQ(in.volume.region.shape, RegionShape::Cylinder);
  EXPECT_EQ(in.volume.region.radius, 0.01);
  EXPECT_EQ(in.count_rate, 100.0);
  EXPECT_EQ(in.start, 0.0);
  EXPECT_FALSE(in.end.has_value());  // the run's duration
  EXPECT_EQ(in.interval, 0.0);       // 100 x time.dt
  EXPECT_EQ(in.radius.value, 0.001);
  EXPECT_EQ(in.material, "");
  EXPECT_EQ(in.velocity, Vec3{});
  EXPECT_EQ(in.velocity_spread, 0.0);
  EXPECT_EQ(in.seed, 1u);
  EXPECT_EQ(in.max_attempts, 1000u);
  ASSERT_EQ(s.model.params.sinks.size(), 2u);
  EXPECT_EQ(s.model.params.sinks[0].name, "sink1");
  EXPECT_EQ(s.model.params.sinks[0].region.max, (Vec3{1.0, 1.0, -0.5}));
  EXPECT_EQ(s.model.params.sinks[1].name, "drain");
  EXPECT_EQ(s.model.params.sinks[1].region.shape, RegionShape::Cylinder);
}

TEST(InletKeys, FacesBecomeVolumesBeyondThem) {
  TempDir d("mpdem_inlet_keys");
  const Scene s = parse(d, R"(
[[inlet]]
region = "disc"
centre = [0, 0, 1]
direction = [0, 0, -2]
disc_radius = 0.1
count_rate = 10
radius = 0.002

[[inlet]]
region = "rect"
corner = [0, 0, 1]
edge1 = [0.2, 0, 0]
edge2 = [0, 0.1, 0]
direction = [0, 0, -1]
depth = 0.01
count_rate = 10
radius = 0.002
)");
  const InletSpec& disc = s.model.params.inlets.at(0);
  EXPECT_EQ(disc.volume.region.shape, RegionShape::Cylinder);
  EXPECT_EQ(disc.volume.region.base, (Vec3{0, 0, 1}));
  EXPECT_EQ(disc.volume.region.axis, (Vec3{0, 0, -0.008}));  // two diameters deep, along the unit direction
  const InletSpec& rect = s.model.params.inlets.at(1);
  EXPECT_EQ(rect.volume.region.shape, RegionShape::Box);
  EXPECT_EQ(rect.volume.region.max, (Vec3{0.2, 0.1, 0.01}));
  EXPECT_EQ(rect.volume.w, (Vec3{0, 0, -1}));  // the normal on the side of `direction`
  // The frame box spans the rectangle (x in [0, 0.2], y in [0, 0.1]) below z = 1.
  const InsertionVolume& v = rect.volume;
  const auto world = [&](const Vec3& a) { return v.origin + v.u * a.x + v.v * a.y + v.w * a.z; };
  const Vec3 far = world(rect.volume.region.max);
  EXPECT_NEAR(far.x, 0.2, 1e-15);
  EXPECT_NEAR(far.y, 0.0, 1e-15);  // the frame's v runs along -edge2 (right-handed with the normal -z)
  EXPECT_NEAR(far.z, 0.99, 1e-15);
  EXPECT_NEAR(world({}).y, 0.1, 1e-15);
}

TEST(InletKeys, BadKeysNameFileLineAndKey) {
  const std::string box = "\n[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.01, 0.01, 0.01]\nradius = 0.001\n";
  // kHead has 4 lines; the [[inlet]] header is line 6, the key added after `box` line 11.
  test::expect_contains(error(box + "mass_rat = 1\n"),
                        {"scene.toml:11: 'inlet.mass_rat'", "unknown key", "inlet.mass_rate"});
  test::expect_contains(error(box), {"scene.toml:6: 'inlet.mass_rate'", "exactly one of mass_rate"});
  test::expect_contains(error(box + "mass_rate = 1\ncount_rate = 2\n"), {"'inlet.count_rate'", "exactly one"});
  test::expect_contains(error(box + "mass_rate = -1\n"), {"scene.toml:11: 'inlet.mass_rate'", "> 0"});
  test::expect_contains(error(box + "mass_rate = 1\nstart = 0.5\nend = 0.5\n"), {"'inlet.end'", "end > start"});
  test::expect_contains(error(box + "mass_rate = 1\nmaterial = \"sand\"\n"), {"'inlet.material'", "sand"});
  test::expect_contains(error(box + "mass_rate = 1\ncylinder_radius = 0.1\n"),
                        {"'inlet.cylinder_radius'", "does not apply to region \"box\""});
  test::expect_contains(error(box + "mass_rate = 1\nvelocity_spread = -0.1\n"), {"'inlet.velocity_spread'", ">= 0"});
  test::expect_contains(error(box + "mass_rate = 1\ninterval = 0\n"), {"'inlet.interval'", "> 0"});
  test::expect_contains(error(box + "mass_rate = 1\nmax_attempts = 0\n"), {"'inlet.max_attempts'"});
  test::expect_contains(error("\n[[inlet]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [0.001, 0.01, 0.01]\n"
                              "radius = 0.001\nmass_rate = 1\n"),
                        {"'inlet.radius'", "does not fit"});
  test::expect_contains(error("\n[[inlet]]\nregion = \"sphere\"\nradius = 0.001\nmass_rate = 1\n"),
                        {"'inlet.region'", "\"disc\" or \"rect\""});
  test::expect_contains(error("\n[[inlet]]\nregion = \"rect\"\ncorner = [0, 0, 0]\nedge1 = [1, 0, 0]\n"
                              "edge2 = [1, 1, 0]\ndirection = [0, 0, 1]\nradius = 0.001\nmass_rate = 1\n"),
                        {"'inlet.edge2'", "perpendicular"});
  test::expect_contains(error("\n[[inlet]]\nregion = \"rect\"\ncorner = [0, 0, 0]\nedge1 = [1, 0, 0]\n"
                              "edge2 = [0, 1, 0]\ndirection = [1, 0, 0]\nradius = 0.001\nmass_rate = 1\n"),
                        {"'inlet.direction'", "out of the rectangle's plane"});
  test::expect_contains(
      error("\n[[inlet]]\nregion = \"disc\"\ncentre = [0, 0, 0]\ndirection = [0, 0, 1]\ndisc_radius = 0.1\n"
            "radius = { distribution = \"lognormal\", mean = 0.001, std = 0.0002 }\nmass_rate = 1\n"),
      {"'inlet.depth'", "unbounded"});
  test::expect_contains(error("\n[[sink]]\nregion = \"disc\"\n"), {"'sink.region'", "\"box\" or \"cylinder\""});
  test::expect_contains(error("\n[[sink]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\nspeed = 1\n"),
                        {"'sink.speed'", "unknown key"});
  test::expect_contains(error("\n[[sink]]\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 0]\n"),
                        {"'sink.max'", "max > min"});
  test::expect_contains(error("\n[[sink]]\nname = \"out\"\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n"
                              "[[sink]]\nname = \"out\"\nregion = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\n"),
                        {"'sink.name'", "another inlet or sink"});
}
