#include "safecell/envelope/static_obstacle_cells.hpp"

#include <algorithm>
#include <mutex>
#include <optional>
#include <variant>

#include "safecell/geometry/point_transform.hpp"
#include "safecell/geometry/shape_bounds.hpp"

namespace safecell {

namespace {

// Added to the bounding sphere of the quick rejection below, so that rounding there never turns
// away a ball the exact test would take.
constexpr double kRejectMargin_m = 1e-6;

// Lines of joint-0 cells per chunk of work (a line of the default cell is 48 cells, of the 6 cm
// grid 142).
constexpr std::size_t kLinesPerChunk = 16;

// An obstacle as the test per ball needs it: the pose inverted once (per ball, the inversion was
// most of the stage's time), a box's half size or another shape's bounding radius.
struct ObstacleTest {
  explicit ObstacleTest(const PlacedShape& obstacle)
      : cell_to_local(obstacle.pose.inverse()), origin_m(obstacle.pose.translation()) {
    if (const auto* box = std::get_if<Box>(&obstacle.shape)) {
      half_size_m = box->size_m / 2.0;
      bounding_radius = half_size_m->norm();
    } else {
      bounding_radius = bounding_radius_m(obstacle.shape);
    }
  }

  [[nodiscard]] bool reached_by(const Ball& ball) const {
    // Most balls are far from every obstacle: a ball that reaches the shape reaches its bounding
    // sphere, so one farther from the sphere is turned away before the transform.
    const double reach = ball.radius_m + bounding_radius + kRejectMargin_m;
    if ((ball.centre_m - origin_m).squaredNorm() > reach * reach) return false;
    const Eigen::Vector3d local = transform_point(cell_to_local, ball.centre_m);
    if (half_size_m) {
      const Eigen::Vector3d outside = (local.cwiseAbs() - *half_size_m).cwiseMax(0.0);
      return outside.norm() <= ball.radius_m;
    }
    return local.norm() <= ball.radius_m + bounding_radius;
  }

  Eigen::Isometry3d cell_to_local;
  Eigen::Vector3d origin_m;                    // the shape's origin, cell frame
  std::optional<Eigen::Vector3d> half_size_m;  // a box
  double bounding_radius = 0.0;  // of the shape about its origin (a box's half diagonal)
};

}  // namespace

bool ball_reaches(const Ball& ball, const PlacedShape& obstacle) {
  return ObstacleTest(obstacle).reached_by(ball);
}

CellSet static_obstacle_cells(const CellEnvelope& envelope,
                              const std::vector<PlacedShape>& obstacles, unsigned threads,
                              const ProgressCallback& progress) {
  const CspaceGrid& grid = envelope.grid();
  CellSet cells(grid.cell_count());
  if (obstacles.empty()) return cells;
  const std::vector<ObstacleTest> tests(obstacles.begin(), obstacles.end());
  const auto reaches_one = [&tests](const Ball& ball) {
    return std::any_of(tests.begin(), tests.end(),
                       [&](const ObstacleTest& test) { return test.reached_by(ball); });
  };
  // Whether one of the balls, moved by `motion` (CellEnvelope::moved_ball), reaches an obstacle.
  const auto moved_reach = [&](const std::vector<Ball>& balls, const Eigen::Isometry3d& motion) {
    return std::any_of(balls.begin(), balls.end(), [&](const Ball& ball) {
      return reaches_one(CellEnvelope::moved_ball(motion, ball));
    });
  };
  // The head's bodies are tested once per prefix (cell_envelope.hpp).
  const std::size_t cached_bodies = envelope.tail_body();
  std::vector<std::vector<bool>> cached(cached_bodies);  // [body][prefix]
  for (std::size_t body = 0; body < cached_bodies; ++body) {
    for (std::size_t prefix = 0; prefix < envelope.prefix_count(body); ++prefix) {
      std::vector<Ball> balls;
      envelope.append_body_balls(body, prefix, balls);
      cached[body].push_back(std::any_of(balls.begin(), balls.end(), reaches_one));
    }
  }
  // Cells are numbered with joint 0 fastest: a line is the cells of joint 0 with the other joints'
  // cells the same. The tail's bounds and balls are made once per line, for its first cell, and
  // moved to the others (CellEnvelope::first_joint_motions): the robot's pose is computed once
  // per line instead of once or twice per cell.
  std::vector<Eigen::Isometry3d> motions;
  envelope.first_joint_motions(motions);
  const std::uint32_t line_length = grid.cells_along(0);
  std::mutex cells_mutex;
  parallel_chunks(
      grid.cell_count() / line_length, kLinesPerChunk, threads,
      [&](std::size_t, std::size_t begin, std::size_t end) {
        std::vector<Ball> balls;
        std::vector<Ball> bounds;
        std::vector<CellIndex> hits;
        for (std::size_t line = begin; line < end; ++line) {
          const auto first = static_cast<CellIndex>(line * line_length);
          GridCoords coords = grid.coords_of(first).value();
          const bool bounded = envelope.tail_bounds(coords, bounds);
          envelope.balls_of_bodies(coords, cached_bodies, envelope.body_count(), balls);
          for (std::uint32_t along = 0; along < line_length; ++along) {
            coords.along[0] = along;
            bool hit = false;
            for (std::size_t body = 0; body < cached_bodies && !hit; ++body) {
              hit = cached[body][envelope.prefix_of(coords, body)];
            }
            // Most cells keep the robot far from every obstacle: their tail's bounds reach none,
            // and its balls need not be tested.
            if (!hit && !(bounded && !moved_reach(bounds, motions[along]))) {
              hit = moved_reach(balls, motions[along]);
            }
            if (hit) hits.push_back(first + along);
          }
        }
        const std::lock_guard lock(cells_mutex);
        for (const CellIndex cell : hits) cells.set(cell);
      },
      progress);
  return cells;
}

}  // namespace safecell
