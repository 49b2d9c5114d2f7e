#include "safecell/closed_loop/closed_loop_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "safecell/closed_loop/controller_setup.hpp"

namespace safecell {
namespace {

constexpr double kWallInset_m = 0.3;  // people come in this far inside the cell's walls
constexpr std::size_t kGoals = 3;

// A generator for one (seed, stream, index): scenarios and tasks do not share draws, so adding a
// draw to one leaves the other as it was.
std::mt19937_64 generator(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(stream), static_cast<std::uint32_t>(index),
                         static_cast<std::uint32_t>(index >> 32)};
  return std::mt19937_64(sequence);
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// A configuration of the arm's working pose family: the base swung to `base_rad`, shoulder,
// elbow and wrist a little off a reach forward and down (the demo's pose).
std::vector<double> working_pose(std::mt19937_64& rng, double base_rad) {
  return {base_rad,
          0.5 + uniform(rng, -0.3, 0.3),
          0.9 + uniform(rng, -0.3, 0.3),
          uniform(rng, -0.5, 0.5),
          0.6 + uniform(rng, -0.3, 0.3),
          uniform(rng, -1.0, 1.0)};
}

// A point on the walls' inset rectangle, at a random place along its perimeter.
Eigen::Vector2d wall_point(std::mt19937_64& rng, const CellModel& cell) {
  const double hx = cell.config.size_m[0] / 2.0 - kWallInset_m;
  const double hy = cell.config.size_m[1] / 2.0 - kWallInset_m;
  const double along = uniform(rng, 0.0, 4.0 * (hx + hy));
  if (along < 2.0 * hx) return {-hx + along, -hy};
  if (along < 2.0 * hx + 2.0 * hy) return {hx, -hy + (along - 2.0 * hx)};
  if (along < 4.0 * hx + 2.0 * hy) return {hx - (along - 2.0 * hx - 2.0 * hy), hy};
  return {-hx, hy - (along - 4.0 * hx - 2.0 * hy)};
}

// Where a path from `from` that passes the base `offset_m` to its side (its nearest point, the
// circle's tangent point: it touches the circle of that radius round the base; negative: the
// other side) meets the far wall.
Eigen::Vector2d across(const CellModel& cell, const Eigen::Vector2d& from, double offset_m) {
  const double distance = from.norm();
  const double radius = std::min(std::abs(offset_m), 0.9 * distance);
  const double turn = std::copysign(std::acos(radius / distance), offset_m);
  const Eigen::Vector2d out = from / distance;
  const Eigen::Vector2d through =
      radius * Eigen::Vector2d(std::cos(turn) * out.x() - std::sin(turn) * out.y(),
                               std::sin(turn) * out.x() + std::cos(turn) * out.y());
  const double hx = cell.config.size_m[0] / 2.0 - kWallInset_m;
  const double hy = cell.config.size_m[1] / 2.0 - kWallInset_m;
  const Eigen::Vector2d heading = (through - from).normalized();
  // Walk on from `through` until a wall is reached.
  double t = std::numeric_limits<double>::infinity();
  if (std::abs(heading.x()) > 1e-9) {
    t = std::min(t, (std::copysign(hx, heading.x()) - through.x()) / heading.x());
  }
  if (std::abs(heading.y()) > 1e-9) {
    t = std::min(t, (std::copysign(hy, heading.y()) - through.y()) / heading.y());
  }
  return through + heading * t;
}

}  // namespace

RobotTask draw_task(const CellModel& cell, const CspaceGrid& grid, std::uint64_t seed,
                    std::size_t index) {
  (void)cell;
  std::mt19937_64 rng = generator(seed, 1, index);
  RobotTask task;
  task.index = index;
  task.program_motion = index % 2 == 0;
  double base = uniform(rng, -1.5, 1.5);
  task.start_rad = inside_grid(grid, working_pose(rng, base));
  for (std::size_t g = 0; g < kGoals; ++g) {
    // Each move swings the base by 0.8 .. 2.4 rad, to the other side where it can.
    const double swing = uniform(rng, 0.8, 2.4);
    base = base > 0.0 ? std::max(-1.5, base - swing) : std::min(1.5, base + swing);
    task.goals_rad.push_back(inside_grid(grid, working_pose(rng, base)));
  }
  return task;
}

ClosedLoopScenario draw_scenario(const CellModel& cell, const CspaceGrid& grid, std::uint64_t seed,
                                 std::size_t index, std::size_t task_pool) {
  std::mt19937_64 rng = generator(seed, 2, index);
  ClosedLoopScenario scenario;
  scenario.index = index;
  scenario.task = draw_task(cell, grid, seed, index % std::max<std::size_t>(1, task_pool));
  PersonVisitPlan& person = scenario.person;
  person.enters_s = uniform(rng, 0.3, 2.5);
  person.speed_m_s = uniform(rng, 0.8, 1.6);
  person.face_m = Eigen::Vector2d::Zero();
  const Eigen::Vector2d from = wall_point(rng, cell);
  const double kind = uniform(rng, 0.0, 1.0);
  // Walk straight at the base, stop `lo`..`hi` m from it (not past where they came in), stand
  // reaching towards it for stand_lo..stand_hi s, and leave to another wall point.
  const auto stand_and_reach = [&](const char* name, double lo, double hi, double stand_lo,
                                   double stand_hi) {
    scenario.kind = name;
    const double distance = std::min(uniform(rng, lo, hi), from.norm());
    const Eigen::Vector2d stop = from.normalized() * distance;
    person.approach_m = {from, stop};
    person.stand_s = uniform(rng, stand_lo, stand_hi);
    person.reach = true;
    person.leave_m = {stop, wall_point(rng, cell)};
  };
  if (kind < 0.4) {
    stand_and_reach("approach", 0.7, 1.3, 0.5, 3.0);
  } else if (kind < 0.75) {
    stand_and_reach("reach", 1.3, 2.2, 1.0, 4.0);
  } else {
    scenario.kind = "cross";
    // Past the robot on either side, not through its base.
    const double side = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    const Eigen::Vector2d to = across(cell, from, side * uniform(rng, 0.8, 1.6));
    person.approach_m = {from, to};
    person.stand_s = 0.0;
    person.leave_m = {to};
  }
  return scenario;
}

}  // namespace safecell
