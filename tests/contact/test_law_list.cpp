// The one list of contact laws (contact/laws/law_list.hpp): docs/scene.md's "Contact laws" table
// lists every key of every law and nothing else; the mixed-law select gives each pair exactly
// its own law's values (bit for bit); names select the laws they say.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "contact/contact_law.hpp"
#include "contact/contact_table.hpp"

using namespace mpdem;

namespace {

std::string quoted(std::string_view s) { return "`\"" + std::string(s) + "\"`"; }

// The rows of the "Contact laws" table of docs/scene.md, as written.
std::set<std::string> documented_rows() {
  std::ifstream in(std::string(MPDEM_SOURCE_DIR) + "/docs/scene.md");
  std::set<std::string> rows;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.starts_with("#### Contact laws")) inside = true;
    else if (inside && line.starts_with("#")) break;
    else if (inside && line.starts_with("| `\"")) rows.insert(line);
  }
  return rows;
}

TEST(LawList, SceneDocsListEveryLawKeyAndNoOther) {
  const std::set<std::string> rows = documented_rows();
  ASSERT_FALSE(rows.empty()) << "docs/scene.md has no \"#### Contact laws\" table";
  std::size_t expected = 0;
  const auto has_row = [&](const std::string& start) {
    for (const std::string& r : rows)
      if (r.starts_with(start)) return true;
    return false;
  };
  for_each_law([&]<class L>(std::type_identity<L>, LawId) {
    const std::string head = "| " + quoted(L::kLaw) + " | " + quoted(L::kCohesion) + " | ";
    if (L::kKeys.empty()) {
      ++expected;
      EXPECT_TRUE(has_row(head + "- |")) << "docs/scene.md lacks the row " << head << "- |";
    }
    for (const LawKey& k : L::kKeys) {
      ++expected;
      const std::string row = head + "`" + std::string(k.name) + "` | " + std::string(k.unit) + " | " +
                              std::string(k.required ? "required" : k.default_text) + " |";
      EXPECT_TRUE(has_row(row)) << "docs/scene.md lacks the row " << row;
    }
  });
  EXPECT_EQ(rows.size(), expected) << "docs/scene.md lists a law or key the list does not have";
}

TEST(LawList, NamesSelectTheirLaws) {
  EXPECT_EQ(find_law("hertz", "none"), law_id<HertzLaw>());
  EXPECT_EQ(find_law("linear", "none"), law_id<LinearLaw>());
  EXPECT_EQ(find_law("linear", "nonsense"), -1);
  EXPECT_EQ(law_id<HertzLaw>(), 0);  // the default
  ContactLawParams p;
  p.law = "linear";
  p.law_keys["stiffness_normal"] = 700.0;
  const PairLaw l = resolve_pair_law(p, 1e9, 4e8);
  EXPECT_EQ(l.law, law_id<LinearLaw>());
  EXPECT_EQ(l.c[LinearLaw::kNormalStiffness], 700.0);
  EXPECT_EQ(l.c[LinearLaw::kTangentialStiffness], 2.0 / 7.0 * 700.0);
}

// MixedLaw's select equals each law's own stiffness and whole contact, bit for bit.
TEST(LawList, MixedSelectIsEachPairsOwnLaw) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    for_each_law([&]<class L>(std::type_identity<L>, LawId id) {
      ContactLawParams p;
      p.law = std::string(L::kLaw);
      p.cohesion = std::string(L::kCohesion);
      for (const LawKey& k : L::kKeys) p.law_keys[std::string(k.name)] = 1e3 * (1.0 + u(rng));
      p.damping_ratio = 0.3 * u(rng);
      const PairLaw law = resolve_pair_law(p, 1e7 * (1.0 + u(rng)), 4e6 * (1.0 + u(rng)));
      ASSERT_EQ(law.law, id);
      ContactState c;
      c.overlap = 1e-5 * u(rng), c.r_star = 1e-3, c.m_star = 1e-5, c.normal = {0, 0, 1};
      c.normal_rate = 0.1 * (u(rng) - 0.5), c.increment = {1e-7 * u(rng), 0.0, 0.0}, c.vt = {0.0, 0.01, 0.0};
      const Stiffness a = L::stiffness(law, c.r_star, c.overlap), b = MixedLaw::stiffness(law, c.r_star, c.overlap);
      EXPECT_EQ(a.k_n, b.k_n);
      EXPECT_EQ(a.f_el, b.f_el);
      EXPECT_EQ(a.k_t, b.k_t);
      EXPECT_EQ(a.energy, b.energy);
      EXPECT_EQ(a.clamp, b.clamp);
      EXPECT_EQ(a.adhesion, b.adhesion);
      const ContactResult x = evaluate_contact<L>(law, c), y = evaluate_contact<MixedLaw>(law, c);
      EXPECT_EQ(x.fn, y.fn);
      EXPECT_EQ(x.fn_limit, y.fn_limit);
      EXPECT_EQ(x.ft.x, y.ft.x);
      EXPECT_EQ(x.ft.y, y.ft.y);
      EXPECT_EQ(x.energy, y.energy);
      EXPECT_EQ(x.damping, y.damping);
    });
  }
}

}  // namespace
