// The history of fused views: each map version finds its own views until `versions` newer maps
// have been recorded, and a version never recorded is not found.

#include <gtest/gtest.h>

#include "model_fixture.hpp"
#include "safecell/explain/fused_views.hpp"

namespace safecell {
namespace {

TEST(FusedViewsHistory, KeepsTheLastVersions) {
  const test::CoarseTables tables;
  const LutSet& luts = tables.luts;
  ForbiddenMapFusion fusion(luts, tables.silhouettes, FusionSettings{});
  FusedViewsHistory history(3);
  for (std::uint64_t version = 1; version <= 5; ++version) {
    std::vector<CameraObservation> views(
        luts.cameras.size(), CameraObservation{true, FeatureMask(luts.columns, luts.rows)});
    views[0].blocked.set(static_cast<int>(version), 0);  // tells the versions apart
    views[1].known = version % 2 == 0;
    fusion.fuse(views, 0);
    history.record(version, fusion, views);
  }
  EXPECT_EQ(history.find(1), nullptr);
  EXPECT_EQ(history.find(2), nullptr);
  EXPECT_EQ(history.find(0), nullptr);
  EXPECT_EQ(history.find(6), nullptr);
  for (std::uint64_t version = 3; version <= 5; ++version) {
    const FusedViews* views = history.find(version);
    ASSERT_NE(views, nullptr) << version;
    EXPECT_EQ(views->map_version, version);
    EXPECT_TRUE(views->obstacles[0].test(static_cast<int>(version), 0)) << version;
    EXPECT_EQ(views->obstacles[0].count(), 1U);
    EXPECT_EQ(views->known[1], version % 2 == 0);
    EXPECT_TRUE(views->all_forbidden.empty());
  }
  history.record_all_forbidden(6, "");
  EXPECT_EQ(history.find(3), nullptr);
  ASSERT_NE(history.find(6), nullptr);
  EXPECT_FALSE(history.find(6)->all_forbidden.empty());
}

}  // namespace
}  // namespace safecell
