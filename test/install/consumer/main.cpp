// An integrator's controller: the installed core with the integrator's own ports. Without a
// coprocessor the robot must be held (no session, no map): the program exits 0 only if it is.

#include <cstdio>

#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/controller/safety_cycle.hpp"

namespace {

using namespace safecell;

class StillRobot final : public RobotPort {
 public:
  RobotJoints read() noexcept override {
    RobotJoints joints;
    joints.joint_count = 2;
    return joints;
  }
  void command_speed_scale(double) noexcept override {}
  bool command_joint_velocity(const double*, std::uint32_t) noexcept override { return true; }
  void stop(StopCategory) noexcept override { ++stops; }
  bool restore_power() noexcept override { return true; }
  int stops = 0;
};

class StepClock final : public ClockPort {
 public:
  std::uint64_t now_ns() noexcept override { return now; }
  std::uint64_t now = 1'000'000'000;
};

class SilentLink final : public LinkPort {
 public:
  bool send(const std::uint8_t*, std::size_t) noexcept override { return true; }
  std::size_t receive(std::uint8_t*, std::size_t) noexcept override { return 0; }
};

GridSpec grid_spec() {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = 2;
  for (std::uint32_t j = 0; j < 2; ++j) spec.joints[j] = {-1.0, 1.0, 0.5, true};
  return spec;
}

constexpr MapStoreLayout kLayout = MapStoreLayout::of(4096);
StaticMapStoreMemory<kLayout> store_memory;

}  // namespace

int main() {
  const CspaceGrid grid = CspaceGrid::create(grid_spec()).value();
  if (grid.cell_count() > kLayout.cell_count) return 3;
  const MapStoreLayout layout = MapStoreLayout::of(grid.cell_count());
  MapStore store(layout, store_memory.storage());
  StillRobot robot;
  StepClock clock;
  SilentLink port;
  ControllerLinkConfig link_config;
  link_config.grid_fingerprint = grid.fingerprint();
  BootCounterEntropy entropy(1);
  ControllerLink link(link_config, port, store, entropy);
  Watchdog watchdog({2'000'000, 6'000'000, 1'000'000'000});
  SafetyCycleConfig config;
  config.look_ahead.stop.joint_count = 2;
  for (std::uint32_t j = 0; j < 2; ++j) config.look_ahead.stop.joints[j] = {0.01, 5.0};
  SafetyCycle cycle(grid, config, robot, clock, link, store, watchdog);
  const double planned[kMaxJoints] = {0.5, 0.5};
  CycleState state = CycleState::kMoving;
  for (int i = 0; i < 10; ++i) {
    clock.now += 4'000'000;  // a 4 ms cycle
    state = cycle.run(planned, true).state;
  }
  std::printf("after 10 cycles without a coprocessor: %s, %d stop commands\n", to_string(state),
              robot.stops);
  return state == CycleState::kWaiting && robot.stops > 0 ? 0 : 1;
}
