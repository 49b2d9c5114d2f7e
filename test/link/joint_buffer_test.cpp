// The smart buffer against analytic trajectories: the joints it returns at any exposure time lie
// within its error bound of the true motion, between samples and ahead of the last one.

#include "safecell/link/joint_buffer.hpp"
#include "safecell/link/robot_pose_at_exposure.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "safecell/cell/cell_grid.hpp"
#include "safecell/cell/cell_model.hpp"
#include "safecell/cell/default_cell.hpp"
#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr std::uint64_t kMs = 1'000'000;

// q(t) = A sin(w t + phase): |q''| <= A w^2.
struct Sine {
  double amplitude, omega, phase;
  double q(double t) const { return amplitude * std::sin(omega * t + phase); }
  double v(double t) const { return amplitude * omega * std::cos(omega * t + phase); }
  double a_max() const { return amplitude * omega * omega; }
};

TEST(JointBuffer, InterpolatedAndExtrapolatedJointsAreWithinTheirBound) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<Sine> joints;
    JointBufferLimits limits;
    for (int j = 0; j < 6; ++j) {
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      const Sine sine{0.2 + 1.5 * unit(run.rng()), 0.5 + 6.0 * unit(run.rng()),
                      6.28 * unit(run.rng())};
      joints.push_back(sine);
      limits.max_acceleration_rad_s2.push_back(sine.a_max());
    }
    JointBuffer buffer(limits);
    // Samples every 4 ms +- 1 ms, stamped with a clock error of up to 100 us (within u).
    const std::uint64_t u = 100'000;
    const auto stamp_error =
        static_cast<std::int64_t>(run.rng()() % (2 * u + 1)) - static_cast<std::int64_t>(u);
    std::uint64_t t = 1'000 * kMs;
    for (int s = 0; s < 100; ++s) {
      std::vector<double> q, v;
      for (const Sine& joint : joints) {
        q.push_back(joint.q(static_cast<double>(t) * 1e-9));
        v.push_back(joint.v(static_cast<double>(t) * 1e-9));
      }
      ASSERT_TRUE(buffer.add(static_cast<std::uint64_t>(static_cast<std::int64_t>(t) + stamp_error),
                             u, q, v));
      t += 3 * kMs + run.rng()() % (2 * kMs);
    }
    // Exposures between the 10th sample and 15 ms past the last.
    for (int e = 0; e < 200; ++e) {
      const std::uint64_t exposure = 1'040 * kMs + run.rng()() % (t - 1'040 * kMs + 10 * kMs);
      const JointsAtTime at = buffer.at(exposure);
      ASSERT_TRUE(at.known) << at.unknown_because << " at " << exposure;
      for (std::size_t j = 0; j < joints.size(); ++j) {
        const double truth = joints[j].q(static_cast<double>(exposure) * 1e-9);
        ASSERT_LE(std::abs(at.position_rad[j] - truth), at.error_rad[j] + 1e-12)
            << "joint " << j << " (A " << joints[j].amplitude << ", w " << joints[j].omega
            << "), exposure " << exposure << ", stamp error " << stamp_error << " ns";
      }
    }
  }
}

TEST(JointBuffer, StaleOrFarAheadMeansUnknown) {
  JointBufferLimits limits;
  limits.max_acceleration_rad_s2 = {1.0};
  limits.max_extrapolation_ns = 20 * kMs;
  limits.max_sample_age_ns = 50 * kMs;
  JointBuffer buffer(limits);
  EXPECT_FALSE(buffer.at(0).known);  // nothing yet
  ASSERT_TRUE(buffer.add(100 * kMs, 0, {0.0}, {1.0}));
  ASSERT_TRUE(buffer.add(104 * kMs, 0, {0.004}, {1.0}));
  EXPECT_FALSE(buffer.add(104 * kMs, 0, {0.0}, {0.0})) << "not newer: ignored";
  EXPECT_TRUE(buffer.at(120 * kMs).known);
  EXPECT_FALSE(buffer.at(125 * kMs).known) << "21 ms past the last sample";
  EXPECT_FALSE(buffer.at(99 * kMs).known) << "before every sample";
  EXPECT_NEAR(buffer.at(102 * kMs).position_rad[0], 0.002, 1e-12);
}

TEST(JointBuffer, RefusesMeaninglessLimitsAndSamples) {
  EXPECT_THROW(JointBuffer(JointBufferLimits{}), std::invalid_argument);
  JointBufferLimits limits;
  limits.max_acceleration_rad_s2 = {1.0, -1.0};
  EXPECT_THROW(JointBuffer{limits}, std::invalid_argument);
  limits.max_acceleration_rad_s2 = {1.0, 1.0};
  JointBuffer buffer(limits);
  EXPECT_THROW((void)buffer.add(1, 0, {0.0}, {0.0}), std::invalid_argument);
}

// The pose for removal: known while its error fits the timing allowance, unknown (and the cycle
// stops) when it does not, or when the joints are stale.
TEST(RobotPoseAtExposure, UsableOnlyWithinTheRemovalsTimingAllowance) {
  const CspaceGrid grid = make_grid(load_cell_model(default_cell()).config);
  JointBufferLimits limits;
  limits.max_acceleration_rad_s2.assign(grid.joint_count(), 5.0);
  JointBuffer buffer(limits);
  const std::vector<double> still(grid.joint_count(), 0.1);
  const std::vector<double> moving(grid.joint_count(), 1.0);
  ASSERT_TRUE(buffer.add(100 * kMs, 100'000, still, moving));
  ASSERT_TRUE(buffer.add(104 * kMs, 100'000, still, moving));
  const RobotPoseAtExposure close = robot_pose_at_exposure(buffer, 104 * kMs, grid, 0.05);
  ASSERT_TRUE(close.known) << close.unknown_because;
  EXPECT_GT(close.error_m, 0.0);
  // 15 ms ahead: the extrapolation's error grows past a 1 mm allowance.
  const RobotPoseAtExposure ahead = robot_pose_at_exposure(buffer, 119 * kMs, grid, 0.001);
  EXPECT_FALSE(ahead.known);
  EXPECT_NE(ahead.unknown_because.find("over the removal's timing allowance"), std::string::npos)
      << ahead.unknown_because;
  EXPECT_FALSE(robot_pose_at_exposure(buffer, 400 * kMs, grid, 1.0).known);  // stale joints
}

}  // namespace
}  // namespace safecell
