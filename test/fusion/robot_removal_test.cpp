#include "safecell/fusion/robot_removal.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace safecell {
namespace {

FeatureMask rect_mask(int columns, int rows, std::initializer_list<FeatureRect> rects) {
  FeatureMask mask(columns, rows);
  for (const auto& rect : rects) mask.set_rect(rect);
  return mask;
}

TEST(RobotRemoval, TheRobotAloneIsRemovedInBothModes) {
  const FeatureMask silhouette = rect_mask(64, 64, {{10, 10, 30, 40}});
  const FeatureMask blocked = rect_mask(64, 64, {{12, 12, 25, 38}});  // the arm, inside
  FeatureMask obstacles;
  for (const auto removal : {RobotRemoval::kPlain, RobotRemoval::kOcclusionAware}) {
    remove_robot(blocked, silhouette, removal, obstacles);
    EXPECT_FALSE(obstacles.any()) << to_string(removal);
  }
}

TEST(RobotRemoval, AHumanBehindTheRobotIsKeptWhole) {
  // The robot's silhouette, the arm blocked inside it, and a person whose blob runs from outside
  // the silhouette into it (partly hidden behind the arm).
  const FeatureMask silhouette = rect_mask(64, 64, {{10, 10, 30, 40}});
  const FeatureMask arm = rect_mask(64, 64, {{12, 12, 25, 38}});
  const FeatureMask person = rect_mask(64, 64, {{20, 30, 40, 50}});
  FeatureMask blocked = arm;
  blocked |= person;

  FeatureMask plain;
  remove_robot(blocked, silhouette, RobotRemoval::kPlain, plain);
  FeatureMask outside = person;
  outside.subtract(silhouette);
  EXPECT_EQ(plain, outside) << "plain removal erases the hidden part";

  // With a reach as wide as the image the whole person is kept, and the arm it touches as well
  // (it may hide the person); silhouette cells that are not blocked stay free.
  FeatureMask unbounded;
  remove_robot(blocked, silhouette, RobotRemoval::kOcclusionAware, unbounded, 64);
  FeatureMask person_part = person;
  person_part &= unbounded;
  EXPECT_EQ(person_part, person) << "the whole person is kept";
  EXPECT_EQ(unbounded, blocked);
  FeatureMask free_in_silhouette = silhouette;
  free_in_silhouette.subtract(blocked);
  EXPECT_FALSE(unbounded.intersects(free_in_silhouette));

  // The default reach keeps the hidden cells within three steps of the visible part only.
  FeatureMask bounded;
  remove_robot(blocked, silhouette, RobotRemoval::kOcclusionAware, bounded);
  EXPECT_TRUE(bounded.test(28, 35));   // 3 columns in from the visible part at column 31
  EXPECT_TRUE(bounded.test(25, 38));   // 3 rows up from the visible part at row 41
  EXPECT_FALSE(bounded.test(27, 35));  // 4 steps in
  EXPECT_FALSE(bounded.test(15, 15));  // the arm far from the person
  FeatureMask visible_part = outside;
  visible_part &= bounded;
  EXPECT_EQ(visible_part, outside);
}

TEST(RobotRemoval, ReachZeroIsPlainRemoval) {
  const FeatureMask silhouette = rect_mask(64, 64, {{10, 10, 30, 40}});
  FeatureMask blocked = rect_mask(64, 64, {{12, 12, 25, 38}, {20, 30, 40, 50}});
  FeatureMask plain;
  FeatureMask zero;
  remove_robot(blocked, silhouette, RobotRemoval::kPlain, plain);
  remove_robot(blocked, silhouette, RobotRemoval::kOcclusionAware, zero, 0);
  EXPECT_EQ(plain, zero);
  EXPECT_THROW(remove_robot(blocked, silhouette, RobotRemoval::kOcclusionAware, zero, -1),
               std::invalid_argument);
}

TEST(RobotRemoval, SeparateBlobsInsideTheSilhouetteAreDropped) {
  const FeatureMask silhouette = rect_mask(100, 20, {{0, 0, 70, 19}});
  // A person outside touching the silhouette at column 70 across the word boundary, and a
  // separate robot blob elsewhere inside; diagonal contact counts as connected.
  FeatureMask blocked = rect_mask(100, 20, {{71, 5, 80, 8}, {10, 2, 20, 6}});
  blocked.set(70, 9);  // diagonal neighbour of (71, 8)
  blocked.set(69, 10);
  FeatureMask aware;
  remove_robot(blocked, silhouette, RobotRemoval::kOcclusionAware, aware, 64);
  EXPECT_TRUE(aware.test(70, 9));
  EXPECT_TRUE(aware.test(69, 10));
  EXPECT_FALSE(aware.test(15, 4));
  EXPECT_EQ(aware.count(), 10U * 4U + 2U);
}

TEST(RobotRemoval, MasksOfDifferentSizesAreRefused) {
  FeatureMask obstacles;
  EXPECT_THROW(
      remove_robot(FeatureMask(64, 64), FeatureMask(32, 64), RobotRemoval::kPlain, obstacles),
      std::invalid_argument);
}

}  // namespace
}  // namespace safecell
