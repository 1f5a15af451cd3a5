// The barrier VTU with activity windows ([[barriers]] active): every element is written, with a
// cell field `active` (UInt8, 1 on, 0 off) at the snapshot's time; a scene without windows keeps
// its fields as they were (no `active`).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "io/vtu_writer.hpp"
#include "state/barriers.hpp"
#include "support/output_folder.hpp"

using namespace mpdem;
using namespace mpdem::test::output;  // OutputTest, slurp

namespace {

const double kNan = std::numeric_limits<double>::quiet_NaN();

// The integers of the DataArray named `name`; empty when there is none.
std::vector<int> int_field(const std::string& vtu, const std::string& name) {
  const std::string tag = "Name=\"" + name + "\"";
  const std::size_t at = vtu.find(tag);
  if (at == std::string::npos) return {};
  const std::size_t begin = vtu.find('>', at) + 1, end = vtu.find("</DataArray>", begin);
  std::istringstream in(vtu.substr(begin, end - begin));
  std::vector<int> out;
  for (int v = 0; in >> v;) out.push_back(v);
  return out;
}

}  // namespace

TEST_F(OutputTest, BarrierVtuMarksSwitchedOffElements) {
  Barriers b;
  MotionLaw lid;
  lid.active_until = 0.5;
  MotionLaw gate;
  gate.active_from = 0.2;
  ASSERT_TRUE(b.add(1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1e9, 0.3, lid, 0.0, kNan));
  ASSERT_TRUE(b.add(2, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, 0, 1e9, 0.3, gate, 0.0, kNan));
  ASSERT_TRUE(b.add(3, {0, 0, 2}, {1, 0, 2}, {0, 1, 2}, 0, 1e9, 0.3, MotionLaw{}, 0.0, kNan));
  const struct {
    double t;
    std::vector<int> active;
  } rows[] = {{0.1, {1, 0, 1}}, {0.3, {1, 1, 1}}, {0.5, {0, 1, 1}}};
  for (const auto& r : rows) {
    b.move_to(r.t);
    const auto file = dir / "barriers.vtu";
    write_barriers_vtu(file, b, r.t, VtkFormat::Ascii);
    const std::string vtu = slurp(file);
    EXPECT_NE(vtu.find("<DataArray type=\"UInt8\" Name=\"active\""), std::string::npos);
    EXPECT_EQ(int_field(vtu, "active"), r.active) << "t = " << r.t;
    EXPECT_EQ(int_field(vtu, "id"), (std::vector<int>{1, 2, 3}));  // all elements written
  }
  Barriers plain;
  ASSERT_TRUE(plain.add(1, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1e9, 0.3, MotionLaw{}, 0.0, kNan));
  write_barriers_vtu(dir / "plain.vtu", plain, 0.0, VtkFormat::Ascii);
  EXPECT_EQ(slurp(dir / "plain.vtu").find("Name=\"active\""), std::string::npos);
}
