// `safecell validate` end to end: the real pipeline misses nothing, every negative control is
// caught, and the figures do not depend on threads or shards.

#include "safecell/validation/ground_truth_validation.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "model_fixture.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/lut_build/model_luts.hpp"
#include "safecell/pipeline/cell_fusion_settings.hpp"
#include "safecell/validation/configuration_strata.hpp"

namespace safecell {
namespace {

// Under AddressSanitizer the table build runs about ten times slower: there the tables draw
// whole cells (the same checks, on wider silhouettes; `safecell validate --envelope-max-move 0.18`
// runs the same on the host build), and the full default only on the host build.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

CellConfig tested_cell() {
  CellConfig config = default_cell();
  if (kSanitized) config.envelope_max_move_m.reset();
  return config;
}

// The default cell's tables (the negative controls are tuned to catch on it), built once.
struct DefaultTables {
  CellModel cell = load_cell_model(tested_cell());
  CspaceGrid grid = make_grid(cell.config);
  LutSet luts = build_model_luts(cell, grid);
  // Robot removal's, as `safecell validate` draws them: whole cells.
  ModelSilhouettes silhouettes{cell, grid, ModelLutOptions{}, CellDrawing::kWholeCells};
};

class GroundTruthValidation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { tables_ = std::make_unique<DefaultTables>(); }
  static void TearDownTestSuite() { tables_.reset(); }

  // The fixed seed of the negative controls: 60 scenes (ten of each stratum), voted as the
  // default cell asks.
  static ValidationOptions fixed_seed() {
    ValidationOptions options;
    options.scenes = 60;
    options.seed = 11;
    options.configurations_per_scene = 300;
    options.fusion = cell_fusion_settings(tables_->cell);
    return options;
  }
  static ValidationReport validate(const ValidationOptions& options) {
    return validate_against_ground_truth(tables_->cell, tables_->grid, tables_->luts,
                                         tables_->silhouettes, options);
  }

  static std::unique_ptr<DefaultTables> tables_;
};

std::unique_ptr<DefaultTables> GroundTruthValidation::tables_;

TEST_F(GroundTruthValidation, ThePipelineMissesNoCollisionWithAVisibleBody) {
  std::size_t scenes_done = 0;
  const ValidationOptions options = fixed_seed();
  const ValidationReport report = validate_against_ground_truth(
      tables_->cell, tables_->grid, tables_->luts, tables_->silhouettes, options,
      [&](std::size_t done, std::size_t) { scenes_done = done; });
  EXPECT_EQ(scenes_done, options.scenes);
  EXPECT_EQ(report.scenes, options.scenes);
  EXPECT_EQ(report.configs_checked, options.scenes * options.configurations_per_scene);
  EXPECT_GT(report.colliding, 1000U) << "the scenes must test collisions at all";
  EXPECT_EQ(report.missed, 0U);
  for (const auto& missed : report.missed_cases) {
    ADD_FAILURE() << "missed: scene " << missed.scene << " (" << missed.stratum << "), "
                  << missed.body;
  }
  EXPECT_EQ(report.free + report.colliding, report.configs_checked);
  EXPECT_GT(report.clear, 0U);
  EXPECT_LE(report.clear_forbidden, report.clear);
  // Every stratum drawn and tested for collisions.
  for (const SceneStratum stratum : kAllSceneStrata) {
    const std::string name = std::string("scene/") + to_string(stratum);
    EXPECT_EQ(report.scenes_per_stratum.at(to_string(stratum)), options.scenes / kSceneStrata);
    EXPECT_GT(report.strata.at(name).colliding, 0U) << name;
  }
  for (const ConfigurationStratum stratum : kAllConfigurationStrata) {
    const std::string name = std::string("configs/") + to_string(stratum);
    EXPECT_EQ(report.strata.at(name).configs, report.configs_checked / kConfigurationStrata);
    EXPECT_GT(report.strata.at(name).colliding, 0U) << name;
  }
}

// The two scenes of the 10,000 of `validate --seed 11` (scenes 6093 and 7255; shards 6094 and
// 7256 of 10,000) in which a person's part that the arm hides from two cameras collides: at the
// default cell's threshold of 3 the blob each of those cameras sees must grow far enough into the
// arm's silhouette (occlusion_reach_cells: 4) to count. With the reach of 3 feature cells the
// same scenes miss (1 configuration each, docs/validation.md): the negative control. It needs
// the tables as the default cell draws them (sub-cells): whole cells, as under the sanitizers,
// are wide enough to cover those two at the reach of 3 too, and there only the reach of 4 is
// checked. (On the arm segments of the default cell before commit 853d384 the scenes were 8023 and
// 9709.)
TEST_F(GroundTruthValidation, APersonTheArmHidesFromTwoCamerasIsNotMissedAtThresholdThree) {
  ASSERT_EQ(tables_->cell.camera_threshold, 3);
  for (const std::size_t shard : {6094U, 7256U}) {
    ValidationOptions options;
    options.scenes = 10000;
    options.seed = 11;
    options.configurations_per_scene = 400;  // `validate`'s default: the same configurations
    options.shard = Shard{shard, 10000};
    options.fusion = cell_fusion_settings(tables_->cell);
    const ValidationReport report = validate(options);
    EXPECT_GT(report.colliding, 100U) << "shard " << shard;
    EXPECT_EQ(report.missed, 0U) << "shard " << shard << " at reach "
                                 << options.fusion.occlusion_reach;
    if (kSanitized) continue;
    options.fusion.occlusion_reach = 3;
    const ValidationReport control = validate(options);
    EXPECT_EQ(control.colliding, report.colliding) << "shard " << shard;
    EXPECT_GT(control.missed, 0U) << "shard " << shard << ": the reach of 3 no longer misses";
    for (const auto& missed : control.missed_cases) {
      EXPECT_TRUE(missed.stratum == "against_arm" || missed.stratum == "reaching")
          << "shard " << shard << ": " << missed.stratum;
      EXPECT_EQ(missed.cameras_visible, 4) << "shard " << shard;
    }
  }
}

// A check that cannot fail is a defect: each deliberately broken pipeline must be caught.
TEST_F(GroundTruthValidation, EveryNegativeControlIsCaught) {
  for (const NegativeControl control :
       {NegativeControl::kEmptyMasks, NegativeControl::kDroppedStrip,
        NegativeControl::kEnvelopeRemoval}) {
    ValidationOptions options = fixed_seed();
    options.negative_control = control;
    const ValidationReport report = validate(options);
    EXPECT_GT(report.missed, 0U) << to_string(control) << " was not caught";
    EXPECT_FALSE(report.missed_cases.empty()) << to_string(control);
  }
}

TEST_F(GroundTruthValidation, ShardsAndThreadsAddUpToTheWholeRun) {
  ValidationOptions options = fixed_seed();
  options.scenes = 8;
  options.configurations_per_scene = 60;
  options.threads = 1;
  const ValidationReport whole = validate(options);
  options.threads = 2;
  ValidationReport merged;
  for (std::size_t k = 1; k <= 4; ++k) {
    options.shard = Shard{k, 4};
    merged += validate(options);
  }
  EXPECT_EQ(merged.scenes, whole.scenes);
  EXPECT_EQ(merged.configs_checked, whole.configs_checked);
  EXPECT_EQ(merged.colliding, whole.colliding);
  EXPECT_EQ(merged.missed, whole.missed);
  EXPECT_EQ(merged.unseen, whole.unseen);
  EXPECT_EQ(merged.unseen_reasons, whole.unseen_reasons);
  EXPECT_EQ(merged.free, whole.free);
  EXPECT_EQ(merged.false_positives, whole.false_positives);
  EXPECT_EQ(merged.clear, whole.clear);
  EXPECT_EQ(merged.clear_forbidden, whole.clear_forbidden);
  EXPECT_EQ(merged.bodies, whole.bodies);
  EXPECT_EQ(merged.objects, whole.objects);
  EXPECT_EQ(merged.strata, whole.strata);
  EXPECT_EQ(merged.scenes_per_stratum, whole.scenes_per_stratum);
  EXPECT_NEAR(merged.forbidden_share_sum, whole.forbidden_share_sum, 1e-9);
}

TEST_F(GroundTruthValidation, TheDocumentedModelErrorIsCoveredAndChangesTheWorld) {
  ValidationOptions options = fixed_seed();
  options.scenes = 24;
  const ValidationReport exact = validate(options);
  options.model_error = kDocumentedTolerances;
  const ValidationReport with_error = validate(options);
  EXPECT_EQ(with_error.missed, 0U);
  for (const auto& missed : with_error.missed_cases) {
    ADD_FAILURE() << "missed: scene " << missed.scene << " (" << missed.stratum << "), "
                  << missed.body;
  }
  // The larger robot of the world collides more often: the ground truth is the world's.
  EXPECT_GT(with_error.colliding, exact.colliding);
}

TEST_F(GroundTruthValidation, NeedlessStopsAreTracedToACause) {
  ValidationOptions options = fixed_seed();
  options.scenes = 12;
  options.needless_stops_traced_per_scene = 3;
  const ValidationReport report = validate(options);
  EXPECT_GT(report.clear_forbidden, 0U);
  EXPECT_GT(report.causes.traced, 0U);
  EXPECT_LE(report.causes.traced, std::min<std::size_t>(report.clear_forbidden, 3 * 12));
  EXPECT_EQ(report.causes.in_cell + report.causes.visual_hull + report.causes.envelope,
            report.causes.traced);
  options.needless_stops_traced_per_scene = 0;
  const ValidationReport untraced = validate(options);
  EXPECT_EQ(untraced.causes.traced, 0U);
  EXPECT_EQ(untraced.strata, report.strata) << "tracing must not change what is sampled";
}

TEST_F(GroundTruthValidation, AbsurdOptionsAreRefused) {
  ValidationOptions options;
  options.scenes = 0;
  EXPECT_THROW((void)validate(options), std::invalid_argument);
  options.scenes = 1;
  options.limits.max_humans = 0;
  EXPECT_THROW((void)validate(options), std::invalid_argument);
  options.limits.max_humans = 1;
  options.limits.max_objects = 11;
  EXPECT_THROW((void)validate(options), std::invalid_argument);
  options.limits.max_objects = 1;
  options.shard = Shard{3, 2};
  EXPECT_THROW((void)validate(options), std::invalid_argument);
  options.shard = Shard{1, 2};  // more shards than scenes
  EXPECT_THROW((void)validate(options), std::invalid_argument);
}

TEST(ScenesOfShard, ShardsAreDisjointAndCoverEveryScene) {
  for (const std::size_t scenes : {1U, 7U, 10000U}) {
    for (std::size_t count = 1; count <= std::min<std::size_t>(scenes, 9); ++count) {
      std::size_t next = 0;
      for (std::size_t k = 1; k <= count; ++k) {
        const SceneRange range = scenes_of_shard(scenes, Shard{k, count});
        EXPECT_EQ(range.first, next) << scenes << " scenes, shard " << k << "/" << count;
        next = range.end;
      }
      EXPECT_EQ(next, scenes);
    }
  }
}

}  // namespace
}  // namespace safecell
