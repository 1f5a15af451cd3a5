// The contact snapshot writers' columns (output/contact_writer.hpp): the touching and bridge flags
// only for a scene with cohesion, after every other column, and a scene without it keeps its
// files byte for byte (the same bytes as a writer call that does not name the flag).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "output/contact_writer.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

std::string slurp(const std::filesystem::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines(const std::filesystem::path& f) {
  std::stringstream s(slurp(f));
  std::vector<std::string> out;
  for (std::string l; std::getline(s, l);) out.push_back(l);
  return out;
}

// A bridge alone across a gap, and a touching contact with a bridge.
std::vector<ContactEntry> cohesive_entries() {
  ContactEntry a;
  a.first = 1, a.second = 2, a.overlap = -2.5e-4, a.bridge = true;
  a.normal = {1.0, 0.0, 0.0}, a.normal_force = {-1e-3, 0.0, 0.0}, a.branch = {3e-3, 0.0, 0.0};
  ContactEntry b = a;
  b.second = 3, b.overlap = 1e-5, b.touching = true;
  return {a, b};
}

}  // namespace

TEST(ContactWriter, CsvFlagsOnlyWithCohesion) {
  TempDir dir("contact_writer");
  const std::vector<ContactEntry> e = cohesive_entries();
  write_contacts_csv(dir.path / "plain.csv", e, 0.5);
  write_contacts_csv(dir.path / "plain_named.csv", e, 0.5, false, false);
  write_contacts_csv(dir.path / "cohesive.csv", e, 0.5, false, true);
  write_contacts_csv(dir.path / "clumps.csv", e, 0.5, true, true);
  EXPECT_EQ(slurp(dir.path / "plain.csv"), slurp(dir.path / "plain_named.csv"));
  const std::string base = "time,first,second,element,px,py,pz,nx,ny,nz,overlap,fnx,fny,fnz,ftx,fty,ftz,sliding";
  const auto plain = lines(dir.path / "plain.csv");
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_EQ(plain[0], base);
  const auto coh = lines(dir.path / "cohesive.csv");
  ASSERT_EQ(coh.size(), 3u);
  EXPECT_EQ(coh[0], base + ",touching,bridge");
  // The same rows with the flags appended: bridge alone, then touching with a bridge.
  EXPECT_EQ(coh[1], plain[1] + ",0,1");
  EXPECT_EQ(coh[2], plain[2] + ",1,1");
  const auto cl = lines(dir.path / "clumps.csv");
  EXPECT_EQ(cl[0], base + ",first_body,second_body,touching,bridge");
  EXPECT_EQ(cl[1], plain[1] + ",-1,-1,0,1");
}

TEST(ContactWriter, VtuFlagsOnlyWithCohesion) {
  TempDir dir("contact_writer");
  const std::vector<ContactEntry> e = cohesive_entries();
  for (VtkFormat f : {VtkFormat::Ascii, VtkFormat::Binary, VtkFormat::Compressed}) {
    write_contacts_vtu(dir.path / "plain.vtu", e, 0.5, f);
    write_contacts_vtu(dir.path / "plain_named.vtu", e, 0.5, f, false, false);
    write_contacts_vtu(dir.path / "cohesive.vtu", e, 0.5, f, false, true);
    const std::string plain = slurp(dir.path / "plain.vtu"), coh = slurp(dir.path / "cohesive.vtu");
    EXPECT_EQ(plain, slurp(dir.path / "plain_named.vtu"));
    for (const char* name : {"Name=\"touching\"", "Name=\"bridge\""}) {
      EXPECT_EQ(plain.find(name), std::string::npos) << name;
      EXPECT_NE(coh.find(name), std::string::npos) << name;
    }
    // Cohesion adds the two arrays after the others, changing nothing before them (inline data;
    // the appended formats' offsets move with the data block's layout).
    if (f == VtkFormat::Ascii) {
      const std::size_t line = coh.rfind('\n', coh.find("Name=\"touching\""));
      EXPECT_EQ(coh.substr(0, line), plain.substr(0, line));
    }
  }
}
