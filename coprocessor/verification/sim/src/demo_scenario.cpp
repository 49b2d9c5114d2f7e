#include "safecell/sim/demo_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace safecell {

std::vector<double> demo_robot_at(const CspaceGrid& grid, double time_s) {
  struct Swing {
    double middle_rad, amplitude_rad, period_s;
  };
  constexpr Swing kSwings[] = {{0.0, 1.0, 10.0}, {0.2, 0.4, 7.0}, {0.9, 0.5, 5.0},
                               {0.0, 0.8, 9.0},  {0.6, 0.4, 4.0}, {0.0, 1.0, 6.0}};
  std::vector<double> q(grid.joint_count());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    const Swing swing = j < std::size(kSwings) ? kSwings[j] : Swing{0.0, 0.0, 1.0};
    const double value = swing.middle_rad + swing.amplitude_rad * std::sin(2.0 * std::numbers::pi *
                                                                           time_s / swing.period_s);
    const JointSpec& joint = grid.joint(j);
    const double margin = 1e-6 * (joint.hi_rad - joint.lo_rad);
    q[j] = std::clamp(value, joint.lo_rad + margin, joint.hi_rad - margin);
  }
  return q;
}

HumanWalker demo_person(const CellModel& cell) {
  const double x = cell.config.size_m[0] / 2.0 - 0.3;
  const double y = cell.config.size_m[1] / 2.0 - 0.3;
  return HumanWalker({{x, -y}, {0.9, -0.5}, {0.9, 0.5}, {x, y}}, kDemoHumanSpeed_m_s, 0.3);
}

SimScene demo_scene(const CspaceGrid& grid, const HumanWalker& person, double time_s) {
  SimScene scene{demo_robot_at(grid, time_s), {}};
  if (time_s >= kDemoHumanEnters_s && time_s - kDemoHumanEnters_s <= person.arrival_time_s()) {
    scene.humans.push_back(person.pose_at(time_s - kDemoHumanEnters_s));
  }
  return scene;
}

}  // namespace safecell
