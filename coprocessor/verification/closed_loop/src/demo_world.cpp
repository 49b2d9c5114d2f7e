#include "safecell/closed_loop/demo_world.hpp"

#include "safecell/closed_loop/controller_setup.hpp"
#include "safecell/closed_loop/fence_walk.hpp"

#include <algorithm>
#include <cmath>

namespace safecell {
namespace {

constexpr double kWalk_m_s = 1.2;
constexpr double kStand_s = 4.0;  // standing next to the arm, reaching towards it
// Where the person stands: 1.9 m from the base, just outside the arm's sweep (it reaches 1.35 m
// there); reaching out, their hand comes into it.
Eigen::Vector2d stand_at() { return {1.65, -0.9}; }

Eigen::Vector2d corner(const CellModel& cell, double sx, double sy) {
  return {sx * (cell.config.size_m[0] / 2.0 - kFenceInset_m),
          sy * (cell.config.size_m[1] / 2.0 - kFenceInset_m)};
}

PersonVisitPlan demo_visit(const CellModel& cell, double enters_s) {
  PersonVisitPlan plan;
  plan.enters_s = enters_s;
  if (cell.config.entries) {
    // In at the first entry, along the fence the shorter way to the (+x, -y) corner, to where
    // they stand, and back out the same way.
    const Doorway door = fence_doorway(cell, cell.config.entries->front(), 0.5);
    const InsetRectangle fence(cell);
    plan.approach_m = {door.outside_m, door.inside_m};
    for (const auto& point : fence.walk(door.inside_m, corner(cell, 1, -1))) {
      plan.approach_m.push_back(point);
    }
    plan.approach_m.push_back(stand_at());
    plan.leave_m.assign(plan.approach_m.rbegin(), plan.approach_m.rend());
  } else {
    plan.approach_m = {corner(cell, 1, -1), stand_at()};
    plan.leave_m = {stand_at(), corner(cell, 1, 1)};
  }
  plan.speed_m_s = kWalk_m_s;
  plan.stand_s = kStand_s;
  plan.face_m = Eigen::Vector2d::Zero();  // the robot's base
  plan.reach = true;
  return plan;
}

}  // namespace

DemoWorld::DemoWorld(const CellModel& cell, const CspaceGrid& grid, double person_enters_s)
    : start_rad_(inside_grid(grid, {1.2, 0.5, 0.9, 0.0, 0.6, 0.0})),
      goals_rad_{inside_grid(grid, {-1.2, 0.5, 0.9, 0.0, 0.6, 0.0}),
                 inside_grid(grid, {1.2, 0.5, 0.9, 0.0, 0.6, 0.0})},
      person_(demo_visit(cell, person_enters_s)) {}

}  // namespace safecell
