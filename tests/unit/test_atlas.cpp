// campaign/atlas + report/results/atlas.hpp: the atlas merges a campaign's database with the
// builders, and the committed data/atlas.csv is never below a builder.
// (tests/unit/atlas_data_test.cpp checks the committed files themselves without tripack's code.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "constructors/registry.hpp"
#include "jobs/atlas.hpp"
#include "jobs/atlas_files.hpp"
#include "jobs/campaign.hpp"
#include "jobs/explore.hpp"
#include "member_checks.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/catalogue_checks.hpp"

namespace tripack {
namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tripack_atlas_" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// For every catalogue member with n <= 200, the committed atlas's best d is at least the
// builder's (the atlas takes every builder as a candidate; 1e-14: the builders' long double d).
// The discovered classes' members, built only here, are also checked as Classes.* checks the
// others (tests/unit/member_checks.hpp).
TEST(Atlas, NoBuilderBeatsTheCommittedAtlas) {
  const Catalogue catalogue = Catalogue::load(Catalogue::default_path());
  const auto entries =
      jobs::read_atlas(std::filesystem::path(TRIPACK_SOURCE_DIR) / "data" / "atlas.csv");
  std::map<long long, long double> best;
  for (const auto& e : entries)
    if (e.rank == 1) best[e.n()] = e.d.value();
  int members = 0;
  for (const auto& member : pipeline::class_members_up_to(catalogue, 200)) {
    // jogged-line members up to 60 disks only: all of them up to 200 cost 650 s more (2
    // threads); every member up to 300 is checked against the atlas by the atlas step and
    // scripts/data/atlas-check.py (docs/atlas.md), and tests/unit/test_vacancy_segment.cpp builds
    // 81 and 110.
    if (member.class_id == "jogged-line" &&
        catalogue.n_of(catalogue.find(member.class_id), member.k, member.p) > 60)
      continue;
    BuildControl control;
    control.threads = 2;
    const Pattern built = build_pattern(catalogue, member, control);
    const long long n = static_cast<long long>(built.packing.size());
    const ClassInfo& cls = catalogue.find(member.class_id);
    if (cls.claim_status == "discovered")
      expect_member_matches_catalogue(catalogue, cls, member, built);
    if (n < 2) continue;
    ASSERT_TRUE(best.count(n)) << "n = " << n << " is not in the atlas";
    // A builder above the atlas must be one the atlas could not take: not certified (197 is
    // 4e-14 above it, uncertified: a degenerate maximum, docs/certified.md). The atlas is built
    // with every builder (`tripack atlas`), so a certified one above it means it is stale.
    if (built.packing.d * (1 - 1e-14L) > best[n]) {
      EXPECT_FALSE(pipeline::analyze_packing(built.packing, {}).certified())
          << member.class_id << " k=" << member.k << " p=" << member.p << " (n = " << n
          << "): a certified builder above the atlas";
    }
    ++members;
  }
  EXPECT_GT(members, 60);
}

// A small campaign and the builders merged: every n gets a certified best row at least as good
// as its builders, polished to 30 digits; a packing both found is one row naming both sources.
TEST(Atlas, MergesTheDatabaseAndTheBuildersAndRoundTrips) {
  const auto dir = fresh_dir("merge");
  jobs::CampaignRequest request;
  request.n_first = 10;
  request.n_last = 13;
  request.runs = 6;
  request.threads = 2;
  request.db = (dir / "runs.db").string();
  jobs::run_campaign(request, ThreadExecutor(request.threads), {});
  const Catalogue catalogue = Catalogue::load(Catalogue::default_path());
  jobs::AtlasSettings settings;
  settings.n_first = 9;  // n = 9 has no run: its builder (Delta(4)-1) alone
  settings.n_last = 13;
  settings.ranked_first = 12;
  settings.ranked_last = 12;
  settings.ranked_count = 3;
  const auto atlas = jobs::build_atlas(catalogue, request.db, settings);
  EXPECT_TRUE(atlas.errors.empty());
  EXPECT_TRUE(atlas.missing.empty());
  std::map<long long, int> rows_of_n;
  for (const auto& row : atlas.rows) {
    ++rows_of_n[row.n()];
    EXPECT_TRUE(row.certified) << row.label;
    EXPECT_EQ(row.precise_points.size(), static_cast<std::size_t>(row.n()));
    EXPECT_EQ(row.d.str().size(), 32u) << row.d.str();  // "0." and 30 digits: d is in (0.1, 1)
    EXPECT_NEAR(static_cast<double>(std::stold(row.d.str()) - row.pattern.packing.d), 0, 1e-17);
  }
  for (long long n = 9; n <= 13; ++n) EXPECT_GE(rows_of_n[n], 1) << "n = " << n;
  EXPECT_LE(rows_of_n[12], 3);
  EXPECT_EQ(rows_of_n[11], 1);
  for (const auto& b : atlas.builders) {
    const auto& best = *std::find_if(atlas.rows.begin(), atlas.rows.end(),
                                     [&](const auto& r) { return r.n() == b.n; });
    EXPECT_GE(std::stold(best.d.str()), std::stold(b.d) * (1 - 1e-20L)) << b.member;
  }
  // t12a = 4Delta(2): the builders of four classes and the campaign, one row.
  const auto& t12a =
      atlas.rows[static_cast<std::size_t>(std::find_if(atlas.rows.begin(), atlas.rows.end(),
                                                       [](const auto& r) { return r.n() == 12; }) -
                                          atlas.rows.begin())];
  EXPECT_EQ(t12a.label.substr(0, 4), "t12a");
  EXPECT_NE(t12a.source_text().find("builder four-delta k=2"), std::string::npos)
      << t12a.source_text();
  EXPECT_NE(t12a.source_text().find("billiards seed"), std::string::npos) << t12a.source_text();
  // Its provenance: the builders and the independent runs of its value, by method, as many runs
  // as the confirmations count besides the builders' one (the four builders give one packing).
  const std::string& provenance = atlas.provenance.at(t12a.label);
  EXPECT_NE(provenance.find("builder four-delta k=2"), std::string::npos) << provenance;
  const auto runs_at = provenance.find("billiards: ");
  ASSERT_NE(runs_at, std::string::npos) << provenance;
  EXPECT_EQ(std::stoll(provenance.substr(runs_at + 11)) + 1, t12a.confirmations()) << provenance;
  // n = 9 has no run: its builder alone.
  for (const auto& row : atlas.rows)
    if (row.n() == 9) {
      EXPECT_EQ(atlas.provenance.at(row.label).rfind("builder ", 0), 0u);
    }
  // Written and read back: the same rows; every file named exists.
  jobs::write_atlas(atlas, dir / "data");
  const auto entries = jobs::read_atlas(dir / "data" / "atlas.csv");
  ASSERT_EQ(entries.size(), atlas.rows.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    EXPECT_EQ(entries[i].label, atlas.rows[i].label);
    EXPECT_EQ(entries[i].d.str(), atlas.rows[i].d.str());
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "data" / entries[i].file));
  }
}

TEST(Atlas, AMalformedTableIsOneLineNamingTheFile) {
  const auto dir = fresh_dir("bad");
  std::ofstream(dir / "atlas.csv") << "n,d\n2,1\n";
  try {
    jobs::read_atlas(dir / "atlas.csv");
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("atlas.csv:1: not a tripack atlas table"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tripack
