#include "safecell/lut_build/model_luts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "model_fixture.hpp"
#include "safecell/geometry/tessellate.hpp"
#include "safecell/lut_build/cell_table_builder.hpp"
#include "safecell/lut_build/pixel_table_builder.hpp"
#include "safecell/robot/kinematics.hpp"
#include "safecell/silhouettes/model_silhouettes.hpp"
#include "safecell/sim/cell_simulation.hpp"
#include "safecell/sim/ground_truth.hpp"
#include "safecell/test/property.hpp"
#include "silhouette_check.hpp"

namespace safecell {
namespace {

class ModelLuts : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    cell_ = new CellModel(test::coarse_default_cell());
    grid_ = new CspaceGrid(make_grid(cell_->config));
    silhouettes_ = new ModelSilhouettes(*cell_, *grid_, ModelLutOptions{});
  }
  static void TearDownTestSuite() {
    delete silhouettes_;
    delete grid_;
    delete cell_;
  }

  static std::vector<CellToPixelsTable> cell_tables(unsigned threads = 2) {
    CellTableBuild build;
    build.cell_count = grid_->cell_count();
    build.table_count = cell_->cameras.size();
    build.columns = cell_->feature_grid.columns();
    build.rows = cell_->feature_grid.rows();
    build.threads = threads;
    return build_cell_to_pixels_tables(build, [](CellIndex cell, std::vector<FeatureMask>& masks) {
      silhouettes_->add_silhouettes(cell, masks);
    });
  }

  static CellModel* cell_;
  static CspaceGrid* grid_;
  static ModelSilhouettes* silhouettes_;
};

CellModel* ModelLuts::cell_ = nullptr;
CspaceGrid* ModelLuts::grid_ = nullptr;
ModelSilhouettes* ModelLuts::silhouettes_ = nullptr;

// Every vertex of the robot's tessellated collision shapes, at random configurations inside
// random cells, lies in a ball of the cell's envelope.
// With `bodies`, the envelope of those bodies holds their shapes.
void expect_envelope_holds_robot(const CellModel& cell, const CspaceGrid& grid,
                                 const CellEnvelope& envelope, int iterations,
                                 BodyRange bodies = {}) {
  test::PropertyRun run(iterations);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid.cell_count() - 1);
  std::vector<Ball> balls;
  for (int i = 0; i < run.iterations(); ++i) {
    const CellIndex index = any_cell(run.rng());
    envelope.balls_of_bodies(grid.coords_of(index).value(), bodies.first, bodies.end, balls);
    const auto q = test::configuration_in(grid, index, run.rng());
    for (const auto& shape :
         collision_shapes_at(*cell.robot, q, Eigen::Isometry3d::Identity(), bodies)) {
      const TriangleMesh mesh = tessellate(shape);
      for (const auto& point : mesh.vertices) {
        const bool inside = std::any_of(balls.begin(), balls.end(), [&](const Ball& ball) {
          return (point - ball.centre_m).norm() <= ball.radius_m + 1e-9;
        });
        ASSERT_TRUE(inside) << "cell " << index << " bodies " << bodies.first << ".." << bodies.end
                            << " point " << point.transpose();
      }
    }
  }
}

CellEnvelope envelope_with_head(const CellModel& cell, const CspaceGrid& grid,
                                std::size_t max_head_prefixes,
                                const std::vector<std::size_t>& part_starts = {}) {
  const ModelLutOptions options;
  return CellEnvelope(*cell.robot, cover_with_balls(*cell.robot, ball_radius_of(cell, options)),
                      grid, options.padding_m, part_starts, max_head_prefixes);
}

TEST_F(ModelLuts, EnvelopeHoldsTheRobotAnywhereInTheCell) {
  expect_envelope_holds_robot(*cell_, *grid_, silhouettes_->envelope(), 300);
}

TEST_F(ModelLuts, EnvelopeFromTailTablesHoldsTheRobotAnywhereInTheCell) {
  // Short heads, so that the tables hold the arm from the base joint, the shoulder or the elbow on.
  for (const std::size_t max_head_prefixes :
       {std::size_t{1}, std::size_t{300}, std::size_t{3000}}) {
    const CellEnvelope envelope = envelope_with_head(*cell_, *grid_, max_head_prefixes);
    ASSERT_GT(envelope.tail_table_balls(), 0u) << "head of up to " << max_head_prefixes;
    ASSERT_LT(envelope.tail_body(), envelope.body_count());
    expect_envelope_holds_robot(*cell_, *grid_, envelope, 150);
  }
}

TEST_F(ModelLuts, EachPartsEnvelopeHoldsItsBodies) {
  // Heads from the base joint on, so that the tail tables are cut where the parts begin.
  for (const PartSplit split :
       {PartSplit::kPerLink, PartSplit::kArmSegments, PartSplit::kLinksAndWrist}) {
    std::vector<std::size_t> starts;
    const std::vector<RobotPart> parts = robot_parts(*cell_->robot, split);
    for (const RobotPart& part : parts) starts.push_back(part.first_body);
    for (const std::size_t max_head_prefixes : {std::size_t{1}, std::size_t{300}}) {
      const CellEnvelope envelope = envelope_with_head(*cell_, *grid_, max_head_prefixes, starts);
      ASSERT_GT(envelope.tail_table_balls(), 0u);
      for (const RobotPart& part : parts) {
        SCOPED_TRACE(std::string(to_string(split)) + ", part " + part.name + ", head of up to " +
                     std::to_string(max_head_prefixes));
        expect_envelope_holds_robot(*cell_, *grid_, envelope, 60,
                                    BodyRange{part.first_body, part.end_body});
      }
    }
  }
  EXPECT_THROW(envelope_with_head(*cell_, *grid_, 300, {cell_->robot->dof() + 1}),
               std::invalid_argument);
}

TEST_F(ModelLuts, PartSilhouettesHoldTheRenderedPartAndUniteToTheRobot) {
  SimulatedCell sim = simulate_cell(*cell_, SensorSettings{});
  const FeatureGrid& features = cell_->feature_grid;
  const std::size_t cameras = cell_->cameras.size();
  for (const PartSplit split :
       {PartSplit::kPerLink, PartSplit::kArmSegments, PartSplit::kLinksAndWrist}) {
    const ModelSilhouettes silhouettes(*cell_, *grid_, test::options_with(split));
    const std::vector<RobotPart>& parts = silhouettes.parts();
    test::PropertyRun run(10);
    std::uniform_int_distribution<CellIndex> any_cell(0, grid_->cell_count() - 1);
    for (int i = 0; i < run.iterations(); ++i) {
      const CellIndex index = any_cell(run.rng());
      const auto q = test::configuration_in(*grid_, index, run.rng());
      std::vector<FeatureMask> whole(cameras, FeatureMask(features));
      silhouettes.add_silhouettes(index, whole);
      std::vector<FeatureMask> united(cameras, FeatureMask(features));
      for (std::size_t p = 0; p < parts.size(); ++p) {
        std::vector<FeatureMask> part(cameras, FeatureMask(features));
        silhouettes.add_part_silhouettes(index, p, part.data());
        for (std::size_t camera = 0; camera < cameras; ++camera) {
          united[camera] |= part[camera];
          const cv::Mat covered =
              sim.robot_coverage(camera, q, BodyRange{parts[p].first_body, parts[p].end_body});
          for (int y = 0; y < covered.rows; ++y) {
            for (int x = 0; x < covered.cols; ++x) {
              if (covered.at<std::uint8_t>(y, x) == 0) continue;
              ASSERT_TRUE(
                  part[camera].test(x / features.cell_width_px(), y / features.cell_height_px()))
                  << to_string(split) << ", part " << parts[p].name << ", camera " << camera
                  << " pixel " << x << "," << y << " cell " << index;
            }
          }
        }
      }
      for (std::size_t camera = 0; camera < cameras; ++camera) {
        ASSERT_EQ(united[camera], whole[camera]) << to_string(split) << ", cell " << index;
      }
    }
    EXPECT_THROW(silhouettes.add_part_silhouettes(0, parts.size(), nullptr), std::out_of_range);
  }
}

TEST_F(ModelLuts, TailTablesGiveFewerOfTheBallsComputedPerCell) {
  // The tables sweep in another frame, but every ball they keep is one of the balls computed per
  // cell; swept over the whole range of the wrist joints, many of the hand's balls fall inside
  // others and are dropped.
  const CellEnvelope per_cell =
      envelope_with_head(*cell_, *grid_, std::numeric_limits<std::size_t>::max());
  EXPECT_EQ(per_cell.tail_table_balls(), 0u);
  EXPECT_EQ(per_cell.tail_body(), per_cell.body_count());
  std::vector<Ball> from_tables;
  std::vector<Ball> computed;
  for (const std::size_t max_head_prefixes :
       {std::size_t{1}, std::size_t{300}, std::size_t{3000}}) {
    const CellEnvelope tabled = envelope_with_head(*cell_, *grid_, max_head_prefixes);
    ASSERT_GT(tabled.tail_table_balls(), 0u) << "head of up to " << max_head_prefixes;
    for (const CellIndex index : {CellIndex{0}, grid_->cell_count() / 3, grid_->cell_count() - 1}) {
      const GridCoords coords = grid_->coords_of(index).value();
      tabled.balls_of_cell(coords, from_tables);
      per_cell.balls_of_cell(coords, computed);
      EXPECT_LT(from_tables.size(), computed.size()) << "cell " << index;
      for (const Ball& ball : from_tables) {
        const bool computed_too = std::any_of(computed.begin(), computed.end(), [&](const Ball& b) {
          return (b.centre_m - ball.centre_m).norm() < 1e-9 &&
                 std::abs(b.radius_m - ball.radius_m) < 1e-9;
        });
        ASSERT_TRUE(computed_too) << "head of up to " << max_head_prefixes << ", cell " << index
                                  << ": ball at " << ball.centre_m.transpose() << " radius "
                                  << ball.radius_m;
      }
    }
  }
}

TEST_F(ModelLuts, SilhouetteHoldsTheRenderedRobot) {
  test::expect_silhouettes_hold_rendered_robot(*cell_, *grid_, *silhouettes_, 40);
}

TEST_F(ModelLuts, PixelTableIsTheExactInverseOfTheCellTable) {
  const auto tables = cell_tables();
  for (const std::size_t budget : {std::size_t{256} << 20, std::size_t{1} << 16}) {
    PixelTableBuild build;
    build.memory_budget_bytes = budget;  // the small budget makes one band per feature row
    const PartLuts pyramid = build_pixel_to_cells_tables(tables[0], *grid_, build);
    const PixelToCellsTable& pixels = pyramid.pixel_to_cells;
    std::vector<CellSet> oracle(pixels.pixel_count(), CellSet(grid_->cell_count()));
    for (CellIndex cell = 0; cell < grid_->cell_count(); ++cell) {
      const FeatureMask mask = tables[0].mask_of(cell);
      for (int row = 0; row < mask.rows(); ++row) {
        for (int column = 0; column < mask.columns(); ++column) {
          if (mask.test(column, row)) {
            oracle[static_cast<std::size_t>(row * mask.columns() + column)].set(cell);
          }
        }
      }
    }
    for (std::size_t pixel = 0; pixel < pixels.pixel_count(); ++pixel) {
      CellSet decoded(grid_->cell_count());
      pixels.add_cells(pixel, decoded);
      ASSERT_EQ(decoded, oracle[pixel]) << "pixel " << pixel << " budget " << budget;
    }
    // Every block of the pyramid holds exactly the union of its pixels' cells.
    ASSERT_EQ(pyramid.pixel_blocks.size(), 3U);
    for (std::size_t level = 1; level <= pyramid.pixel_blocks.size(); ++level) {
      const PixelToCellsTable& blocks = pyramid.pixel_blocks[level - 1];
      const int size = 1 << level;
      for (int y = 0; y < blocks.rows(); ++y) {
        for (int x = 0; x < blocks.columns(); ++x) {
          CellSet expected(grid_->cell_count());
          for (int py = y * size; py < std::min(pixels.rows(), (y + 1) * size); ++py) {
            for (int px = x * size; px < std::min(pixels.columns(), (x + 1) * size); ++px) {
              expected |= oracle[static_cast<std::size_t>(py * pixels.columns() + px)];
            }
          }
          CellSet decoded(grid_->cell_count());
          blocks.add_cells(static_cast<std::size_t>(y * blocks.columns() + x), decoded);
          ASSERT_EQ(decoded, expected) << "level " << level << " block " << x << "," << y;
        }
      }
    }
  }
}

// Cell c of the repeated table has the rectangles of cell c mod the table's cells, in order.
// Control: the table repeated once is itself, and a count past 2^32 - 1 cells is refused.
TEST(RepeatCells, EachCellHasTheRectanglesOfItsCellInTheFirstPeriod) {
  const CellToPixelsTable table(
      8, 8, {0, 2, 2, 3},
      {FeatureRect{0, 0, 1, 1}, FeatureRect{3, 3, 3, 4}, FeatureRect{7, 7, 7, 7}});
  const CellToPixelsTable repeated = repeat_cells(table, 4);
  ASSERT_EQ(repeated.cell_count(), 12u);
  for (CellIndex cell = 0; cell < repeated.cell_count(); ++cell) {
    const auto got = repeated.rects_of(cell);
    const auto want = table.rects_of(cell % 3);
    ASSERT_TRUE(std::equal(got.begin(), got.end(), want.begin(), want.end())) << "cell " << cell;
  }
  const CellToPixelsTable once = repeat_cells(table, 1);
  EXPECT_TRUE(std::equal(once.offsets().begin(), once.offsets().end(), table.offsets().begin(),
                         table.offsets().end()));
  EXPECT_THROW((void)repeat_cells(table, 1U << 31), std::invalid_argument);
  EXPECT_EQ(repeat_cells(table, 0).cell_count(), 0u);
}

TEST_F(ModelLuts, CellTableDoesNotDependOnTheThreadCount) {
  const auto one = cell_tables(1);
  const auto two = cell_tables(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t camera = 0; camera < one.size(); ++camera) {
    EXPECT_TRUE(std::equal(one[camera].offsets().begin(), one[camera].offsets().end(),
                           two[camera].offsets().begin(), two[camera].offsets().end()));
    EXPECT_TRUE(std::equal(one[camera].rects().begin(), one[camera].rects().end(),
                           two[camera].rects().begin(), two[camera].rects().end()));
  }
}

TEST_F(ModelLuts, StaticCellsHoldEveryCollisionWithTheWorkbench) {
  const LutSet set = build_model_luts(*cell_, *grid_);
  ASSERT_FALSE(cell_->obstacles.empty());
  const GroundTruth truth(cell_->obstacles);
  test::PropertyRun run(3000);
  std::uniform_int_distribution<CellIndex> any_cell(0, grid_->cell_count() - 1);
  // Joint 1 turned towards the workbench (at about 139 degrees), the rest anywhere.
  std::uniform_real_distribution<double> towards_bench(1.7, 3.1);
  int collisions = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    auto q = test::configuration_in(*grid_, any_cell(run.rng()), run.rng());
    q[0] = towards_bench(run.rng());
    if (!truth.collides(collision_shapes_at(*cell_->robot, q))) continue;
    ++collisions;
    ASSERT_TRUE(set.static_cells.test(test::cell_of(*grid_, q))) << "sample " << i;
  }
  if (run.full_length()) {
    EXPECT_GT(collisions, run.iterations() / 200) << "too few collisions to test anything";
  }
  EXPECT_LT(set.static_cells.count(), grid_->cell_count() / 2);
}

TEST_F(ModelLuts, SetCarriesTheFingerprintOfItsInputs) {
  const LutSet set = build_model_luts(*cell_, *grid_);
  EXPECT_EQ(set.fingerprint, model_lut_fingerprint(*cell_, *grid_, ModelLutOptions{}));
  EXPECT_EQ(set.grid_fingerprint, grid_->fingerprint());
  EXPECT_EQ(set.cameras.size(), cell_->cameras.size());
  ModelLutOptions padded;
  padded.padding_m = 0.03;
  EXPECT_NE(model_lut_fingerprint(*cell_, *grid_, padded), set.fingerprint);
  CellModel moved = *cell_;
  moved.obstacles[0].pose.translation().x() += 0.01;
  EXPECT_NE(model_lut_fingerprint(moved, *grid_, ModelLutOptions{}), set.fingerprint);
  // The parts voting: the cell's unless the options say; another split is other tables.
  const PartSplit other =
      cell_->robot_parts == PartSplit::kPerLink ? PartSplit::kArmSegments : PartSplit::kPerLink;
  EXPECT_NE(model_lut_fingerprint(*cell_, *grid_, test::options_with(other)), set.fingerprint);
  EXPECT_EQ(model_lut_fingerprint(*cell_, *grid_, test::options_with(cell_->robot_parts)),
            set.fingerprint);
  CellModel other_cell = *cell_;
  other_cell.robot_parts = other;
  EXPECT_EQ(model_lut_fingerprint(other_cell, *grid_, ModelLutOptions{}),
            model_lut_fingerprint(*cell_, *grid_, test::options_with(other)));
  EXPECT_EQ(set.parts.size(), robot_parts(*cell_->robot, cell_->robot_parts).size());
  // The balls' size: the cell's unless the options say.
  CellModel smaller_balls = *cell_;
  smaller_balls.ball_radius_m = cell_->ball_radius_m * 0.75;
  EXPECT_NE(model_lut_fingerprint(smaller_balls, *grid_, ModelLutOptions{}), set.fingerprint);
  ModelLutOptions with_radius;
  with_radius.ball_radius_m = smaller_balls.ball_radius_m;
  EXPECT_EQ(model_lut_fingerprint(*cell_, *grid_, with_radius),
            model_lut_fingerprint(smaller_balls, *grid_, ModelLutOptions{}));
  for (const CameraLuts& camera : set.cameras) EXPECT_EQ(camera.parts.size(), set.parts.size());
}

TEST_F(ModelLuts, AbsurdInputsAreRefused) {
  ModelLutOptions options;
  options.ball_radius_m = 0.0;
  EXPECT_THROW(ModelSilhouettes(*cell_, *grid_, options), std::invalid_argument);
  options = ModelLutOptions{};
  options.padding_m = -0.1;
  EXPECT_THROW(ModelSilhouettes(*cell_, *grid_, options), std::invalid_argument);
  options = ModelLutOptions{};
  options.parts = static_cast<PartSplit>(9);
  EXPECT_THROW(ModelSilhouettes(*cell_, *grid_, options), std::invalid_argument);
  CellModel no_camera = *cell_;
  no_camera.cameras.clear();
  EXPECT_THROW(ModelSilhouettes(no_camera, *grid_, ModelLutOptions{}), std::invalid_argument);
  CellModel no_robot = *cell_;
  no_robot.robot.reset();
  EXPECT_THROW(ModelSilhouettes(no_robot, *grid_, ModelLutOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
