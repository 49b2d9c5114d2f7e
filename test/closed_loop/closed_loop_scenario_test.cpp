// The closed-loop validation's scenarios: drawn from (seed, index) alone, of every kind, within
// the stated bounds (speed, where people stop, the side a crossing passes the robot), and the
// person's visit: outside the cell before and after, standing where the plan says, facing the
// robot and reaching towards it.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include "safecell/cell/cell_file.hpp"
#include "safecell/cell/cell_grid.hpp"
#include "safecell/closed_loop/closed_loop_scenario.hpp"

namespace safecell {
namespace {

const CellModel& default_model() {
  static const CellModel model = load_cell_model(load_cell_file_or_default(""));
  return model;
}

const CspaceGrid& default_grid() {
  static const CspaceGrid grid = make_grid(default_model().config);
  return grid;
}

// The distance from the origin (the robot's base) to the segment a..b.
double distance_to_base(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp(-a.dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab).norm();
}

std::string described(const ClosedLoopScenario& s) {
  std::string text = "scenario " + std::to_string(s.index) + " " + s.kind + " speed " +
                     std::to_string(s.person.speed_m_s) + " path";
  for (const Eigen::Vector2d& p : s.person.approach_m) {
    text += " (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
  }
  return text;
}

TEST(ClosedLoopScenario, DrawnFromSeedAndIndexAloneWithinTheStatedBounds) {
  std::map<std::string, int> kinds;
  for (std::size_t index = 0; index < 300; ++index) {
    const ClosedLoopScenario s = draw_scenario(default_model(), default_grid(), 7, index, 8);
    const ClosedLoopScenario again = draw_scenario(default_model(), default_grid(), 7, index, 8);
    ASSERT_EQ(s.person.approach_m, again.person.approach_m) << described(s);
    ASSERT_EQ(s.task.goals_rad, again.task.goals_rad) << described(s);
    ++kinds[s.kind];
    EXPECT_GE(s.person.speed_m_s, 0.8) << described(s);
    EXPECT_LE(s.person.speed_m_s, 1.6) << described(s);
    EXPECT_EQ(s.task.index, index % 8);
    EXPECT_EQ(s.task.program_motion, s.task.index % 2 == 0);
    const Eigen::Vector2d stop = s.person.approach_m.back();
    if (s.kind == "approach") {
      EXPECT_GE(stop.norm(), 0.7 - 1e-9) << described(s);
      EXPECT_LE(stop.norm(), 1.3 + 1e-9) << described(s);
    } else if (s.kind == "reach") {
      EXPECT_GE(stop.norm(), 1.3 - 1e-9) << described(s);
      EXPECT_LE(stop.norm(), 2.2 + 1e-9) << described(s);
    } else {
      ASSERT_EQ(s.kind, "cross");
      const double passes =
          distance_to_base(s.person.approach_m[s.person.approach_m.size() - 2], stop);
      EXPECT_GE(passes, 0.8 - 1e-6) << described(s);
      EXPECT_LE(passes, 1.6 + 1e-6) << described(s);
    }
    for (const auto& goal : s.task.goals_rad) {
      for (std::uint32_t j = 0; j < default_grid().joint_count(); ++j) {
        EXPECT_GT(goal[j], default_grid().joint(j).lo_rad) << described(s);
        EXPECT_LT(goal[j], default_grid().joint(j).hi_rad) << described(s);
      }
    }
  }
  EXPECT_GT(kinds["approach"], 60);
  EXPECT_GT(kinds["reach"], 60);
  EXPECT_GT(kinds["cross"], 40);
  // A different seed gives different scenarios.
  EXPECT_NE(draw_scenario(default_model(), default_grid(), 8, 0, 8).person.approach_m,
            draw_scenario(default_model(), default_grid(), 7, 0, 8).person.approach_m);
}

double length_m(const std::vector<Eigen::Vector2d>& path, std::size_t points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points; ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

bool inside_fence(const Eigen::Vector2d& p) {
  return std::abs(p.x()) <= 1.7 + 1e-9 && std::abs(p.y()) <= 1.7 + 1e-9;
}

TEST(ClosedLoopScenario, PeopleComeInAndGoOutThroughTheDoorWalkingAlongTheFence) {
  const EntryConfig& door = default_model().config.entries.value().front();
  ASSERT_EQ(door.wall, CellWall::kMinusX);
  const auto at_door = [&](const Eigen::Vector2d& p, double x) {
    return std::abs(p.x() - x) < 1e-9 && p.y() >= door.span_m[0] && p.y() <= door.span_m[1];
  };
  for (std::size_t index = 0; index < 200; ++index) {
    const ClosedLoopScenario s = draw_scenario(default_model(), default_grid(), 7, index, 8);
    const auto& in = s.person.approach_m;
    const auto& out = s.person.leave_m;
    ASSERT_GE(in.size(), 3U) << described(s);
    EXPECT_TRUE(at_door(in[0], -2.6)) << described(s);
    EXPECT_TRUE(at_door(in[1], -1.7)) << described(s);
    EXPECT_TRUE(at_door(out.back(), -2.6)) << described(s);
    EXPECT_TRUE(at_door(out[out.size() - 2], -1.7)) << described(s);
    for (std::size_t i = 1; i < in.size(); ++i) EXPECT_TRUE(inside_fence(in[i])) << described(s);
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
      EXPECT_TRUE(inside_fence(out[i])) << described(s);
    }
    // Along the fence: every step of the walk in up to the visit's own path keeps to it.
    for (std::size_t i = 2; i + 1 < in.size(); ++i) {
      const bool on_fence =
          std::abs(std::abs(in[i].x()) - 1.7) < 1e-9 || std::abs(std::abs(in[i].y()) - 1.7) < 1e-9;
      EXPECT_TRUE(on_fence) << described(s);
    }
    // They reach the start of the visit's path at the drawn time, 0.3 .. 2.5 s into the run.
    const double arrives = s.person.enters_s + length_m(in, in.size() - 1) / s.person.speed_m_s;
    EXPECT_GE(arrives, 0.3 - 1e-9) << described(s);
    EXPECT_LE(arrives, 2.5 + 1e-9) << described(s);
  }
}

TEST(ClosedLoopScenario, WithoutEntriesPeopleStepInAtTheWalls) {
  CellModel open = default_model();
  open.config.entries.reset();
  for (std::size_t index = 0; index < 50; ++index) {
    const ClosedLoopScenario s = draw_scenario(open, default_grid(), 7, index, 8);
    ASSERT_EQ(s.person.approach_m.size(), 2U) << described(s);
    const Eigen::Vector2d from = s.person.approach_m.front();
    EXPECT_TRUE(inside_fence(from)) << described(s);
    EXPECT_GE(s.person.enters_s, 0.3) << described(s);
  }
}

TEST(PersonVisit, OutsideBeforeAndAfterStandingFacingTheBaseAndReaching) {
  PersonVisitPlan plan;
  plan.enters_s = 2.0;
  plan.approach_m = {{3.0, 0.0}, {1.0, 0.0}};  // 2 m at 1 m/s
  plan.leave_m = {{1.0, 0.0}, {1.0, 3.0}};     // 3 m
  plan.speed_m_s = 1.0;
  plan.stand_s = 2.0;
  plan.reach = true;
  const PersonVisit visit(plan);
  EXPECT_DOUBLE_EQ(visit.leaves_s(), 2.0 + 2.0 + 2.0 + 3.0);
  EXPECT_FALSE(visit.at(1.9));
  EXPECT_FALSE(visit.at(9.1));
  ASSERT_TRUE(visit.at(3.0));
  EXPECT_NEAR(visit.at(3.0)->position_m.x(), 2.0, 1e-9);
  const HumanPose standing = *visit.at(5.5);  // 1.5 s into standing
  EXPECT_NEAR(standing.position_m.x(), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(standing.heading_rad), std::numbers::pi, 1e-9);  // facing the base
  EXPECT_NEAR(standing.right_arm_reach_rad, std::numbers::pi / 2.0, 1e-9);
  EXPECT_EQ(standing.gait_amplitude, 0.0);
  EXPECT_NEAR(visit.at(7.0)->position_m.y(), 1.0, 1e-9);  // leaving
}

}  // namespace
}  // namespace safecell
