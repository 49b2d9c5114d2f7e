// The controller's cycle allocates nothing after init: this executable replaces the global
// operator new (every form the program can reach) with one that counts while a cycle runs. The
// cycles under count take map updates (keyframes and deltas), plan and re-plan paths, slow down
// and stop, so every path of the cycle that the closed loop uses is covered. Negative control: an
// allocation made on purpose inside a counted stretch is seen.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "cycle_rig.hpp"
#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/gross_motion.hpp"
#include "safecell/controller/host/planner_memory.hpp"
#include "scripted_coprocessor.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<long> allocations{0};

void* allocate(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  void* memory = std::malloc(size == 0 ? 1 : size);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* memory) noexcept { std::free(memory); }
void operator delete[](void* memory) noexcept { std::free(memory); }
void operator delete(void* memory, std::size_t) noexcept { std::free(memory); }
void operator delete[](void* memory, std::size_t) noexcept { std::free(memory); }

namespace safecell {
namespace {

constexpr std::uint64_t kLuts = 0x1075;

// Frames built before the count starts, handed out when due; sends are only counted.
class PreloadedPort final : public LinkPort {
 public:
  bool send(const std::uint8_t*, std::size_t) noexcept override {
    ++sent;
    return true;
  }
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override {
    if (next >= frames.size() || due[next] > now) return 0;
    const test::Bytes& frame = frames[next++];
    if (frame.size() > capacity) return capacity + 1;
    for (std::size_t i = 0; i < frame.size(); ++i) buffer[i] = frame[i];
    return frame.size();
  }
  std::vector<test::Bytes> frames;
  std::vector<std::uint64_t> due;
  std::size_t next = 0;
  std::uint64_t now = 0;
  long sent = 0;
};

TEST(ControllerCycle, AllocatesNothingAfterInit) {
  GridSpec spec;
  spec.m_max_m = 0.1;
  spec.joint_count = 3;
  for (std::uint32_t j = 0; j < 3; ++j) spec.joints[j] = {-2.0, 2.0, 0.5, true};
  const CspaceGrid grid = CspaceGrid::create(spec).value();
  const CellIndex cells = grid.cell_count();
  SimulatedRobotConfig robot_config;
  robot_config.joint_count = 3;
  for (std::uint32_t j = 0; j < 3; ++j) robot_config.joints[j] = {-2.0, 2.0, 1.0, 3.0, 3.0};
  robot_config.start_rad[0] = -1.8;
  PreloadedPort port;
  test::CycleRig rig(grid, robot_config, SafetyCycleConfig{}, port, kLuts);
  SimulatedRobot& robot = rig.robot;
  SafetyCycle& cycle = rig.cycle;
  const PlannerLayout layout = PlannerLayout::for_grid(cells);
  PlannerMemoryHost planner_memory(layout);
  GridPlanner planner(grid, layout, planner_memory.memory());
  GrossMotionConfig motion_config;
  for (std::uint32_t j = 0; j < 3; ++j) {
    motion_config.max_speed_rad_s[j] = 1.0;
    motion_config.accel_rad_s2[j] = 3.0;
  }
  GrossMotion motion(grid, planner, motion_config);
  JointAngles goal;
  goal.rad[0] = 1.8;
  ASSERT_EQ(motion.move_to(goal), Status::kOk);

  // A handshake, then a map every 33 ms: free at first, then a wall across joint 0 that comes
  // and goes (keyframes and deltas), so the robot slows, stops, re-plans and moves on.
  test::ScriptedCoprocessor coprocessor(grid.fingerprint(), kLuts, 0x5E55, cells);
  const std::uint64_t start = robot.time_ns();
  port.frames.push_back(coprocessor.handshake(start));
  port.due.push_back(start);
  // The rig's source of challenges, drawn the same way: the answer is known before the count.
  BootCounterEntropy same_as_the_rig(1);
  std::uint64_t challenge = 0;
  ASSERT_TRUE(same_as_the_rig.draw(challenge));
  port.frames.push_back(coprocessor.answer_to(challenge, start));
  port.due.push_back(start);
  std::vector<std::uint64_t> previous;
  for (std::uint64_t k = 1; k <= 120; ++k) {
    const std::uint64_t capture = start + k * 33'000'000;
    std::vector<std::uint64_t> map(cell_bits::words_for(cells), 0);
    if ((k / 20) % 2 == 1) {
      for (CellIndex c = 0; c < cells; ++c) {
        const std::uint32_t along = grid.coords_of(c).value().along[0];
        if (along == grid.cells_along(0) / 2 && grid.coords_of(c).value().along[1] > 2) {
          cell_bits::set(map.data(), c);
        }
      }
    }
    const bool keyframe = k == 1 || k % 10 == 0;
    port.frames.push_back(coprocessor.update(keyframe ? nullptr : &previous, k - 1, map, k, capture,
                                             capture + 30'000'000));
    port.due.push_back(capture + 30'000'000);
    previous = map;
  }

  double planned[kMaxJoints] = {};
  const auto one_cycle = [&] {
    port.now = robot.time_ns();
    const RobotJoints joints = robot.read();
    motion.plan_velocity(joints, rig.store.store().view(), rig.store.store().version(), port.now,
                         planned);
    const CycleReport& report = cycle.run(planned, true);
    (void)cycle.service_link(port.now + 3'000'000);  // the idle time's map work, also counted
    robot.step(0.004);
    return report.state;
  };
  for (int i = 0; i < 50; ++i) (void)one_cycle();  // init: the session and the first maps
  long states[5] = {};
  counting = true;
  for (int i = 0; i < 1000; ++i) ++states[static_cast<int>(one_cycle())];
  counting = false;
  EXPECT_EQ(allocations.load(), 0) << "allocations in 1000 cycles";
  EXPECT_GT(states[static_cast<int>(CycleState::kMoving)], 0);
  EXPECT_GT(states[static_cast<int>(CycleState::kStopped)] +
                states[static_cast<int>(CycleState::kSlowed)],
            0)
      << "the wall never slowed the robot: the count covers too little";
  EXPECT_GT(motion.progress().plans, 1u) << "no re-plan under count";
  EXPECT_GT(rig.link.updates_applied(), 100u);

  // The negative control: the counter sees an allocation.
  counting = true;
  auto* probe = new std::vector<int>(10);
  counting = false;
  EXPECT_GT(allocations.load(), 0);
  delete probe;
}

}  // namespace
}  // namespace safecell
