#include "safecell/pipeline/cell_fusion_settings.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "safecell/cell/default_cell.hpp"

namespace safecell {
namespace {

CellModel cell_voting(std::optional<int> threshold, std::optional<int> reach) {
  CellConfig config = default_cell();
  config.source = "cell.yaml";
  config.camera_threshold = threshold;
  config.occlusion_reach_cells = reach;
  return load_cell_model(config);
}

TEST(CellFusionSettings, TheFusionVotesAsTheCellSays) {
  const FusionSettings fusion = cell_fusion_settings(cell_voting(3, 5));
  EXPECT_EQ(fusion.camera_threshold, 3);
  EXPECT_EQ(fusion.occlusion_reach, 5);
  EXPECT_EQ(cell_fusion_settings(cell_voting(2, std::nullopt)).occlusion_reach,
            kDefaultOcclusionReach);
}

// The default cell votes as the validation found safe: no warning. Three cameras with a shorter
// reach (set, or left to the default of 3) is warned about, naming the file, the fields and the
// reach to set; two cameras need no reach.
TEST(CellFusionSettings, AThresholdOfThreeWithoutTheValidatedReachIsWarnedAbout) {
  EXPECT_EQ(vote_warning(load_cell_model(default_cell())), "");
  EXPECT_EQ(vote_warning(cell_voting(3, kReachValidatedAtThresholdThree)), "");
  EXPECT_EQ(vote_warning(cell_voting(4, 6)), "");
  EXPECT_EQ(vote_warning(cell_voting(2, 0)), "");
  EXPECT_EQ(vote_warning(cell_voting(1, std::nullopt)), "");

  const std::string set_short = vote_warning(cell_voting(3, 3));
  EXPECT_NE(set_short.find("cell.yaml: camera_threshold 3 with occlusion_reach_cells 3 -"),
            std::string::npos)
      << set_short;
  EXPECT_NE(set_short.find("set occlusion_reach_cells: 4"), std::string::npos) << set_short;
  const std::string unset = vote_warning(cell_voting(4, std::nullopt));
  EXPECT_NE(unset.find("camera_threshold 4 with occlusion_reach_cells 3 (unset: the default)"),
            std::string::npos)
      << unset;
}

}  // namespace
}  // namespace safecell
