#include "safecell/camera/feature_grid.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "safecell/camera/camera_error.hpp"
#include "safecell/camera/default_cameras.hpp"
#include "safecell/camera/feature_projection.hpp"

namespace safecell {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::string grid_error_of(int width_px, int height_px, int columns, int rows) {
  try {
    static_cast<void>(FeatureGrid::tiling(width_px, height_px, columns, rows));
  } catch (const CameraError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(FeatureGrid, ThePapersGrid) {
  const FeatureGrid grid;
  EXPECT_EQ(grid.columns(), 64);
  EXPECT_EQ(grid.rows(), 64);
  EXPECT_EQ(grid.cell_width_px(), 11);
  EXPECT_EQ(grid.cell_height_px(), 9);
  EXPECT_EQ(grid.image_width_px(), 704);
  EXPECT_EQ(grid.image_height_px(), 576);
  EXPECT_EQ(grid.cell_count(), 4096u);
  EXPECT_EQ(FeatureGrid::tiling(704, 576), grid);
}

TEST(FeatureGrid, CellsAtCornersAndEdges) {
  const FeatureGrid grid;
  EXPECT_EQ(grid.cell_of({-0.5, -0.5}), (FeatureCell{0, 0}));
  EXPECT_EQ(grid.cell_of({0.0, 0.0}), (FeatureCell{0, 0}));
  // Pixel 10 is the last of column 0, pixel 11 the first of column 1; rows are 9 px.
  EXPECT_EQ(grid.cell_of({10.49, 8.49}), (FeatureCell{0, 0}));
  EXPECT_EQ(grid.cell_of({10.5, 8.5}), (FeatureCell{1, 1}));
  EXPECT_EQ(grid.cell_of({703.0, 575.0}), (FeatureCell{63, 63}));
  EXPECT_EQ(grid.cell_of({703.4999, 575.4999}), (FeatureCell{63, 63}));
  EXPECT_EQ(grid.cell_of({std::nextafter(703.5, 0.0), 0.0}), (FeatureCell{63, 0}));
  EXPECT_EQ(grid.cell_of({0.0, 575.0}), (FeatureCell{0, 63}));
  EXPECT_EQ(grid.cell_of({351.5, 287.5}), (FeatureCell{32, 32}));
  EXPECT_FALSE(grid.cell_of({703.5, 0.0}).has_value());
  EXPECT_FALSE(grid.cell_of({0.0, 575.5}).has_value());
  EXPECT_FALSE(grid.cell_of({-0.51, 0.0}).has_value());
  EXPECT_FALSE(grid.cell_of({0.0, -0.51}).has_value());
  EXPECT_FALSE(grid.cell_of({kNan, 0.0}).has_value());
  EXPECT_FALSE(grid.cell_of({1e300, 0.0}).has_value());
}

TEST(FeatureGrid, IndicesAreRowMajor) {
  const FeatureGrid grid;
  EXPECT_EQ(grid.index_of({0, 0}), 0u);
  EXPECT_EQ(grid.index_of({63, 0}), 63u);
  EXPECT_EQ(grid.index_of({0, 1}), 64u);
  EXPECT_EQ(grid.index_of({5, 7}), 7u * 64u + 5u);
  EXPECT_EQ(grid.index_of({63, 63}), 4095u);
  EXPECT_THROW(static_cast<void>(grid.index_of({64, 0})), CameraError);
  EXPECT_THROW(static_cast<void>(grid.index_of({0, -1})), CameraError);
  try {
    static_cast<void>(grid.index_of({-1, 3}));
    FAIL() << "no error";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()),
              "feature grid: cell: (column -1, row 3) is outside the grid, expected columns "
              "0..63 and rows 0..63");
  }
}

TEST(FeatureGrid, CellRectangles) {
  const FeatureGrid grid;
  EXPECT_EQ(grid.cell_rect_px({0, 0}), cv::Rect(0, 0, 11, 9));
  EXPECT_EQ(grid.cell_rect_px({1, 2}), cv::Rect(11, 18, 11, 9));
  EXPECT_EQ(grid.cell_rect_px({63, 63}), cv::Rect(693, 567, 11, 9));
  EXPECT_THROW(static_cast<void>(grid.cell_rect_px({0, 64})), CameraError);
}

TEST(FeatureGrid, EveryPixelLiesInTheRectangleOfItsCell) {
  for (const FeatureGrid& grid :
       {FeatureGrid(), FeatureGrid::tiling(640, 480, 64, 48), FeatureGrid::tiling(30, 20, 3, 4)}) {
    std::size_t pixels = 0;
    for (int v = 0; v < grid.image_height_px(); ++v) {
      for (int u = 0; u < grid.image_width_px(); ++u) {
        const auto cell = grid.cell_of({u, v});
        ASSERT_TRUE(cell.has_value()) << u << ", " << v;
        ASSERT_TRUE(grid.cell_rect_px(*cell).contains({u, v})) << u << ", " << v;
        ASSERT_LT(grid.index_of(*cell), grid.cell_count());
        ++pixels;
      }
    }
    EXPECT_EQ(pixels, grid.cell_count() * static_cast<std::size_t>(grid.cell_width_px()) *
                          static_cast<std::size_t>(grid.cell_height_px()));
  }
}

TEST(FeatureGrid, TilingMustBeExact) {
  const FeatureGrid grid = FeatureGrid::tiling(640, 480, 64, 48);
  EXPECT_EQ(grid.cell_width_px(), 10);
  EXPECT_EQ(grid.cell_height_px(), 10);
  EXPECT_EQ(grid_error_of(700, 576, 64, 64),
            "feature grid: image_width_px: 700 px, expected a positive multiple of the 64 "
            "columns so that they tile it exactly");
  EXPECT_EQ(grid_error_of(704, 570, 64, 64),
            "feature grid: image_height_px: 570 px, expected a positive multiple of the 64 rows "
            "so that they tile it exactly");
  EXPECT_EQ(grid_error_of(0, 576, 64, 64).rfind("feature grid: image_width_px: 0 px", 0), 0u);
  EXPECT_EQ(grid_error_of(704, 576, 0, 64),
            "feature grid: columns: 0, expected a number of cells > 0");
  EXPECT_EQ(grid_error_of(704, 576, 64, -1),
            "feature grid: rows: -1, expected a number of cells > 0");
}

TEST(FeatureGrid, ProjectsCellPointsToFeatureCells) {
  const PinholeCamera camera = default_cameras()[0];
  const FeatureGrid grid;
  // The camera looks at (0, 0, 0.8): the principal point (351.5, 287.5) is pixel (352, 288).
  EXPECT_EQ(project_to_feature_cell(camera, grid, {0.0, 0.0, 0.8}), (FeatureCell{32, 32}));
  // Behind the camera, and beside it out of the field of view.
  EXPECT_FALSE(project_to_feature_cell(camera, grid, {3.0, 3.0, 3.0}).has_value());
  EXPECT_FALSE(project_to_feature_cell(camera, grid, {1.95, -1.95, 2.9}).has_value());
  try {
    static_cast<void>(
        project_to_feature_cell(camera, FeatureGrid::tiling(640, 480, 64, 48), {0, 0, 0}));
    FAIL() << "no error";
  } catch (const CameraError& error) {
    EXPECT_EQ(std::string(error.what()),
              "camera 'cam0': feature grid: 64 x 48 cells of 10 x 10 px cover 640 x 480 px, "
              "expected the camera's 704 x 576 px image");
  }
}

}  // namespace
}  // namespace safecell
