// A bare-metal image of the controller core for a Cortex-M7, to measure it: the default cell's
// grid, the map store and link with static memory, the look-ahead, the watchdog and the safety
// cycle, behind ports that read and write memory-mapped "registers", with session challenges from
// a boot counter. It is linked, never run here: its text/data/bss sizes and the cycle's stack
// depth (from GCC's call graph) are what the bare-metal build reports
// (cmake/ControllerImageReport.cmake). A real target replaces the ports with its robot interface,
// its timer, its Ethernet driver and, where it has one, its hardware random number generator.
// Not in the image: the grid planner (its per-cell arrays, 4.7 MB on the default grid, are the
// host module's; a target runs gross motion with a planner on a partition it can afford).

#include "safecell/base/freestanding_math.hpp"
#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/controller/safety_cycle.hpp"
#include "safecell/controller/watchdog.hpp"

namespace safecell {
namespace {

// The default cell's grid (safecell cell info): 48 x 37 x 21 x 5 cells.
constexpr CellIndex kCells = 186'480;
constexpr MapStoreLayout kLayout = MapStoreLayout::of(kCells);

GridSpec default_grid() {
  GridSpec spec;
  spec.m_max_m = 0.18;
  spec.joint_count = 6;
  constexpr double kDeg = kPi / 180.0;
  const double ranges[6][2] = {{-160, 160}, {-137.5, 137.5}, {-142.5, 142.5},
                               {-240, 240}, {-105, 120},     {-270, 270}};
  const double lever_m[6] = {1.524, 1.371, 0.745, 0.120, 0.119, 0.045};
  for (std::uint32_t j = 0; j < 6; ++j) {
    spec.joints[j] = {ranges[j][0] * kDeg, ranges[j][1] * kDeg, lever_m[j], j < 4};
  }
  return spec;
}

// The map store's memory: zero-initialised (bss), sized at compile time.
StaticMapStoreMemory<kLayout> store_memory;

// Memory-mapped "registers" the ports read and write.
volatile std::uint64_t timer_ns;
volatile double joint_position[kMaxJoints];
volatile double joint_velocity[kMaxJoints];
volatile double speed_override;
volatile std::uint32_t stop_request;
volatile std::uint8_t ethernet_rx[kMaxFrameBytes];
volatile std::uint32_t ethernet_rx_size;
volatile std::uint8_t ethernet_tx[kMaxFrameBytes];
// The boot count in non-volatile memory: the start-up code increments it before the core starts,
// so the session challenges of this boot are ones no earlier boot gave out.
volatile std::uint32_t boot_count;

class TargetClock final : public ClockPort {
 public:
  std::uint64_t now_ns() noexcept override { return timer_ns; }
};

class TargetRobot final : public RobotPort {
 public:
  RobotJoints read() noexcept override {
    RobotJoints joints;
    joints.joint_count = 6;
    for (std::uint32_t j = 0; j < 6; ++j) {
      joints.position_rad[j] = joint_position[j];
      joints.velocity_rad_s[j] = joint_velocity[j];
    }
    joints.read_time_ns = timer_ns;
    return joints;
  }
  void command_speed_scale(double scale) noexcept override { speed_override = scale; }
  bool command_joint_velocity(const double*, std::uint32_t) noexcept override { return false; }
  void stop(StopCategory category) noexcept override {
    stop_request = static_cast<std::uint32_t>(category);
  }
  bool restore_power() noexcept override { return true; }
};

class TargetEthernet final : public LinkPort {
 public:
  bool send(const std::uint8_t* data, std::size_t size) noexcept override {
    for (std::size_t i = 0; i < size && i < kMaxFrameBytes; ++i) ethernet_tx[i] = data[i];
    return true;
  }
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override {
    const std::size_t size = ethernet_rx_size;
    if (size > capacity) return capacity + 1;
    for (std::size_t i = 0; i < size; ++i) buffer[i] = ethernet_rx[i];
    ethernet_rx_size = 0;
    return size;
  }
};

[[noreturn]] void run() {
  const Result<CspaceGrid, GridSpecError> grid = CspaceGrid::create(default_grid());
  if (!grid.ok() || grid.value().cell_count() != kCells) __builtin_trap();
  TargetClock clock;
  TargetRobot robot;
  TargetEthernet ethernet;
  BootCounterEntropy entropy(boot_count);
  MapStore store(kLayout, store_memory.storage());
  ControllerLinkConfig link_config;
  link_config.grid_fingerprint = grid.value().fingerprint();
  ControllerLink link(link_config, ethernet, store, entropy);
  Watchdog watchdog({2'000'000, 6'000'000, 1'000'000});
  SafetyCycleConfig config;
  config.look_ahead.stop.joint_count = 6;
  for (std::uint32_t j = 0; j < 6; ++j) config.look_ahead.stop.joints[j] = {0.01, 5.0};
  SafetyCycle cycle(grid.value(), config, robot, clock, link, store, watchdog);
  const double planned[kMaxJoints] = {0.5, 0.5, 0.5, 0.0, 0.0, 0.0};
  std::uint64_t next = timer_ns;
  for (;;) {
    next += 4'000'000;
    // The idle time: map work in slices until a quarter period before the next cycle.
    (void)cycle.service_link(next - 1'000'000);
    while (timer_ns < next) {
    }
    (void)cycle.run(planned, false);
  }
}

}  // namespace
}  // namespace safecell

// No C runtime start-up: the image is measured, not run.
extern "C" [[noreturn]] void _start() { safecell::run(); }
