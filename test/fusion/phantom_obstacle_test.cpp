// The paper's Figure 5 in a small world: a point robot moving in the unit square (C-space = its
// position, 2 joints), 1-D cameras in the plane, two round obstacles. Seen by two cameras the
// back-projection also marks the two places where a ray through one obstacle crosses a ray
// through the other (phantom obstacles); a third camera, with the threshold at three, removes
// them and keeps the real ones.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <numbers>

#include "safecell/fusion/forbidden_map_fusion.hpp"
#include "safecell/lut_build/cell_table_builder.hpp"
#include "safecell/lut_build/pixel_table_builder.hpp"

namespace safecell {
namespace {

constexpr int kColumns = 64;
constexpr double kFov = std::numbers::pi / 2.0;
constexpr double kObstacleRadius = 0.04;
const Eigen::Vector2d kObstacles[] = {{0.25, 0.25}, {0.75, 0.75}};

// A camera in the plane looking at the square's centre; a point's column from its angle.
struct PlaneCamera {
  Eigen::Vector2d position;

  [[nodiscard]] double angle_of(const Eigen::Vector2d& point) const {
    const Eigen::Vector2d axis = (Eigen::Vector2d(0.5, 0.5) - position).normalized();
    const Eigen::Vector2d to = point - position;
    return std::atan2(axis.x() * to.y() - axis.y() * to.x(), axis.dot(to));
  }
  [[nodiscard]] int column_of(double angle) const {
    return std::clamp(static_cast<int>(std::floor((angle + kFov / 2) / kFov * kColumns)), 0,
                      kColumns - 1);
  }
};

// The robot never covers anything here: fusion sees the obstacles alone.
class NoRobot final : public RobotSilhouettes {
 public:
  explicit NoRobot(std::size_t cameras) : cameras_(cameras) {}
  [[nodiscard]] std::size_t camera_count() const override { return cameras_; }
  void add_silhouette(CellIndex, std::size_t, FeatureMask&) const override {}

 private:
  std::size_t cameras_;
};

CspaceGrid unit_square_grid() {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = 2;
  const double l = 0.1 / (2.0 * std::sin(0.0125));  // cells of 1/40
  spec.joints[0] = JointSpec{0.0, 1.0, l, true};
  spec.joints[1] = JointSpec{0.0, 1.0, l, true};
  return CspaceGrid::create(spec).value();
}

struct Square {
  Eigen::Vector2d lo;
  Eigen::Vector2d hi;
};

Square square_of(const CspaceGrid& grid, CellIndex cell) {
  const GridCoords coords = grid.coords_of(cell).value();
  const AngleInterval x = grid.cell_bounds(coords, 0).value();
  const AngleInterval y = grid.cell_bounds(coords, 1).value();
  return {{x.lo_rad, y.lo_rad}, {x.hi_rad, y.hi_rad}};
}

LutSet plane_luts(const CspaceGrid& grid, const std::vector<PlaneCamera>& cameras) {
  CellTableBuild build;
  build.cell_count = grid.cell_count();
  build.table_count = cameras.size();
  build.columns = kColumns;
  build.rows = 1;
  const auto tables =
      build_cell_to_pixels_tables(build, [&](CellIndex cell, std::vector<FeatureMask>& masks) {
        const Square square = square_of(grid, cell);
        for (std::size_t c = 0; c < cameras.size(); ++c) {
          double lo = 10.0;
          double hi = -10.0;
          for (const Eigen::Vector2d& corner :
               {square.lo, square.hi, Eigen::Vector2d(square.lo.x(), square.hi.y()),
                Eigen::Vector2d(square.hi.x(), square.lo.y())}) {
            lo = std::min(lo, cameras[c].angle_of(corner));
            hi = std::max(hi, cameras[c].angle_of(corner));
          }
          masks[c].set_rect(FeatureRect{static_cast<std::uint16_t>(cameras[c].column_of(lo)), 0,
                                        static_cast<std::uint16_t>(cameras[c].column_of(hi)), 0});
        }
      });
  LutSet set;
  set.columns = kColumns;
  set.rows = 1;
  set.static_cells = CellSet(grid.cell_count());
  set.parts = {RobotPart{"arm", 0, 1}};
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    CameraLuts camera;
    camera.camera = "plane" + std::to_string(c);
    camera.parts.push_back(build_pixel_to_cells_tables(tables[c], grid));
    set.cameras.push_back(std::move(camera));
  }
  return set;
}

std::vector<CameraObservation> observe(const std::vector<PlaneCamera>& cameras) {
  std::vector<CameraObservation> observations;
  for (const auto& camera : cameras) {
    CameraObservation observation{true, FeatureMask(kColumns, 1)};
    for (const auto& obstacle : kObstacles) {
      const double centre = camera.angle_of(obstacle);
      const double half = std::asin(kObstacleRadius / (obstacle - camera.position).norm());
      observation.blocked.set_rect(
          FeatureRect{static_cast<std::uint16_t>(camera.column_of(centre - half)), 0,
                      static_cast<std::uint16_t>(camera.column_of(centre + half)), 0});
    }
    observations.push_back(std::move(observation));
  }
  return observations;
}

struct Outcome {
  int obstacle_cells = 0;
  int obstacle_cells_forbidden = 0;
  int phantom_cells = 0;  // forbidden, and far from both obstacles
};

Outcome fuse_scene(const std::vector<PlaneCamera>& cameras) {
  const CspaceGrid grid = unit_square_grid();
  const LutSet luts = plane_luts(grid, cameras);
  const NoRobot robot(cameras.size());
  FusionSettings settings;
  settings.camera_threshold = static_cast<int>(cameras.size());
  ForbiddenMapFusion fusion(luts, robot, settings);
  const CellSet& forbidden = fusion.fuse(observe(cameras), 0);
  Outcome outcome;
  for (CellIndex cell = 0; cell < grid.cell_count(); ++cell) {
    const Square square = square_of(grid, cell);
    double nearest = 10.0;
    bool touches = false;
    for (const auto& obstacle : kObstacles) {
      const Eigen::Vector2d closest = obstacle.cwiseMax(square.lo).cwiseMin(square.hi);
      touches = touches || (closest - obstacle).norm() <= kObstacleRadius;
      nearest = std::min(nearest, (0.5 * (square.lo + square.hi) - obstacle).norm());
    }
    outcome.obstacle_cells += touches ? 1 : 0;
    outcome.obstacle_cells_forbidden += touches && forbidden.test(cell) ? 1 : 0;
    outcome.phantom_cells += nearest > 0.15 && forbidden.test(cell) ? 1 : 0;
  }
  return outcome;
}

TEST(PhantomObstacles, AppearWithTwoCamerasAndDisappearWithThree) {
  const PlaneCamera left{{-1.0, 0.5}};
  const PlaneCamera below{{0.5, -1.0}};
  // Looking along the diagonal through both obstacles: its one blocked ray meets the other
  // cameras' rays only at the real obstacles.
  const PlaneCamera upper_right{{2.0, 2.0}};

  const Outcome two = fuse_scene({left, below});
  EXPECT_GT(two.obstacle_cells, 0);
  EXPECT_EQ(two.obstacle_cells_forbidden, two.obstacle_cells);
  EXPECT_GT(two.phantom_cells, 0)
      << "two cameras should see phantoms at (0.25, 0.75), (0.75, 0.25)";

  const Outcome three = fuse_scene({left, below, upper_right});
  EXPECT_EQ(three.obstacle_cells_forbidden, three.obstacle_cells);
  EXPECT_EQ(three.phantom_cells, 0);
}

}  // namespace
}  // namespace safecell
