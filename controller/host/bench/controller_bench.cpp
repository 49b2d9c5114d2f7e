// safecell-controller-bench: the controller core's costs on a host core, with Google Benchmark.
//
//   controller_cycle   SafetyCycle::run at 250 Hz with a map delta every 8th cycle (maps at
//                      30 Hz), with the link's default share of a cycle (map_work_per_poll): link
//                      frames checked, the delta applied and verified in the map store in slices,
//                      the look-ahead, the watchdog, the commands and the joint report. Per-cycle
//                      times give p50, p99 and the worst (the test suite proves no allocation);
//                      Between cycles the link works on in further slices (the idle time of a
//                      4 ms cycle), each timed: slice_p99_us. update_cycles: the cycles from an
//                      update's first frame to its swap.
//     _every_delta     the same with the next delta as soon as the last one is read (the worst
//                      cadence: the link works on a map in nearly every cycle)
//     _unsliced        every delta in the cycle it arrives, whole (no work limit): the cost the
//                      slicing spreads out, for comparison
//   delta_apply        MapStore::offer of every chunk of one delta; ns_per_unit: the time of one
//                      unit of MapStore work (map_store.hpp), to size map_work_per_poll
//   planner            GridPlanner::plan between free cells of the maps (seeded pairs)
//   map_store_memory   the store's bytes for the grid and, with m_max = 6 cm, the ~14 M-cell
//                      grid; the maps (upsampled to the fine grid) held one after the other,
//                      each checked bit for bit (inexact_maps), with their mixed blocks
// Maps: --maps FILE (map_sequence_file.hpp; `safecell bench` passes the demo's maps) or, without
// it, synthetic maps on the default cell's grid (a region sweeping through C-space).
// --json prints one JSON object of the named figures after the benchmark table.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "map_sequence_file.hpp"
#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/grid_planner.hpp"
#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/controller/host/planner_memory.hpp"
#include "safecell/controller/host/scripted_coprocessor.hpp"
#include "safecell/controller/host/simulated_robot.hpp"
#include "safecell/controller/safety_cycle.hpp"
#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_hash.hpp"

namespace safecell {
namespace {

using Words = std::vector<std::uint64_t>;
constexpr std::uint64_t kLuts = 0x1075;
constexpr std::uint64_t kSession = 0xBE4C;
constexpr std::size_t kRunBytes = 1370;  // map.options: MapChunk.runs max_size

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index =
      static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size()))) - 1;
  return values[std::min(index, values.size() - 1)];
}

// The default cell's grid (safecell cell info), for runs without --maps.
GridSpec default_grid() {
  GridSpec spec;
  spec.m_max_m = 0.18;
  spec.joint_count = 6;
  const double deg = 3.14159265358979323846 / 180.0;
  const double ranges[6][2] = {{-160, 160}, {-137.5, 137.5}, {-142.5, 142.5},
                               {-240, 240}, {-105, 120},     {-270, 270}};
  const double l[6] = {1.524, 1.371, 0.745, 0.120, 0.119, 0.045};
  for (std::uint32_t j = 0; j < 6; ++j) {
    spec.joints[j] = {ranges[j][0] * deg, ranges[j][1] * deg, l[j], j < 4};
  }
  return spec;
}

// Synthetic maps: a ball of forbidden cells (a person) sweeping through C-space, over a slab of
// static obstacles.
MapSequence synthetic_maps(const GridSpec& spec, int count) {
  const CspaceGrid grid = CspaceGrid::create(spec).value();
  MapSequence sequence;
  sequence.grid = spec;
  sequence.cell_count = grid.cell_count();
  for (int m = 0; m < count; ++m) {
    Words map(cell_bits::words_for(grid.cell_count()), 0);
    const double t = static_cast<double>(m) / count;
    for (CellIndex c = 0; c < grid.cell_count(); ++c) {
      const GridCoords at = grid.coords_of(c).value();
      double distance = 0.0;
      for (std::uint32_t j = 0; j < 3; ++j) {
        const double centre = (j == 0 ? 0.2 + 0.6 * t : 0.5) * grid.cells_along(j);
        const double d = (at.along[j] - centre) / grid.cells_along(j);
        distance += d * d;
      }
      if (distance < 0.04 || at.along[1] < grid.cells_along(1) / 8) cell_bits::set(map.data(), c);
    }
    sequence.maps.push_back(std::move(map));
  }
  return sequence;
}

// --quick: no figures of the fine (6 cm) grid, whose maps take seconds to make.
bool& quick() {
  static bool on = false;
  return on;
}

// --map-work=N: ControllerLinkConfig::map_work_per_poll for the sliced cycles (0: its default).
std::uint32_t& map_work_per_poll() {
  static std::uint32_t units = 0;
  return units;
}

MapSequence& maps() {
  static MapSequence sequence;
  return sequence;
}

class QueuePort final : public LinkPort {
 public:
  bool send(const std::uint8_t*, std::size_t) noexcept override { return true; }
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override {
    if (next_ >= frames.size()) return 0;
    const auto& frame = frames[next_++];
    if (frame.size() > capacity) return capacity + 1;
    std::memcpy(buffer, frame.data(), frame.size());
    return frame.size();
  }
  bool drained() const { return next_ >= frames.size(); }
  void load(std::vector<std::vector<std::uint8_t>> loaded) {
    frames = std::move(loaded);
    next_ = 0;
  }
  std::vector<std::vector<std::uint8_t>> frames;

 private:
  std::size_t next_ = 0;
};

class VirtualClock final : public ClockPort {
 public:
  std::uint64_t now_ns() noexcept override { return now; }
  std::uint64_t now = 1'000'000'000;
};

// A configuration in the first map's free space with every discretised joint planned to move.
JointAngles free_configuration(const CspaceGrid& grid, const Words& map) {
  std::mt19937_64 rng(3);
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const auto cell = static_cast<CellIndex>(rng() % grid.cell_count());
    if (!cell_bits::test(map.data(), cell)) {
      return grid.cell_centre(grid.coords_of(cell).value()).value();
    }
  }
  return grid.cell_centre(GridCoords{}).value();
}

// delta_every: a delta arrives every this many cycles (8: maps at 30 Hz, the cycle at 250 Hz).
void controller_cycle_with(benchmark::State& state, int delta_every, bool sliced) {
  const MapSequence& sequence = maps();
  const CspaceGrid grid = CspaceGrid::create(sequence.grid).value();
  const CellIndex cells = grid.cell_count();
  HostMapStore store(MapStoreLayout::of(cells));
  QueuePort port;
  VirtualClock clock;
  ControllerLinkConfig link_config;
  link_config.grid_fingerprint = grid.fingerprint();
  link_config.lut_fingerprint = kLuts;
  if (map_work_per_poll() > 0) link_config.map_work_per_poll = map_work_per_poll();
  if (!sliced) {
    link_config.map_work_per_poll = MapStore::kUnlimited;
    link_config.max_frames_per_poll = ControllerLink::kMaxFramesPerPoll;
  }
  BootCounterEntropy entropy(1);
  ControllerLink link(link_config, port, store.store(), entropy);
  SimulatedRobotConfig robot_config;
  robot_config.joint_count = grid.joint_count();
  const JointAngles start = free_configuration(grid, sequence.maps.front());
  for (std::uint32_t j = 0; j < grid.joint_count(); ++j) {
    robot_config.joints[j] = {grid.joint(j).lo_rad, grid.joint(j).hi_rad, 1.5, 5.0, 5.0};
    robot_config.start_rad[j] = start.rad[j];
  }
  SimulatedRobot robot(robot_config);
  Watchdog watchdog({2'000'000, 6'000'000, 1'000'000'000});
  SafetyCycleConfig config;
  config.look_ahead.stop = SimulatedRobot::measure_stop_model(robot_config);
  config.min_healthy_cameras = 1;
  SafetyCycle cycle(grid, config, robot, clock, link, store.store(), watchdog);
  ScriptedCoprocessor source(grid.fingerprint(), kLuts, kSession, cells);
  // The session and the first map, untimed. The link's challenge is the boot counter's first.
  BootCounterEntropy same_as_the_link(1);
  std::uint64_t challenge = 0;
  (void)same_as_the_link.draw(challenge);
  port.load({source.handshake(clock.now), source.answer(challenge, clock.now)});
  double planned[kMaxJoints] = {};
  for (std::uint32_t j = 0; j < 3 && j < grid.joint_count(); ++j) planned[j] = 0.5 - 0.4 * j;
  (void)cycle.run(planned, true);
  std::uint64_t version = 1;
  clock.now += 4'000'000;
  port.load(source.update(nullptr, 0, sequence.maps.front().data(), version, clock.now - 50'000'000,
                          clock.now));
  for (int c = 0; c < 10000 && store.store().version() != version; ++c) {
    (void)cycle.run(planned, true);
    while (link.poll(clock.now)) {
    }
    clock.now += 4'000'000;
    robot.set_time_ns(clock.now);
  }
  if (store.store().version() != version) {
    state.SkipWithError("the first keyframe was not applied");
    return;
  }
  std::vector<double> cycle_us;
  std::size_t lines = 0;
  std::size_t frames = 0;
  std::uint64_t cycle_count = 0;
  // Deltas go from the map the store holds (a lost update is not assumed applied).
  std::size_t held_index = 0;
  std::size_t sent_index = 0;
  std::uint64_t sent_version = version;
  std::uint64_t updates_sent = 0;
  std::uint64_t update_sent_cycle = 0;
  std::vector<double> update_cycles;
  std::vector<double> slice_us;
  while (state.KeepRunning()) {
    clock.now += 4'000'000;
    // A new update once the last one is read and worked in (bounded polls leave some over).
    if (++cycle_count % static_cast<std::uint64_t>(delta_every) == 0 && port.drained() &&
        !store.store().chunk_in_work()) {
      sent_index = (sent_index + 1) % sequence.maps.size();
      ++sent_version;
      auto update =
          source.update(sequence.maps[held_index].data(), version, sequence.maps[sent_index].data(),
                        sent_version, clock.now - 50'000'000, clock.now);
      frames += update.size();
      ++updates_sent;
      port.load(std::move(update));
      update_sent_cycle = cycle_count;
    }
    const auto begin = std::chrono::steady_clock::now();
    const CycleReport& report = cycle.run(planned, true);
    const auto end = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(end - begin).count();
    state.SetIterationTime(seconds);
    cycle_us.push_back(seconds * 1e6);
    lines += report.look_ahead.lines_checked;
    // The idle time before the next cycle: more slices of the link's work (as
    // SafetyCycle::service_link does against the real clock), each timed.
    for (int slice = 0; sliced && slice < 100'000; ++slice) {
      const auto slice_begin = std::chrono::steady_clock::now();
      const bool more = link.poll(clock.now);
      const auto slice_end = std::chrono::steady_clock::now();
      slice_us.push_back(std::chrono::duration<double>(slice_end - slice_begin).count() * 1e6);
      if (!more) break;
    }
    if (store.store().version() != version) {
      version = store.store().version();
      held_index = sent_index;
      update_cycles.push_back(static_cast<double>(cycle_count - update_sent_cycle + 1));
    }
    robot.set_time_ns(clock.now);
  }
  // Updates the link did not apply: refused, or their frames too old when read (the work per
  // poll too small for the maps' rate). Any is a configuration to change, so it is reported.
  state.counters["updates_lost"] = static_cast<double>(updates_sent - update_cycles.size());
  state.counters["link_errors"] = static_cast<double>(link.latch().total());
  state.counters["p50_us"] = percentile(cycle_us, 0.5);
  state.counters["p99_us"] = percentile(cycle_us, 0.99);
  state.counters["worst_us"] = percentile(cycle_us, 1.0);
  state.counters["maps_applied"] = static_cast<double>(update_cycles.size());
  state.counters["slice_p99_us"] = percentile(slice_us, 0.99);
  state.counters["slice_worst_us"] = percentile(slice_us, 1.0);
  state.counters["update_cycles_p50"] = percentile(update_cycles, 0.5);
  state.counters["update_cycles_p99"] = percentile(update_cycles, 0.99);

  state.counters["frames_per_delta"] =
      static_cast<double>(frames) / static_cast<double>(updates_sent > 0 ? updates_sent : 1);
  state.counters["box_lines_per_cycle"] =
      static_cast<double>(lines) / static_cast<double>(cycle_us.empty() ? 1 : cycle_us.size());
}

// The chunks of every delta of the sequence, as the store sees them (no link).
struct SentDelta {
  std::vector<MapChunkHeader> headers;
  std::vector<std::vector<std::uint8_t>> runs;
};

SentDelta delta_of(const Words& base, std::uint64_t base_version, const Words& target,
                   std::uint64_t version, CellIndex cells, bool keyframe) {
  SentDelta delta;
  CellIndex from = 0;
  do {
    MapChunkHeader header;
    header.kind = keyframe ? MapChunkKind::kKeyframe : MapChunkKind::kDelta;
    header.map_version = version;
    header.base_version = keyframe ? 0 : base_version;
    header.map_hash = map_hash(target.data(), cells);
    header.chunk_index = static_cast<std::uint32_t>(delta.headers.size());
    header.first_cell = from;
    std::vector<std::uint8_t> runs(kRunBytes);
    std::size_t size = 0;
    header.end_cell =
        keyframe ? encode_keyframe_chunk(target.data(), cells, from, runs.data(), runs.size(), size)
                 : encode_delta_chunk(base.data(), target.data(), cells, from, runs.data(),
                                      runs.size(), size);
    runs.resize(size);
    from = header.end_cell;
    delta.headers.push_back(header);
    delta.runs.push_back(std::move(runs));
  } while (from < cells);
  for (auto& header : delta.headers)
    header.chunk_count = static_cast<std::uint32_t>(delta.headers.size());
  return delta;
}

void controller_cycle(benchmark::State& state) { controller_cycle_with(state, 8, true); }
void controller_cycle_every_delta(benchmark::State& state) {
  controller_cycle_with(state, 1, true);
}
void controller_cycle_unsliced(benchmark::State& state) { controller_cycle_with(state, 8, false); }

void delta_apply_on(benchmark::State& state, const std::vector<Words>& sequence, CellIndex cells) {
  HostMapStore store(MapStoreLayout::of(cells));
  const SentDelta first = delta_of(sequence.front(), 0, sequence.front(), 1, cells, true);
  for (std::size_t c = 0; c < first.headers.size(); ++c) {
    (void)store.store().offer(first.headers[c], first.runs[c].data(), first.runs[c].size(), 1);
  }
  std::uint64_t version = 1;
  std::size_t held = 0;
  std::vector<double> apply_us;
  double units = 0;
  while (state.KeepRunning()) {
    const std::size_t to = (held + 1) % sequence.size();
    const SentDelta delta =
        delta_of(sequence[held], version, sequence[to], version + 1, cells, false);
    const std::uint64_t done = store.store().work_done();
    const auto begin = std::chrono::steady_clock::now();
    MapOffer offer;
    for (std::size_t c = 0; c < delta.headers.size(); ++c) {
      offer = store.store().offer(delta.headers[c], delta.runs[c].data(), delta.runs[c].size(), 1);
    }
    const auto end = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(end - begin).count();
    state.SetIterationTime(seconds);
    apply_us.push_back(seconds * 1e6);
    units += static_cast<double>(store.store().work_done() - done);
    if (offer.outcome != MapOutcome::kApplied) {
      state.SkipWithError("a delta of the sequence was refused");
      return;
    }
    ++version;
    held = to;
  }
  state.counters["p50_us"] = percentile(apply_us, 0.5);
  state.counters["p99_us"] = percentile(apply_us, 0.99);
  state.counters["worst_us"] = percentile(apply_us, 1.0);
  double total_us = 0;
  for (const double us : apply_us) total_us += us;
  state.counters["ns_per_unit"] = units > 0 ? total_us * 1e3 / units : 0.0;
  state.counters["units_p50"] = units / static_cast<double>(apply_us.empty() ? 1 : apply_us.size());
}

// The time of MapStore work by kind, to weigh its units (map_store.hpp): deltas back and forth
// between an empty map and (a) short runs packed into 4 blocks, (b) one run over each of 256
// blocks. ns_per_run and ns_per_block solve t = runs * a + blocks * b over the two.
void map_work_costs(benchmark::State& state) {
  constexpr CellIndex kCells = 256 * kStoreBlockCells;
  const Words empty(cell_bits::words_for(kCells), 0);
  Words packed = empty;
  for (CellIndex c = 0; c < 4 * kStoreBlockCells; c += 8)
    cell_bits::set_range(packed.data(), c, c + 3);
  Words spread = empty;
  for (CellIndex b = 0; b < 256; ++b) {
    cell_bits::set_range(spread.data(), b * kStoreBlockCells, (b + 1) * kStoreBlockCells - 1);
  }
  HostMapStore store(MapStoreLayout::of(kCells));
  const SentDelta key = delta_of(empty, 0, empty, 1, kCells, true);
  (void)store.store().offer(key.headers[0], key.runs[0].data(), key.runs[0].size(), 1);
  std::uint64_t version = 1;
  double packed_us = 0;
  double spread_us = 0;
  std::uint64_t rounds = 0;
  auto apply = [&](const Words& from, const Words& to) {
    const SentDelta delta = delta_of(from, version, to, version + 1, kCells, false);
    const auto begin = std::chrono::steady_clock::now();
    for (std::size_t c = 0; c < delta.headers.size(); ++c) {
      (void)store.store().offer(delta.headers[c], delta.runs[c].data(), delta.runs[c].size(), 1);
    }
    const auto end = std::chrono::steady_clock::now();
    ++version;
    return std::chrono::duration<double>(end - begin).count() * 1e6;
  };
  while (state.KeepRunning()) {
    const double packed_round = apply(empty, packed) + apply(packed, empty);
    const double spread_round = apply(empty, spread) + apply(spread, empty);
    state.SetIterationTime((packed_round + spread_round) * 1e-6);
    packed_us += packed_round;
    spread_us += spread_round;
    ++rounds;
  }
  if (store.store().version() != version) {
    state.SkipWithError("a delta was refused");
    return;
  }
  // Per delta: packed = 256 runs + 4 blocks (+4 made level); spread = 256 runs + 256 blocks (+256).
  const double per_delta = 2.0 * static_cast<double>(rounds);
  const double block_ns = (spread_us - packed_us) / per_delta / 252.0 * 1e3;
  const double run_ns = (packed_us / per_delta * 1e3 - 4.0 * block_ns) / 256.0;
  state.counters["ns_per_run"] = run_ns;
  state.counters["ns_per_block"] = block_ns;
}

void delta_apply(benchmark::State& state) { delta_apply_on(state, maps().maps, maps().cell_count); }

void planner(benchmark::State& state) {
  const MapSequence& sequence = maps();
  const CspaceGrid grid = CspaceGrid::create(sequence.grid).value();
  const CellIndex cells = grid.cell_count();
  HostMapStore store(MapStoreLayout::of(cells));
  const SentDelta key = delta_of(sequence.maps.back(), 0, sequence.maps.back(), 1, cells, true);
  for (std::size_t c = 0; c < key.headers.size(); ++c) {
    (void)store.store().offer(key.headers[c], key.runs[c].data(), key.runs[c].size(), 1);
  }
  const PlannerLayout layout = PlannerLayout::for_grid(cells);
  PlannerMemoryHost memory(layout);
  GridPlanner planner(grid, layout, memory.memory());
  std::mt19937_64 rng(11);
  std::vector<double> plan_ms;
  double found = 0;
  while (state.KeepRunning()) {
    CellIndex start = 0;
    CellIndex goal = 0;
    do {
      start = static_cast<CellIndex>(rng() % cells);
      goal = static_cast<CellIndex>(rng() % cells);
    } while (store.store().view().forbidden(start) || store.store().view().forbidden(goal));
    const auto begin = std::chrono::steady_clock::now();
    const PlanResult result = planner.plan(store.store().view(), start, goal);
    const auto end = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(end - begin).count();
    state.SetIterationTime(seconds);
    plan_ms.push_back(seconds * 1e3);
    found += result.status == PlanStatus::kFound ? 1 : 0;
  }
  state.counters["p50_ms"] = percentile(plan_ms, 0.5);
  state.counters["worst_ms"] = percentile(plan_ms, 1.0);
  state.counters["found_share"] = found / static_cast<double>(plan_ms.size());
  state.counters["planner_bytes"] = static_cast<double>(layout.bytes());
}

// The sequence's maps on a finer grid: every fine cell takes the value of the coarse cell its
// centre lies in.
std::vector<Words> upsampled(const MapSequence& sequence, const CspaceGrid& coarse,
                             const CspaceGrid& fine, std::size_t count) {
  std::vector<std::vector<std::uint32_t>> along(fine.joint_count());
  for (std::uint32_t j = 0; j < fine.joint_count(); ++j) {
    for (std::uint32_t i = 0; i < fine.cells_along(j); ++i) {
      const double centre = fine.joint(j).lo_rad + (i + 0.5) * fine.cell_width_rad(j);
      const auto coarse_i =
          static_cast<std::uint32_t>((centre - coarse.joint(j).lo_rad) / coarse.cell_width_rad(j));
      along[j].push_back(std::min(coarse_i, coarse.cells_along(j) - 1));
    }
  }
  std::vector<Words> maps;
  for (std::size_t m = 0; m < count && m < sequence.maps.size(); ++m) {
    const Words& source = sequence.maps[m * (sequence.maps.size() / count)];
    Words map(cell_bits::words_for(fine.cell_count()), 0);
    GridCoords at{};
    for (CellIndex c = 0; c < fine.cell_count(); ++c) {
      CellIndex coarse_cell = 0;
      for (std::uint32_t j = 0; j < fine.joint_count(); ++j) {
        coarse_cell += along[j][at.along[j]] * coarse.stride(j);
      }
      if (cell_bits::test(source.data(), coarse_cell)) cell_bits::set(map.data(), c);
      for (std::uint32_t j = 0; j < fine.joint_count(); ++j) {
        if (++at.along[j] < fine.cells_along(j)) break;
        at.along[j] = 0;
      }
    }
    maps.push_back(std::move(map));
  }
  return maps;
}

// What a store of the default layout did with a sequence of maps.
struct HeldMaps {
  double mixed_blocks_max = 0;
  double degraded_blocks_max = 0;
  double inexact_maps = 0;  // not applied, or not held bit for bit as sent
};

// The blocks of a map neither all free nor all forbidden.
std::uint32_t mixed_blocks(const Words& map, CellIndex cells) {
  std::uint32_t mixed = 0;
  for (CellIndex first = 0; first < cells; first += kStoreBlockCells) {
    const CellIndex end = std::min<CellIndex>(cells, first + kStoreBlockCells);
    const std::uint64_t set = cell_bits::count(map.data(), first, end);
    if (set != 0 && set != end - first) ++mixed;
  }
  return mixed;
}

// Offers each map as a keyframe while the one before is held, and checks the store then holds it
// exactly (against the map itself, as a dense bitmap).
HeldMaps hold_all(const std::vector<Words>& sequence, CellIndex cells) {
  HostMapStore store(MapStoreLayout::of(cells));
  HeldMaps held;
  Words words(cell_bits::words_for(cells));
  std::uint64_t version = 0;
  for (const Words& map : sequence) {
    const SentDelta key = delta_of(map, 0, map, ++version, cells, true);
    for (std::size_t c = 0; c < key.headers.size(); ++c) {
      (void)store.store().offer(key.headers[c], key.runs[c].data(), key.runs[c].size(), 1);
    }
    store.store().view().copy_dense(words.data());
    if (store.store().version() != version || words != map) held.inexact_maps += 1;
    held.mixed_blocks_max =
        std::max(held.mixed_blocks_max, static_cast<double>(mixed_blocks(map, cells)));
    held.degraded_blocks_max =
        std::max(held.degraded_blocks_max, static_cast<double>(store.store().degraded_blocks()));
  }
  return held;
}

GridSpec fine_grid(const GridSpec& spec) {
  GridSpec fine = spec;
  fine.m_max_m = 0.06;
  return fine;
}

}  // namespace
const GridSpec& maps_spec();
namespace {

const std::vector<Words>& fine_maps() {
  static const std::vector<Words> upsampled_maps = [] {
    const CspaceGrid coarse = CspaceGrid::create(maps_spec()).value();
    const CspaceGrid fine = CspaceGrid::create(fine_grid(maps_spec())).value();
    return upsampled(maps(), coarse, fine, 4);
  }();
  return upsampled_maps;
}

void map_store_memory(benchmark::State& state) {
  const MapSequence& sequence = maps();
  const CellIndex cells = sequence.cell_count;
  const CspaceGrid fine = CspaceGrid::create(fine_grid(sequence.grid)).value();
  HeldMaps held;
  HeldMaps fine_held;
  while (state.KeepRunning()) {
    held = hold_all(sequence.maps, cells);
    if (!quick()) fine_held = hold_all(fine_maps(), fine.cell_count());
  }
  // The compressed form with room for two maps of mixed blocks (the pool that never degrades),
  // for comparison.
  const auto compressed_bytes = [](CellIndex count) {
    return static_cast<double>(
        MapStoreLayout::compressed(count, 2 * store_blocks_for(count)).bytes());
  };
  state.counters["cells"] = cells;
  state.counters["map_store_bytes"] = static_cast<double>(MapStoreLayout::of(cells).bytes());
  state.counters["compressed_bytes"] = compressed_bytes(cells);
  state.counters["dense_double_buffer_bytes"] = 2.0 * cell_bits::words_for(cells) * 8;
  state.counters["blocks"] = store_blocks_for(cells);
  state.counters["mixed_blocks_max"] = held.mixed_blocks_max;
  state.counters["degraded_blocks_max"] = held.degraded_blocks_max;
  state.counters["inexact_maps"] = held.inexact_maps;
  if (quick()) return;
  state.counters["fine_cells"] = fine.cell_count();
  state.counters["fine_map_store_bytes"] =
      static_cast<double>(MapStoreLayout::of(fine.cell_count()).bytes());
  state.counters["fine_compressed_bytes"] = compressed_bytes(fine.cell_count());
  state.counters["fine_dense_double_buffer_bytes"] =
      2.0 * cell_bits::words_for(fine.cell_count()) * 8;
  state.counters["fine_blocks"] = store_blocks_for(fine.cell_count());
  state.counters["fine_mixed_blocks_max"] = fine_held.mixed_blocks_max;
  state.counters["fine_degraded_blocks_max"] = fine_held.degraded_blocks_max;
  state.counters["fine_inexact_maps"] = fine_held.inexact_maps;
}

void delta_apply_fine(benchmark::State& state) {
  if (quick()) {
    state.SkipWithError("not run with --quick");
    return;
  }
  const CspaceGrid fine = CspaceGrid::create(fine_grid(maps().grid)).value();
  delta_apply_on(state, fine_maps(), fine.cell_count());
}

// Keeps the counters of every run.
class CounterCollector final : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      for (const auto& [name, counter] : run.counters) {
        counters_[run.run_name.function_name + "." + name] = counter.value;
      }
    }
  }
  bool has(const std::string& key) const { return counters_.count(key) > 0; }
  double get(const std::string& key) const {
    const auto found = counters_.find(key);
    return found == counters_.end() ? -1.0 : found->second;
  }

 private:
  std::map<std::string, double> counters_;
};

// Timed by their own clocks (manual time); the memory report runs once.
BENCHMARK(controller_cycle)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(controller_cycle_every_delta)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(controller_cycle_unsliced)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(delta_apply)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(map_work_costs)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(delta_apply_fine)
    ->Name("delta_apply_fine_grid")
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(planner)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(map_store_memory)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

const GridSpec& maps_spec() { return maps().grid; }

}  // namespace safecell

int main(int argc, char** argv) {
  using namespace safecell;
  std::string maps_path;
  bool json = false;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument.rfind("--maps=", 0) == 0) {
      maps_path = argument.substr(7);
    } else if (argument.rfind("--map-work=", 0) == 0) {
      map_work_per_poll() = static_cast<std::uint32_t>(std::stoul(argument.substr(11)));
    } else if (argument == "--quick") {
      quick() = true;
    } else if (argument == "--json") {
      json = true;
    } else if (argument == "--help" || argument == "-h") {
      std::cout << "safecell-controller-bench [--maps=FILE] [--json] [Google Benchmark flags]\n"
                   "  --maps=FILE  the maps to run on (written by `safecell bench`); default:\n"
                   "               synthetic maps on the default cell's grid\n"
                   "  --map-work=N the link's map work per cycle, in MapStore units\n"
                   "               (default: ControllerLinkConfig's)\n"
                   "  --quick      without the fine (6 cm) grid's figures\n"
                   "  --json       one JSON object of the named figures at the end\n";
      return 0;
    } else {
      rest.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(rest.size());
  benchmark::Initialize(&count, rest.data());
  // What neither this program nor Google Benchmark took (such as `--maps FILE` without the `=`).
  if (benchmark::ReportUnrecognizedArguments(count, rest.data())) return 2;
  try {
    maps() = maps_path.empty() ? synthetic_maps(default_grid(), 30) : read_map_sequence(maps_path);
  } catch (const std::exception& error) {
    std::cerr << "safecell-controller-bench: " << error.what() << "\n";
    return 2;
  }
  CounterCollector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  if (json) {
    const std::pair<const char*, const char*> figures[] = {
        {"controller_cycle_p50_us", "controller_cycle.p50_us"},
        {"controller_cycle_p99_us", "controller_cycle.p99_us"},
        {"controller_cycle_worst_us", "controller_cycle.worst_us"},
        {"controller_cycle_every_delta_p50_us", "controller_cycle_every_delta.p50_us"},
        {"controller_cycle_every_delta_p99_us", "controller_cycle_every_delta.p99_us"},
        {"controller_cycle_every_delta_worst_us", "controller_cycle_every_delta.worst_us"},
        {"controller_cycle_unsliced_p99_us", "controller_cycle_unsliced.p99_us"},
        {"controller_cycle_unsliced_worst_us", "controller_cycle_unsliced.worst_us"},
        {"controller_link_slice_p99_us", "controller_cycle.slice_p99_us"},
        {"controller_link_slice_worst_us", "controller_cycle.slice_worst_us"},
        {"controller_update_cycles_p50", "controller_cycle.update_cycles_p50"},
        {"controller_update_cycles_p99", "controller_cycle.update_cycles_p99"},
        {"controller_every_delta_update_cycles_p99",
         "controller_cycle_every_delta.update_cycles_p99"},
        {"controller_frames_per_delta", "controller_cycle.frames_per_delta"},
        {"controller_updates_lost", "controller_cycle.updates_lost"},
        {"controller_every_delta_updates_lost", "controller_cycle_every_delta.updates_lost"},
        {"delta_apply_us", "delta_apply.p50_us"},
        {"delta_apply_p99_us", "delta_apply.p99_us"},
        {"delta_apply_worst_us", "delta_apply.worst_us"},
        {"map_work_ns_per_unit", "delta_apply.ns_per_unit"},
        {"map_work_ns_per_run", "map_work_costs.ns_per_run"},
        {"map_work_ns_per_block", "map_work_costs.ns_per_block"},
        {"delta_apply_14m_us", "delta_apply_fine_grid.p50_us"},
        {"delta_apply_14m_worst_us", "delta_apply_fine_grid.worst_us"},
        {"planner_ms", "planner.p50_ms"},
        {"planner_worst_ms", "planner.worst_ms"},
        {"planner_bytes", "planner.planner_bytes"},
        {"map_store_bytes", "map_store_memory.map_store_bytes"},
        {"map_store_dense_bytes", "map_store_memory.dense_double_buffer_bytes"},
        {"map_store_mixed_blocks_max", "map_store_memory.mixed_blocks_max"},
        {"map_store_blocks", "map_store_memory.blocks"},
        {"map_store_degraded_blocks_max", "map_store_memory.degraded_blocks_max"},
        {"map_store_inexact_maps", "map_store_memory.inexact_maps"},
        {"map_store_compressed_bytes", "map_store_memory.compressed_bytes"},
        {"map_store_14m_cells", "map_store_memory.fine_cells"},
        {"map_store_14m_bytes", "map_store_memory.fine_map_store_bytes"},
        {"map_store_14m_dense_bytes", "map_store_memory.fine_dense_double_buffer_bytes"},
        {"map_store_14m_blocks", "map_store_memory.fine_blocks"},
        {"map_store_14m_mixed_blocks_max", "map_store_memory.fine_mixed_blocks_max"},
        {"map_store_14m_degraded_blocks_max", "map_store_memory.fine_degraded_blocks_max"},
        {"map_store_14m_inexact_maps", "map_store_memory.fine_inexact_maps"},
        {"map_store_14m_compressed_bytes", "map_store_memory.fine_compressed_bytes"},
    };
    std::printf("\n{");
    bool first = true;
    for (const auto& [key, counter] : figures) {
      if (!collector.has(counter)) continue;  // not run (--quick, a filter, an error)
      std::printf("%s\n  \"%s\": %.6g", first ? "" : ",", key, collector.get(counter));
      first = false;
    }
    std::printf("\n}\n");
  }
  return 0;
}
