// The link's costs (issue: frame_encode_us, frame_check_us, crc_mb_s, delta_bytes_p50/p99,
// keyframe_bytes): sealing and checking a full-size frame (1500 bytes), the safety CRC over one,
// and the map updates of the demo's sequence on the default cell: its scenario through the real
// pipeline, each update a delta against the previous map (the controller acknowledged it), its
// bytes on the wire counted with every frame's header and CRC; keyframe_bytes is the largest
// keyframe of the sequence.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "default_cell_tables.hpp"
#include "safecell/base/crc32.hpp"
#include "safecell/bench/project_benchmarks.hpp"
#include "safecell/link/map_publisher.hpp"
#include "safecell/protocol/frame_checker.hpp"
#include "safecell/v1/message.pb.h"
#include "safecell/validation/percentile.hpp"

namespace safecell {
namespace {

constexpr LinkEndpoints kSender{1, 2, 0x5AFEC0DE00000001ull, 0x0123456789ABCDEFull};
constexpr LinkEndpoints kReceiver{2, 1, 0x5AFEC0DE00000001ull, 0x0123456789ABCDEFull};

std::vector<std::uint8_t> full_payload() {
  std::vector<std::uint8_t> payload(kMaxPayloadBytes);
  for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = static_cast<std::uint8_t>(i * 31);
  return payload;
}

void frame_seal_full_size(benchmark::State& state) {
  const std::vector<std::uint8_t> payload = full_payload();
  std::vector<std::uint8_t> frame(kMaxFrameBytes);
  FrameSealer sealer(kSender);
  std::uint64_t now = 1'000'000'000;
  while (state.KeepRunning()) {
    benchmark::DoNotOptimize(
        sealer.seal(payload.data(), payload.size(), now, now - 1000, frame.data(), frame.size()));
    ++now;
  }
}

void frame_check_full_size(benchmark::State& state) {
  const std::vector<std::uint8_t> payload = full_payload();
  std::vector<std::uint8_t> frame(kMaxFrameBytes);
  FrameSealer sealer(kSender);
  (void)sealer.seal(payload.data(), payload.size(), 1000, 900, frame.data(), frame.size());
  const ArrivalLimits limits{1'000'000, 1'000'000, 1'000'000};
  while (state.KeepRunning()) {
    FrameChecker checker(kReceiver, limits, 1000);  // a fresh session: frame 1 is expected
    benchmark::DoNotOptimize(checker.check(frame.data(), frame.size(), 1000));
  }
}

void safety_crc32_full_frame(benchmark::State& state) {
  const std::vector<std::uint8_t> frame = full_payload();
  while (state.KeepRunning()) {
    benchmark::DoNotOptimize(safety_crc32(frame.data(), kMaxFrameBytes - 48));
  }
  state.counters["bytes"] = static_cast<double>(kMaxFrameBytes - 48);
}

double wire_bytes(const MapUpdate& update) {
  double bytes = 0.0;
  for (const auto& chunk : update.chunks) {
    v1::Message message;
    *message.mutable_map_chunk() = chunk;
    bytes += static_cast<double>(message.ByteSizeLong() + kFrameOverheadBytes);
  }
  return bytes;
}

// One timed unit: publishing (encoding) the next map of the sequence as a delta.
void map_updates_of_demo_sequence(benchmark::State& state) {
  const std::vector<CellSet>& maps = default_cell_demo_maps();
  const std::uint32_t cells = maps.front().cell_count();
  // The largest keyframe of the sequence (any map may have to go out whole).
  double keyframe_bytes = 0.0;
  for (const CellSet& map : maps) {
    keyframe_bytes =
        std::max(keyframe_bytes, wire_bytes(MapPublisher(cells, {}).publish(map, 4, 4)));
  }
  MapPublisher sizes(cells, {});
  (void)sizes.publish(maps.front(), 4, 4);
  std::vector<double> delta_bytes;
  for (std::size_t m = 1; m < maps.size(); ++m) {
    sizes.acknowledge(sizes.last_version());
    delta_bytes.push_back(wire_bytes(sizes.publish(maps[m], 4, 4)));
  }
  MapPublisher publisher(cells, {});
  (void)publisher.publish(maps.front(), 4, 4);
  std::size_t next = 1;
  while (state.KeepRunning()) {
    publisher.acknowledge(publisher.last_version());
    benchmark::DoNotOptimize(publisher.publish(maps[next], 4, 4));
    next = next + 1 < maps.size() ? next + 1 : 1;
  }
  state.counters["keyframe_bytes"] = keyframe_bytes;
  state.counters["delta_bytes_p50"] = percentile(delta_bytes, 0.5);
  state.counters["delta_bytes_p99"] = percentile(delta_bytes, 0.99);
  state.counters["delta_bytes_max"] = *std::max_element(delta_bytes.begin(), delta_bytes.end());
  state.counters["cells"] = static_cast<double>(cells);
}

}  // namespace

void register_link_benchmarks() {
  register_benchmark("frame_seal_full_size", frame_seal_full_size, benchmark::kMicrosecond);
  register_benchmark("frame_check_full_size", frame_check_full_size, benchmark::kMicrosecond);
  register_benchmark("safety_crc32_full_frame", safety_crc32_full_frame, benchmark::kMicrosecond);
  register_benchmark("map_updates_of_demo_sequence", map_updates_of_demo_sequence,
                     benchmark::kMicrosecond);
}

}  // namespace safecell
