#include "safecell/sim/human_walker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr double kPi = std::numbers::pi;

void expect_at(const HumanPose& pose, double x_m, double y_m, double heading_rad) {
  EXPECT_NEAR(pose.position_m.x(), x_m, 1e-12);
  EXPECT_NEAR(pose.position_m.y(), y_m, 1e-12);
  EXPECT_NEAR(pose.heading_rad, heading_rad, 1e-12);
}

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(HumanWalker, WalksAnLShapedPathByHand) {
  // 3 m along +x, then 4 m along +y, at the default 1.6 m/s: 7 m in 4.375 s.
  const HumanWalker walker({{0.0, 0.0}, {3.0, 0.0}, {3.0, 4.0}});
  EXPECT_DOUBLE_EQ(walker.path_length_m(), 7.0);
  EXPECT_DOUBLE_EQ(walker.arrival_time_s(), 4.375);
  expect_at(walker.pose_at(0.0), 0.0, 0.0, 0.0);
  expect_at(walker.pose_at(1.0), 1.6, 0.0, 0.0);        // 1.6 m along the first segment
  expect_at(walker.pose_at(2.5), 3.0, 1.0, kPi / 2.0);  // 4.0 m: 1.0 m into the second
  expect_at(walker.pose_at(4.0), 3.0, 3.4, kPi / 2.0);  // 6.4 m
  EXPECT_DOUBLE_EQ(walker.pose_at(2.5).gait_amplitude, 1.0);
}

TEST(HumanWalker, WalksADiagonalByHand) {
  // A 3-4-5 segment at 1 m/s: after 2 s, 2/5 of the way; heading atan2(4, 3).
  const HumanWalker walker({{1.0, 1.0}, {4.0, 5.0}}, 1.0);
  expect_at(walker.pose_at(2.0), 2.2, 2.6, 0.9272952180016122);
}

TEST(HumanWalker, SwingsAtOnePointEightStepsPerSecond) {
  const HumanWalker walker({{0.0, 0.0}, {100.0, 0.0}});
  // Half a gait cycle (pi) per step: 0.5 s is 0.9 steps = 0.9 pi = 2.827433388230814 rad;
  // 1 s is 1.8 pi, and 1.5 s is 2.7 pi, wrapped to 0.7 pi = 2.199114857512855 rad.
  EXPECT_NEAR(walker.pose_at(0.5).gait_phase_rad, 2.827433388230814, 1e-12);
  EXPECT_NEAR(walker.pose_at(1.0).gait_phase_rad, 5.654866776461628, 1e-12);
  EXPECT_NEAR(walker.pose_at(1.5).gait_phase_rad, 2.199114857512855, 1e-12);
}

TEST(HumanWalker, StandsStillAtTheLastWaypoint) {
  const HumanWalker walker({{0.0, 0.0}, {3.0, 0.0}, {3.0, 4.0}}, 1.6, 0.5);
  for (const double time_s : {4.375, 5.0, 1000.0, std::numeric_limits<double>::infinity()}) {
    const HumanPose pose = walker.pose_at(time_s);
    expect_at(pose, 3.0, 4.0, kPi / 2.0);
    EXPECT_EQ(pose.gait_amplitude, 0.0) << time_s;
    EXPECT_EQ(pose.arm_raise_rad, 0.5) << time_s;
  }
}

TEST(HumanWalker, SkipsRepeatedWaypointsAndStandsOnASingleOne) {
  const HumanWalker repeated({{0.0, 0.0}, {0.0, 0.0}, {0.0, 2.0}, {0.0, 2.0}}, 1.0);
  expect_at(repeated.pose_at(0.0), 0.0, 0.0, kPi / 2.0);
  expect_at(repeated.pose_at(1.0), 0.0, 1.0, kPi / 2.0);
  expect_at(repeated.pose_at(3.0), 0.0, 2.0, kPi / 2.0);

  const HumanWalker single({{1.5, -2.0}});
  EXPECT_EQ(single.arrival_time_s(), 0.0);
  expect_at(single.pose_at(0.0), 1.5, -2.0, 0.0);
  EXPECT_EQ(single.pose_at(0.0).gait_amplitude, 0.0);
}

TEST(HumanWalker, TimesBeforeTheStartGiveTheStart) {
  const HumanWalker walker({{1.0, 1.0}, {2.0, 1.0}});
  expect_at(walker.pose_at(-3.0), 1.0, 1.0, 0.0);
  EXPECT_EQ(walker.pose_at(-3.0).gait_phase_rad, 0.0);
}

TEST(HumanWalker, InvalidParametersAreNamedWithTheirValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto walker_error = [](std::vector<Eigen::Vector2d> waypoints, double speed_m_s,
                               double arm_raise_rad = 0.0) {
    return error_of([&] { static_cast<void>(HumanWalker(waypoints, speed_m_s, arm_raise_rad)); });
  };
  EXPECT_EQ(walker_error({}, 1.0), "HumanWalker: waypoints_m: none given, expected at least one");
  EXPECT_EQ(walker_error({{0.0, 0.0}, {nan, 1.0}}, 1.0),
            "HumanWalker: waypoints_m[1]: value (nan, 1), expected finite coordinates");
  EXPECT_EQ(walker_error({{0.0, -inf}}, 1.0),
            "HumanWalker: waypoints_m[0]: value (0, -inf), expected finite coordinates");
  for (const auto& [speed_m_s, text] :
       {std::pair{0.0, "0"}, std::pair{-1.0, "-1"}, std::pair{3.5, "3.5"}, std::pair{nan, "nan"},
        std::pair{inf, "inf"}}) {
    EXPECT_EQ(walker_error({{0.0, 0.0}}, speed_m_s), std::string("HumanWalker: speed_m_s: value ") +
                                                         text +
                                                         ", expected above 0 and at most 3 m/s");
  }
  EXPECT_EQ(walker_error({{0.0, 0.0}}, 1.0, nan),
            "HumanWalker: arm_raise_rad: value nan, expected a finite angle");
  EXPECT_EQ(walker_error({{0.0, 0.0}}, 3.0), "(no error)");  // the limit itself is allowed
  EXPECT_EQ(error_of([nan] {
              static_cast<void>(HumanWalker({{0.0, 0.0}}).pose_at(nan));
            }),
            "HumanWalker::pose_at: time_s is NaN");
}

// The walked distance v t, marched off segment by segment.
Eigen::Vector2d marched(const std::vector<Eigen::Vector2d>& waypoints, double distance_m) {
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const Eigen::Vector2d step = waypoints[i] - waypoints[i - 1];
    if (distance_m < step.norm()) return waypoints[i - 1] + step.normalized() * distance_m;
    distance_m -= step.norm();
  }
  return waypoints.back();
}

TEST(HumanWalker, PelvisIsOnThePathAtDistanceSpeedTimesTime) {
  test::PropertyRun run(200);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0), speed(0.1, 3.0), share(0.0, 1.2);
  for (int i = 0; i < run.iterations(); ++i) {
    std::vector<Eigen::Vector2d> waypoints(1 + run.rng()() % 6);
    for (auto& point : waypoints) point = {coordinate(run.rng()), coordinate(run.rng())};
    const double speed_m_s = speed(run.rng());
    const HumanWalker walker(waypoints, speed_m_s);
    for (int k = 0; k < 20; ++k) {
      const double time_s = share(run.rng()) * walker.arrival_time_s();
      const Eigen::Vector2d expected = marched(waypoints, speed_m_s * time_s);
      const HumanPose pose = walker.pose_at(time_s);
      ASSERT_NEAR((pose.position_m - expected).norm(), 0.0, 1e-9)
          << "iteration " << i << " time " << time_s;
      // Walking, the figure faces along its segment: a small step ahead lies straight ahead.
      if (time_s < walker.arrival_time_s()) {
        const Eigen::Vector2d ahead = marched(waypoints, speed_m_s * time_s + 1e-7);
        const Eigen::Vector2d facing(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
        if ((ahead - expected).norm() > 0.5e-7) {
          ASSERT_NEAR((ahead - expected).normalized().dot(facing), 1.0, 1e-6)
              << "iteration " << i << " time " << time_s;
        }
      }
    }
  }
}

}  // namespace
}  // namespace safecell
