#include "safecell/closed_loop/closed_loop_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/closed_loop/fence_walk.hpp"

namespace safecell {
namespace {

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
  const InsetRectangle rectangle(cell);
  return rectangle.point(uniform(rng, 0.0, rectangle.perimeter()));
}

double path_length_m(const std::vector<Eigen::Vector2d>& path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

// How a person comes in through one of the cell's entries and goes out through one: from outside
// the fence to the inset rectangle, and back.
struct EntryRoute {
  Eigen::Vector2d outside_in;
  Eigen::Vector2d inside_in;
  Eigen::Vector2d inside_out;
  Eigen::Vector2d outside_out;
};

void append(std::vector<Eigen::Vector2d>& path, const Eigen::Vector2d& point) {
  if (path.empty() || (path.back() - point).norm() > 1e-9) path.push_back(point);
}

EntryRoute entry_route(std::mt19937_64& rng, const CellModel& cell) {
  const std::vector<EntryConfig>& entries = *cell.config.entries;
  const auto pick = [&] {
    return entries[std::uniform_int_distribution<std::size_t>(0, entries.size() - 1)(rng)];
  };
  const EntryConfig in = pick();
  const EntryConfig out = pick();
  const double along_in = uniform(rng, 0.2, 0.8);
  const double along_out = uniform(rng, 0.2, 0.8);
  const Doorway door_in = fence_doorway(cell, in, along_in);
  const Doorway door_out = fence_doorway(cell, out, along_out);
  return {door_in.outside_m, door_in.inside_m, door_out.inside_m, door_out.outside_m};
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
  const InsetRectangle rectangle(cell);
  const double hx = rectangle.hx;
  const double hy = rectangle.hy;
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

// Through the cell's entries (when it names them): the person comes in at one, walks along the
// fence to where the visit's own path begins, arriving there at the time the plan says they
// entered, and after the visit walks along the fence to an entry and out.
void route_through_entries(PersonVisitPlan& person, const CellModel& cell, std::uint64_t seed,
                           std::size_t index) {
  if (!cell.config.entries) return;
  std::mt19937_64 rng = generator(seed, 3, index);
  const EntryRoute route = entry_route(rng, cell);
  const InsetRectangle rectangle(cell);
  std::vector<Eigen::Vector2d> in{route.outside_in, route.inside_in};
  for (const auto& point : rectangle.walk(route.inside_in, person.approach_m.front())) {
    append(in, point);
  }
  person.enters_s -= path_length_m(in) / person.speed_m_s;
  // The visit's own path as drawn (its stop may be where it begins).
  in.insert(in.end(), person.approach_m.begin() + 1, person.approach_m.end());
  person.approach_m = std::move(in);
  for (const auto& point : rectangle.walk(person.leave_m.back(), route.inside_out)) {
    append(person.leave_m, point);
  }
  append(person.leave_m, route.outside_out);
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
  route_through_entries(person, cell, seed, index);
  return scenario;
}

}  // namespace safecell
