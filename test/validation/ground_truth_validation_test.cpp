#include "safecell/validation/ground_truth_validation.hpp"

#include <gtest/gtest.h>

#include "model_fixture.hpp"
#include "safecell/lut/model_luts.hpp"

namespace safecell {
namespace {

TEST(GroundTruthValidation, NoCollisionWithASeenPersonIsMissed) {
  const test::CoarseTables tables;
  const auto& [cell, grid, luts, silhouettes] = tables;
  ValidationOptions options;
  options.scenes = 6;
  options.seed = 11;
  options.configurations_per_scene = 150;
  options.phantom_samples = 20;
  std::size_t scenes_done = 0;
  const ValidationReport report =
      validate_against_ground_truth(cell, grid, luts, silhouettes, options,
                                    [&](std::size_t done, std::size_t) { scenes_done = done; });
  EXPECT_EQ(scenes_done, options.scenes);
  EXPECT_EQ(report.configs_checked, options.scenes * options.configurations_per_scene);
  EXPECT_GT(report.colliding, 10U) << "the scenes must test collisions at all";
  EXPECT_EQ(report.missed, 0U);
  EXPECT_EQ(report.free + report.colliding, report.configs_checked);
  EXPECT_GE(report.false_positive_rate, 0.0);
  EXPECT_LE(report.false_positive_rate, 1.0);
  EXPECT_GT(report.fusion_ms_p99, 0.0);
}

TEST(GroundTruthValidation, BoxesArePlacedSeenAndNeverMissed) {
  const test::CoarseTables tables;
  const auto& [cell, grid, luts, silhouettes] = tables;
  ValidationOptions options;
  options.scenes = 5;
  options.seed = 3;
  options.max_humans = 1;
  options.max_objects = 4;
  options.configurations_per_scene = 150;
  options.phantom_samples = 20;
  const ValidationReport report =
      validate_against_ground_truth(cell, grid, luts, silhouettes, options);
  EXPECT_GE(report.objects, options.scenes) << "too few boxes placed to test them";
  EXPECT_GT(report.colliding, 10U);
  EXPECT_EQ(report.missed, 0U);
  for (const auto& missed : report.missed_cases) ADD_FAILURE() << "missed " << missed.obstacle;
}

TEST(GroundTruthValidation, AbsurdOptionsAreRefused) {
  const test::CoarseTables tables;
  const auto& [cell, grid, luts, silhouettes] = tables;
  ValidationOptions options;
  options.scenes = 0;
  EXPECT_THROW((void)validate_against_ground_truth(cell, grid, luts, silhouettes, options),
               std::invalid_argument);
  options.scenes = 1;
  options.max_humans = 0;
  EXPECT_THROW((void)validate_against_ground_truth(cell, grid, luts, silhouettes, options),
               std::invalid_argument);
  options.max_humans = 1;
  options.max_objects = 11;
  EXPECT_THROW((void)validate_against_ground_truth(cell, grid, luts, silhouettes, options),
               std::invalid_argument);
}

}  // namespace
}  // namespace safecell
