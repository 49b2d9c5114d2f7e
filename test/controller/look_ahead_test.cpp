// The look-ahead against a brute-force check that knows nothing of boxes or levels: it samples
// the continuous path the robot may sweep before it could stop (each joint's reach from the
// relation, all joints at once) and looks up every sample's cell. Whenever the look-ahead lets
// the robot move, no sample may lie in a forbidden cell. Negative control: a look-ahead that
// checks each joint's line of cells alone is caught by the same brute force.

#include "safecell/controller/look_ahead.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "safecell/test/property.hpp"
#include "store_receiver.hpp"

namespace safecell {
namespace {

using test::Words;

CspaceGrid make_grid(std::uint32_t joints, std::mt19937_64& rng, bool with_swept_joint) {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = joints + (with_swept_joint ? 1 : 0);
  for (std::uint32_t j = 0; j < spec.joint_count; ++j) {
    spec.joints[j].lo_rad = -1.0 - 0.5 * static_cast<double>(rng() % 3);
    spec.joints[j].hi_rad = 1.0;
    spec.joints[j].l_m = 0.3 + 0.1 * static_cast<double>(rng() % 5);
    spec.joints[j].discretised = !(with_swept_joint && j == joints / 2);
  }
  return CspaceGrid::create(spec).value();
}

LookAheadConfig config_for(const CspaceGrid& grid) {
  LookAheadConfig config;
  config.control_cycle_s = 0.004;
  config.actuation_s = 0.002;
  config.stop.joint_count = grid.joint_count();
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    config.stop.joints[j] = JointStop{0.01, 8.0 + static_cast<double>(j)};
  }
  return config;
}

// The brute force: the reach of joint j (radians) in the relation's own terms, the distance the
// robot's motion plus a person's approach cover before a stop completes, then the straight path
// from the current joints to all those reaches at once, sampled finely. The first sample in a
// forbidden cell, or none.
struct Sweep {
  bool hits = false;
  JointAngles at;
};
Sweep sweep(const CspaceGrid& grid, const MapView& map, const LookAheadConfig& config,
            const JointAngles& from, const double* speed_rad_s, double map_age_s) {
  const double reaction_s =
      map_age_s + config.sensor_period_s + config.control_cycle_s + config.actuation_s;
  double reach[kMaxJoints] = {};
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    if (!grid.joint(j).discretised || speed_rad_s[j] == 0.0) continue;
    const double speed = std::abs(speed_rad_s[j]);
    const double l = grid.joint(j).l_m;
    const double t = reaction_s + config.stop.stop_time_s(j, speed);
    reach[j] = std::copysign((speed + config.human_speed_m_s / l) * t, speed_rad_s[j]);
  }
  Sweep result;
  constexpr int kSamples = 4000;
  for (int s = 0; s <= kSamples; ++s) {
    JointAngles q = from;
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      q.rad[j] += reach[j] * s / kSamples;
      const JointSpec& spec = grid.joint(j);
      q.rad[j] = std::fmin(std::fmax(q.rad[j], spec.lo_rad), spec.hi_rad);  // joint limits
    }
    const CellIndex cell = grid.cell_containing(q).value();
    if (map.forbidden(cell)) return {true, q};
  }
  return result;
}

// The broken variant: each moving joint's line of cells on its own, as far as the look-ahead's
// box reaches along it.
bool lines_alone_free(const CspaceGrid& grid, const MapView& map, const LookAheadResult& box,
                      const JointAngles& from, const double* speed_rad_s) {
  const GridCoords current = grid.coords_containing(from).value();
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    for (std::uint32_t k = 1; k <= box.box_cells[j] && speed_rad_s[j] != 0.0; ++k) {
      GridCoords c = current;
      if (speed_rad_s[j] > 0 ? c.along[j] + k >= grid.cells_along(j) : k > c.along[j]) break;
      c.along[j] = speed_rad_s[j] > 0 ? c.along[j] + k : c.along[j] - k;
      if (map.forbidden(grid.index_of(c).value())) return false;
    }
  }
  return true;
}

std::string describe(const CspaceGrid& grid, const JointAngles& q, const double* v, double age) {
  std::ostringstream out;
  out << "joints " << grid.joint_count() << ", cells " << grid.cell_count() << ", q = (";
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) out << (j ? ", " : "") << q.rad[j];
  out << "), v = (";
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) out << (j ? ", " : "") << v[j];
  out << "), map age " << age;
  return out.str();
}

TEST(LookAhead, AFreeMapAllowsFullSpeedAndAForbiddenCellHereStops) {
  std::mt19937_64 rng(1);
  const CspaceGrid grid = make_grid(3, rng, false);
  StoreReceiver store(grid.cell_count(), 64);
  Words map(cell_bits::words_for(grid.cell_count()), 0);
  hold(store, map, grid.cell_count());
  const LookAhead look_ahead(grid, config_for(grid));
  MotionState motion;
  motion.planned_rad_s[0] = 0.3;
  motion.velocity_rad_s[0] = 0.3;
  LookAheadResult result = look_ahead.check(store.store().view(), motion, 0.05);
  EXPECT_EQ(result.reason, LookAheadReason::kClear);
  EXPECT_EQ(result.speed_scale, 1.0);

  cell_bits::set(map.data(), grid.cell_containing(motion.position).value());
  StoreReceiver blocked(grid.cell_count(), 64);
  hold(blocked, map, grid.cell_count());
  result = look_ahead.check(blocked.store().view(), motion, 0.05);
  EXPECT_TRUE(result.stop());
  EXPECT_EQ(result.reason, LookAheadReason::kCurrentCellForbidden);
  EXPECT_EQ(result.blocking_cell, grid.cell_containing(motion.position).value());
}

// Forbidden cells two cells ahead along joint 2 slow the robot that moves joint 2: the result
// names joint 2 (planned fast) as the joint that decides the speed and as the one of least slack.
TEST(LookAhead, NamesTheJointThatLimitsTheSpeed) {
  std::mt19937_64 rng(1);
  const CspaceGrid grid = make_grid(3, rng, false);
  MotionState motion;
  motion.planned_rad_s[1] = 8.0;
  motion.velocity_rad_s[1] = 0.05;
  const GridCoords here = grid.coords_containing(motion.position).value();
  Words map(cell_bits::words_for(grid.cell_count()), 0);
  for (CellIndex c = 0; c < grid.cell_count(); ++c) {
    if (grid.coords_of(c).value().along[1] == here.along[1] + 4) cell_bits::set(map.data(), c);
  }
  StoreReceiver store(grid.cell_count(), 64);
  hold(store, map, grid.cell_count());
  const LookAheadResult result =
      LookAhead(grid, config_for(grid)).check(store.store().view(), motion, 0.05);
  ASSERT_EQ(result.reason, LookAheadReason::kFreeDistanceShrinking) << to_string(result.reason);
  EXPECT_LT(result.speed_scale, 1.0);
  EXPECT_EQ(result.critical_joint, 1);
  EXPECT_EQ(result.least_slack_joint, 1);
  EXPECT_GT(result.slack_s, 0.0);
}

TEST(LookAhead, RefusesNonsenseInput) {
  std::mt19937_64 rng(2);
  const CspaceGrid grid = make_grid(2, rng, false);
  StoreReceiver store(grid.cell_count(), 64);
  hold(store, Words(cell_bits::words_for(grid.cell_count()), 0), grid.cell_count());
  const LookAhead look_ahead(grid, config_for(grid));
  MotionState motion;
  EXPECT_EQ(look_ahead.check(store.store().view(), motion, NAN).reason,
            LookAheadReason::kInvalidInput);
  EXPECT_EQ(look_ahead.check(store.store().view(), motion, -1.0).reason,
            LookAheadReason::kInvalidInput);
  motion.velocity_rad_s[1] = INFINITY;
  EXPECT_EQ(look_ahead.check(store.store().view(), motion, 0.0).reason,
            LookAheadReason::kInvalidInput);
  motion.velocity_rad_s[1] = 0.0;
  motion.position.rad[0] = 5.0;
  const LookAheadResult outside = look_ahead.check(store.store().view(), motion, 0.0);
  EXPECT_EQ(outside.reason, LookAheadReason::kOutsideGrid);
  EXPECT_TRUE(outside.stop());
}

// Two joints moving together towards a cell that lies on neither joint's own line.
TEST(LookAhead, SeesTheDiagonalCellThatLinesAloneMiss) {
  std::mt19937_64 rng(3);
  const CspaceGrid grid = make_grid(2, rng, false);
  MotionState motion;
  motion.planned_rad_s[0] = motion.velocity_rad_s[0] = 0.5;
  motion.planned_rad_s[1] = motion.velocity_rad_s[1] = 0.5;
  GridCoords diagonal = grid.coords_containing(motion.position).value();
  ++diagonal.along[0];
  ++diagonal.along[1];
  Words map(cell_bits::words_for(grid.cell_count()), 0);
  cell_bits::set(map.data(), grid.index_of(diagonal).value());
  StoreReceiver store(grid.cell_count(), 64);
  hold(store, map, grid.cell_count());
  const LookAhead look_ahead(grid, config_for(grid));
  const LookAheadResult result = look_ahead.check(store.store().view(), motion, 0.05);
  EXPECT_TRUE(result.stop()) << to_string(result.reason);
  EXPECT_TRUE(result.has_blocking_cell);
  EXPECT_EQ(result.blocking_cell, grid.index_of(diagonal).value());
  EXPECT_TRUE(
      lines_alone_free(grid, store.store().view(), result, motion.position, motion.velocity_rad_s))
      << "the negative control should miss it";
  EXPECT_TRUE(sweep(grid, store.store().view(), look_ahead.config(), motion.position,
                    motion.velocity_rad_s, 0.05)
                  .hits);
}

TEST(LookAhead, NeverLetsTheRobotSweepIntoAForbiddenCell) {
  test::PropertyRun run(300);
  int allowed = 0;
  int slowed = 0;
  int lines_alone_missed = 0;
  for (int i = 0; i < run.iterations(); ++i) {
    auto& rng = run.rng();
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const CspaceGrid grid =
        make_grid(2 + static_cast<std::uint32_t>(rng() % 3), rng, rng() % 3 == 0);
    Words map(cell_bits::words_for(grid.cell_count()), 0);
    const double density = 0.002 + 0.05 * unit(rng);
    for (CellIndex c = 0; c < grid.cell_count(); ++c) {
      if (unit(rng) < density) cell_bits::set(map.data(), c);
    }
    StoreReceiver store(grid.cell_count(), store_blocks_for(grid.cell_count()) * 2);
    hold(store, map, grid.cell_count());
    LookAheadConfig config = config_for(grid);
    config.max_cells = 4 + static_cast<std::uint32_t>(rng() % 20);
    const LookAhead look_ahead(grid, config);
    MotionState motion;
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      const JointSpec& spec = grid.joint(j);
      motion.position.rad[j] = spec.lo_rad + (spec.hi_rad - spec.lo_rad) * unit(rng);
      const double planned = rng() % 3 == 0 ? 0.0 : (unit(rng) - 0.5) * 2.0;
      motion.planned_rad_s[j] = planned;
      motion.velocity_rad_s[j] = planned * unit(rng);  // somewhere on the way to planned speed
    }
    const double age = 0.2 * unit(rng);
    const MapView view = store.store().view();
    const LookAheadResult result = look_ahead.check(view, motion, age);
    const std::string input = describe(grid, motion.position, motion.velocity_rad_s, age) +
                              ", max cells " + std::to_string(config.max_cells) + ": " +
                              to_string(result.reason);
    if (!result.stop() || result.reason == LookAheadReason::kNoFreeDistance) {
      // It lets the robot go on this cycle: the measured speed must be stoppable in time.
      const Sweep measured = sweep(grid, view, config, motion.position, motion.velocity_rad_s, age);
      ASSERT_FALSE(measured.hits) << input;
    }
    if (!result.stop()) {
      ++allowed;
      slowed += result.speed_scale < 1.0 ? 1 : 0;
      double commanded[kMaxJoints] = {};
      for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
        commanded[j] = motion.planned_rad_s[j] * result.speed_scale;
      }
      const Sweep at_scale = sweep(grid, view, config, motion.position, commanded, age);
      ASSERT_FALSE(at_scale.hits) << input << ", scale " << result.speed_scale;
    }
    // The negative control: let the robot move whenever its lines alone are free.
    LookAheadResult lines_box = result;
    for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
      lines_box.box_cells[j] = result.needed_cells[j] < 1000 ? result.needed_cells[j] : 0;
    }
    if (result.reason != LookAheadReason::kCurrentCellForbidden &&
        result.reason != LookAheadReason::kOutsideGrid &&
        lines_alone_free(grid, view, lines_box, motion.position, motion.velocity_rad_s) &&
        sweep(grid, view, config, motion.position, motion.velocity_rad_s, age).hits) {
      ++lines_alone_missed;
    }
  }
  // Slowing down comes up about 8 times in 300 draws, none about once in 2,500 runs (seed 8787):
  // NamesTheJointThatLimitsTheSpeed makes it happen instead of hoping for it here.
  if (run.full_length()) {
    EXPECT_GT(allowed, run.iterations() / 10) << "too few cases where the robot may move";
    EXPECT_GT(lines_alone_missed, 0) << "the negative control was never caught";
  }
  std::printf("look-ahead: %d of %d allowed motion (%d slowed); lines alone missed %d\n", allowed,
              run.iterations(), slowed, lines_alone_missed);
}

}  // namespace
}  // namespace safecell
