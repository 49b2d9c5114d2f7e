#pragma once
// A safety cycle on the simulated robot, wired as the controller module wires it: the map store
// with the default pool, the link, a watchdog for a 4 ms cycle, the stop model measured from the
// robot. The test brings the grid, the robot, the cycle's configuration and the link's port.

#include <cstdint>

#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/controller/host/simulated_robot.hpp"
#include "safecell/controller/safety_cycle.hpp"
#include "safecell/controller/watchdog.hpp"

namespace safecell::test {

struct CycleRig {
  CycleRig(const CspaceGrid& grid, const SimulatedRobotConfig& robot_config,
           const SafetyCycleConfig& config, LinkPort& port, std::uint64_t lut_fingerprint)
      : robot(robot_config),
        clock(robot),
        store(MapStoreLayout::of(grid.cell_count())),
        link(link_config(grid, lut_fingerprint), port, store.store(), entropy),
        watchdog({3'000'000, 5'000'000, 2'000'000}),
        cycle(grid, with_stop_model(config, robot_config), robot, clock, link, store.store(),
              watchdog) {
    robot.set_time_ns(1'000'000'000);
  }

  static ControllerLinkConfig link_config(const CspaceGrid& grid, std::uint64_t lut_fingerprint) {
    ControllerLinkConfig config;
    config.grid_fingerprint = grid.fingerprint();
    config.lut_fingerprint = lut_fingerprint;
    return config;
  }
  static SafetyCycleConfig with_stop_model(SafetyCycleConfig config,
                                           const SimulatedRobotConfig& robot_config) {
    config.look_ahead.stop = SimulatedRobot::measure_stop_model(robot_config);
    return config;
  }

  SimulatedRobot robot;
  SimulatedClock clock;
  HostMapStore store;
  BootCounterEntropy entropy{1};
  ControllerLink link;
  Watchdog watchdog;
  SafetyCycle cycle;
};

}  // namespace safecell::test
