// The link end to end on loopback UDP: the demo's sequence of maps from the coprocessor's sender,
// through the fault-injecting proxy, to the controller's receiver. Under every fault class, every
// map the controller accepts equals the one the coprocessor sent with that version, and each
// fault class is detected with its cause.

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "demo_maps.hpp"
#include "safecell/controller/boot_counter_entropy.hpp"
#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/controller/host/system_entropy.hpp"
#include "safecell/controller/host/udp_link_port.hpp"
#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/faultproxy/fault_proxy.hpp"
#include "safecell/link/coprocessor_link.hpp"
#include "safecell/link/udp_transport.hpp"
#include "safecell/protocol/nanopb_codec.hpp"

namespace safecell {
namespace {

using Words = std::vector<std::uint64_t>;
using namespace std::chrono_literals;

constexpr std::uint64_t kLutFingerprint = 0x4C55544C55544C55ull;
// The controller's clock runs 7 s ahead of the coprocessor's: the link must sync them.
constexpr std::uint64_t kControllerClockAhead_ns = 7'000'000'000ull;

std::uint64_t steady_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

// The negative control of the check below: a receiver with neither the safety layer nor the map
// checks (no CRC, sequence, version, base or hash; a map counts as taken at its last chunk). It
// sees the same datagrams as the real one, and under faults it must take wrong maps, or the
// check could not fail.
class NaiveReceiver {
 public:
  explicit NaiveReceiver(CellIndex cells) : cells_(cells), words_(cell_bits::words_for(cells)) {}

  void take(const std::uint8_t* data, std::size_t size) {
    if (size < kFrameOverheadBytes || size > kMaxFrameBytes) return;
    if (decode_message(data + kFrameHeaderBytes, size - kFrameOverheadBytes, message_) !=
            Status::kOk ||
        message_.which_body != safecell_v1_Message_map_chunk_tag) {
      return;
    }
    const safecell_v1_MapChunk& chunk = message_.body.map_chunk;
    const MapChunkView view{wire_enum(chunk.kind) == safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_DELTA
                                ? MapChunkKind::kDelta
                                : MapChunkKind::kKeyframe,
                            chunk.first_cell, chunk.end_cell, chunk.runs.bytes, chunk.runs.size};
    (void)apply_map_chunk(view, words_.data(), cells_);
    if (chunk.chunk_index + 1 == chunk.chunk_count) taken_[chunk.map_version] = words_;
  }
  const std::map<std::uint64_t, Words>& taken() const { return taken_; }

 private:
  CellIndex cells_;
  Words words_;
  safecell_v1_Message message_{};
  std::map<std::uint64_t, Words> taken_;
};

// The controller's UDP port, letting the naive receiver see every datagram the link receives.
class TappedPort final : public LinkPort {
 public:
  TappedPort(UdpLinkPort& inner, NaiveReceiver& tap) : inner_(inner), tap_(tap) {}
  bool send(const std::uint8_t* data, std::size_t size) noexcept override {
    return inner_.send(data, size);
  }
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override {
    const std::size_t size = inner_.receive(buffer, capacity);
    if (size > 0 && size <= capacity) tap_.take(buffer, size);
    return size;
  }

 private:
  UdpLinkPort& inner_;
  NaiveReceiver& tap_;
};

// The controller's side in its own thread: polls the link, sends a joint state every 4 ms and
// records every map it takes. Its session challenges come from the kernel, or, given a boot
// count, from a boot counter (a controller restarted with the same count draws the same ones).
class ControllerSide {
 public:
  ControllerSide(const CspaceGrid& grid, const ControllerLinkConfig& config,
                 std::uint32_t boot_count = 0)
      : cells_(grid.cell_count()),
        store_(MapStoreLayout::of(cells_)),
        port_({"127.0.0.1", 0}, {"127.0.0.1", 9}),
        naive_(cells_),
        tapped_(port_, naive_),
        boot_counter_(boot_count),
        link_(config, tapped_, store_.store(),
              boot_count != 0 ? static_cast<EntropyPort&>(boot_counter_) : system_entropy_) {}
  ~ControllerSide() { stop(); }

  std::uint16_t port() const { return port_.local_port(); }
  void talk_to(std::uint16_t peer) { port_.set_peer({"127.0.0.1", peer}); }

  void start() {
    thread_ = std::thread([this] { run(); });
  }
  void stop() {
    running_ = false;
    if (thread_.joinable()) thread_.join();
  }

  std::map<std::uint64_t, Words> taken() const {
    const std::lock_guard lock(mutex_);
    return taken_;
  }
  // The speed limit each taken map came with.
  std::map<std::uint64_t, double> limits() const {
    const std::lock_guard lock(mutex_);
    return limits_;
  }
  // Read after stop().
  const ControllerLink& link() const { return link_; }
  const NaiveReceiver& naive() const { return naive_; }
  bool saw_block(LinkBlock block) const {
    return seen_blocks_ & (1U << static_cast<unsigned>(block));
  }

 private:
  static std::uint64_t now() { return steady_ns() + kControllerClockAhead_ns; }

  void run() {
    std::uint64_t next_joint_state = now();
    std::uint64_t held = 0;
    while (running_) {
      (void)port_.wait_readable(1000);
      link_.poll(now());
      if (link_.session_up()) seen_blocks_ |= 1U << static_cast<unsigned>(link_.block(now()));
      if (store_.store().version() != held) {
        held = store_.store().version();
        const std::lock_guard lock(mutex_);
        Words words(cell_bits::words_for(cells_));
        store_.store().view().copy_dense(words.data());
        taken_[held] = std::move(words);
        limits_[held] = link_.separation_speed_limit();
      }
      if (now() >= next_joint_state) {
        JointSample joints;
        joints.joint_count = 6;
        joints.read_time_ns = now();
        link_.send_joint_state(
            joints, MotionReport{safecell_v1_ControllerState_CONTROLLER_STATE_MOVING, 1.0}, now());
        next_joint_state += 4'000'000;
      }
    }
  }

  CellIndex cells_;
  HostMapStore store_;
  UdpLinkPort port_;
  NaiveReceiver naive_;
  TappedPort tapped_;
  SystemEntropy system_entropy_;
  BootCounterEntropy boot_counter_;
  ControllerLink link_;
  std::thread thread_;
  std::atomic<bool> running_{true};
  std::atomic<unsigned> seen_blocks_{0};
  mutable std::mutex mutex_;
  std::map<std::uint64_t, Words> taken_;
  std::map<std::uint64_t, double> limits_;
};

struct FaultClass {
  const char* name;
  FaultRates to_controller;
  FaultRates to_coprocessor;
  LinkError expected;  // what the controller must detect (kNone: nothing)
};

FaultRates rates(double FaultRates::*field, double value) {
  FaultRates r;
  r.*field = value;
  return r;
}

std::vector<FaultClass> fault_classes() {
  FaultRates cut;
  cut.cut_after = 250ms;
  cut.cut_for = 250ms;
  // 400 ms of everything 200 ms late, beyond the maximum data age (150 ms). The stretch outlasts
  // the delay, so the first late frames arrive in order, as stale, before later ones overtake.
  FaultRates delayed;
  delayed.delay_after = 250ms;
  delayed.delay_for = 400ms;
  delayed.delay_by = 200ms;
  FaultRates everything;
  everything.drop = everything.duplicate = everything.reorder = 0.03;
  everything.flip = everything.insert = everything.delay = 0.03;
  return {
      {"none", {}, {}, LinkError::kNone},
      {"drop", rates(&FaultRates::drop, 0.1), rates(&FaultRates::drop, 0.1), LinkError::kLoss},
      {"duplicate", rates(&FaultRates::duplicate, 0.1), {}, LinkError::kRepetition},
      {"reorder", rates(&FaultRates::reorder, 0.1), {}, LinkError::kIncorrectSequence},
      {"delay", delayed, {}, LinkError::kDelay},
      {"reorder_delay", rates(&FaultRates::delay, 0.1), {}, LinkError::kIncorrectSequence},
      {"flip", rates(&FaultRates::flip, 0.1), rates(&FaultRates::flip, 0.1),
       LinkError::kCorruption},
      {"insert", rates(&FaultRates::insert, 0.1), {}, LinkError::kCorruption},
      {"cut", cut, cut, LinkError::kLoss},
      {"everything", everything, everything, LinkError::kCorruption},
  };
}

class LinkUnderFaults : public ::testing::TestWithParam<FaultClass> {};

// The coprocessor's transport, keeping a copy of every datagram it sends: what the network
// could record and replay.
class RecordingTransport final : public DatagramTransport {
 public:
  explicit RecordingTransport(UdpTransport& inner) : inner_(inner) {}
  bool send(std::span<const std::uint8_t> datagram) override {
    sent.emplace_back(datagram.begin(), datagram.end());
    return inner_.send(datagram);
  }
  std::optional<std::size_t> receive(std::span<std::uint8_t> buffer,
                                     std::chrono::microseconds timeout) override {
    return inner_.receive(buffer, timeout);
  }
  std::vector<std::vector<std::uint8_t>> sent;

 private:
  UdpTransport& inner_;
};

CoprocessorLinkConfig coprocessor_config(const CspaceGrid& grid) {
  CoprocessorLinkConfig config;
  config.cell_count = grid.cell_count();
  config.grid_fingerprint = grid.fingerprint();
  config.lut_fingerprint = kLutFingerprint;
  return config;
}

ControllerLinkConfig controller_config(const CspaceGrid& grid) {
  ControllerLinkConfig config;
  config.grid_fingerprint = grid.fingerprint();
  config.lut_fingerprint = kLutFingerprint;
  return config;
}

// A session recorded on the wire: its opening, answer, clock echoes and the demo's first maps.
std::vector<std::vector<std::uint8_t>> record_a_session(std::uint32_t boot_count) {
  const test::DemoMaps& demo = test::demo_maps();
  ControllerSide controller(demo.grid, controller_config(demo.grid), boot_count);
  UdpTransport udp({"127.0.0.1", 0}, {"127.0.0.1", controller.port()});
  RecordingTransport recording(udp);
  controller.talk_to(udp.local_port());
  controller.start();
  CoprocessorLink link(coprocessor_config(demo.grid), recording);
  link.open(2s);
  for (std::size_t m = 0; m < 10; ++m) {
    (void)link.send_map(demo.maps[m], steady_ns(), 4, 4);
    link.poll(10ms);
  }
  link.poll(50ms);
  controller.stop();
  EXPECT_GE(controller.taken().size(), 5u) << "the recording is of a session";
  return recording.sent;
}

// Sends the recording again through `transport` (the network replays it from the address it was
// recorded from, the one the controller talks to), 1 ms apart; `between` runs after each.
void replay(const std::vector<std::vector<std::uint8_t>>& recording, DatagramTransport& transport,
            const std::function<void()>& between) {
  for (const auto& datagram : recording) {
    (void)transport.send(datagram);
    between();
  }
}

// A recorded session, replayed over UDP into a controller started again (the product's source of
// challenges): no session opens and no map of the recording is taken. Negative control: two
// controllers whose challenges repeat (a boot counter that was not kept) open the recorded
// session again, so the test would see a challenge that is not fresh.
TEST(LinkSession, ARecordedSessionReplayedIntoARestartedControllerOpensNothing) {
  const test::DemoMaps& demo = test::demo_maps();
  const auto recording = record_a_session(0);
  ASSERT_FALSE(recording.empty());
  const auto replay_into = [](ControllerSide& controller,
                              const std::vector<std::vector<std::uint8_t>>& datagrams) {
    UdpTransport network({"127.0.0.1", 0}, {"127.0.0.1", controller.port()});
    controller.talk_to(network.local_port());
    controller.start();
    replay(datagrams, network, [] { std::this_thread::sleep_for(1ms); });
    std::this_thread::sleep_for(50ms);
    controller.stop();
  };
  {
    ControllerSide restarted(demo.grid, controller_config(demo.grid));
    replay_into(restarted, recording);
    EXPECT_FALSE(restarted.link().session_up());
    EXPECT_TRUE(restarted.taken().empty()) << "a map of the recording was taken";
    EXPECT_GE(restarted.link().stale_answers(), 1u);
  }
  const auto same_boot_recording = record_a_session(1);
  ControllerSide same_challenges(demo.grid, controller_config(demo.grid), 1);
  replay_into(same_challenges, same_boot_recording);
  EXPECT_TRUE(same_challenges.link().session_up()) << "negative control: the replay opens";
  // Its maps are refused as too old here (this controller's clock went on; one that restarts at
  // boot could find them fresh: ControllerLinkTest.ARecordedSessionReplayedInto...).
}

// A recording replayed into a live session: the live session keeps its id and goes on
// taking its own maps, every one right; the replay is detected (its data frames are of another
// session) and named, never taken for the live session's.
TEST(LinkSession, ARecordedSessionReplayedIntoALiveOneDoesNotDisturbIt) {
  const test::DemoMaps& demo = test::demo_maps();
  const auto recording = record_a_session(0);
  ControllerSide controller(demo.grid, controller_config(demo.grid));
  UdpTransport udp({"127.0.0.1", 0}, {"127.0.0.1", controller.port()});
  controller.talk_to(udp.local_port());
  controller.start();
  CoprocessorLink link(coprocessor_config(demo.grid), udp);
  link.open(2s);
  std::map<std::uint64_t, const CellSet*> sent;
  std::uint64_t sent_after_replay = 0;  // the first version sent after the replay
  for (std::size_t m = 0; m < demo.maps.size(); ++m) {
    // Between the fifth and sixth map, from the live coprocessor's address, while its link goes
    // on answering.
    if (m == 5) replay(recording, udp, [&link] { link.poll(1ms); });
    const MapUpdate update = link.send_map(demo.maps[m], steady_ns(), 4, 4);
    sent.emplace(update.version, &demo.maps[m]);
    if (m == 5) sent_after_replay = update.version;
    link.poll(10ms);
  }
  link.poll(50ms);
  controller.stop();
  EXPECT_EQ(controller.link().session_id(), link.session_id()) << "the live session was replaced";
  const auto taken = controller.taken();
  std::size_t wrong = 0;
  std::size_t after_replay = 0;
  for (const auto& [version, words] : taken) {
    const auto original = sent.find(version);
    wrong += original == sent.end() || words != original->second->words() ? 1U : 0U;
    after_replay += version >= sent_after_replay ? 1U : 0U;
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(after_replay, 0u) << "the live session took no map after the replay";
  EXPECT_GE(controller.link().stale_answers(), 1u);
  EXPECT_GT(controller.link().latch().count(LinkError::kMasquerade), 0u);
}

TEST(LinkSession, TheControllersWatchdogAndDataAgeAreTheSessions) {
  const test::DemoMaps& demo = test::demo_maps();
  ControllerLinkConfig controller_config;
  controller_config.grid_fingerprint = demo.grid.fingerprint();
  controller_config.lut_fingerprint = kLutFingerprint;
  controller_config.watchdog_ns = 180'000'000;
  controller_config.max_data_age_ns = 220'000'000;
  ControllerSide controller(demo.grid, controller_config);

  CoprocessorLinkConfig link_config;
  link_config.cell_count = demo.grid.cell_count();
  link_config.grid_fingerprint = demo.grid.fingerprint();
  link_config.lut_fingerprint = kLutFingerprint;
  link_config.watchdog_us = 100'000;
  link_config.max_data_age_us = 150'000;
  UdpTransport transport({"127.0.0.1", 0}, {"127.0.0.1", controller.port()});
  controller.talk_to(transport.local_port());
  controller.start();
  CoprocessorLink link(link_config, transport);
  // Before the session, the values given.
  EXPECT_EQ(link.config().watchdog_us, 100'000U);
  link.open(2s);
  EXPECT_EQ(link.config().watchdog_us, 180'000U);
  EXPECT_EQ(link.config().max_data_age_us, 220'000U);
  controller.stop();
}

TEST_P(LinkUnderFaults, EveryMapTheControllerTakesIsTheOneSent) {
  const FaultClass& faults = GetParam();
  const test::DemoMaps& demo = test::demo_maps();
  const CspaceGrid& grid = demo.grid;

  ControllerLinkConfig controller_config;
  controller_config.grid_fingerprint = grid.fingerprint();
  controller_config.lut_fingerprint = kLutFingerprint;
  ControllerSide controller(grid, controller_config);

  CoprocessorLinkConfig link_config;
  link_config.cell_count = grid.cell_count();
  link_config.grid_fingerprint = grid.fingerprint();
  link_config.lut_fingerprint = kLutFingerprint;
  link_config.publisher.runs_per_chunk_bytes = 48;  // several chunks per update
  UdpTransport transport({"127.0.0.1", 0}, {"127.0.0.1", 9});

  FaultProxySettings proxy_settings;
  proxy_settings.peer_a = transport.local_port();
  proxy_settings.peer_b = controller.port();
  proxy_settings.a_to_b = faults.to_controller;
  proxy_settings.b_to_a = faults.to_coprocessor;
  proxy_settings.seed = 7;
  FaultProxy proxy(proxy_settings);
  transport.set_peer({"127.0.0.1", proxy.port_a()});
  controller.talk_to(proxy.port_b());
  proxy.start();
  controller.start();

  // The handshake itself may meet the faults: retry a few times, as the service does.
  CoprocessorLink link(link_config, transport);
  bool opened = false;
  for (int attempt = 0; attempt < 5 && !opened; ++attempt) {
    try {
      link.open(2s);
      opened = true;
    } catch (const std::exception& error) {
      ADD_FAILURE() << "attempt " << attempt << ": " << error.what();
    }
  }
  ASSERT_TRUE(opened);

  std::map<std::uint64_t, CellSet> sent;
  std::map<std::uint64_t, double> sent_limits;  // the speed limit of each (none, half, quarter)
  for (const CellSet& map : demo.maps) {
    const std::uint32_t reduction = std::array<std::uint32_t, 3>{0, 500, 750}[sent.size() % 3];
    const MapUpdate update = link.send_map(map, steady_ns(), 4, 4, reduction);
    sent.emplace(update.version, map);
    sent_limits.emplace(update.version, 1.0 - reduction * 1e-3);
    link.poll(10ms);
    if (update.version % 10 == 0) link.send_clock_echo();
  }
  link.poll(300ms);
  controller.stop();
  proxy.stop();

  // Maps taken that differ from the one sent with their version (or were never sent).
  const auto wrong_maps = [&sent](const std::map<std::uint64_t, Words>& maps) {
    std::size_t wrong = 0;
    for (const auto& [version, words] : maps) {
      const auto original = sent.find(version);
      wrong += original == sent.end() || words != original->second.words() ? 1U : 0U;
    }
    return wrong;
  };
  const std::map<std::uint64_t, Words> taken = controller.taken();
  const std::size_t wrong = wrong_maps(taken);
  const ErrorLatch& detected = controller.link().latch();
  std::string causes;
  for (int e = 1; e < kLinkErrorCount; ++e) {
    const auto error = static_cast<LinkError>(e);
    if (detected.count(error) > 0) {
      causes += std::string(to_string(error)) + " " + std::to_string(detected.count(error)) + ", ";
    }
  }
  RecordProperty("proxy", proxy.report_json());
  EXPECT_EQ(wrong, 0u) << "maps taken that differ from the one sent with their version";
  for (const auto& [version, limit] : controller.limits()) {
    const auto original = sent_limits.find(version);  // a version never sent: counted above
    if (original == sent_limits.end()) continue;
    EXPECT_EQ(limit, original->second) << "the speed limit taken with version " << version;
  }
  // Liveness: most updates get through (the link repairs after every fault).
  EXPECT_GE(taken.size(), demo.maps.size() / 3)
      << "the controller took " << taken.size() << " of " << demo.maps.size() << " updates; "
      << proxy.report_json() << "; detected: " << causes;
  if (faults.expected == LinkError::kNone) {
    EXPECT_EQ(detected.total(), 0u) << causes;
    // Every update applied, none refused: counted by the link itself (the maps this thread
    // samples may miss one that a newer update replaced before the thread looked). Each delta is
    // based on the update sent before it, which the controller took before it (in order), however
    // late its acknowledgement comes back.
    const ControllerLink& received = controller.link();
    EXPECT_EQ(received.updates_applied(), demo.maps.size())
        << received.updates_applied() << " applied, " << received.updates_refused() << " refused";
    EXPECT_EQ(received.updates_refused(), 0u) << "an update refused on a link without faults";
    EXPECT_EQ(received.hash_mismatches(), 0u);
    EXPECT_EQ(taken.rbegin()->second, demo.maps.back().words());
    // A receiver without checks takes every map right too when nothing goes wrong.
    EXPECT_EQ(wrong_maps(controller.naive().taken()), 0u);
  } else {
    EXPECT_GT(detected.count(faults.expected), 0u)
        << faults.name << ": expected " << to_string(faults.expected) << ", detected: " << causes
        << "; proxy: " << proxy.report_json();
  }
  // The negative control: without the safety layer and the map checks, the same faults get
  // wrong maps taken.
  if (std::string(faults.name) == "everything") {
    EXPECT_GT(wrong_maps(controller.naive().taken()), 0u)
        << "a receiver without checks took no wrong map: the check could not fail";
  }
  if (std::string(faults.name) == "cut") {
    EXPECT_TRUE(controller.saw_block(LinkBlock::kMapTooOld))
        << "a 250 ms cut must outlast the 100 ms watchdog";
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFaultClass, LinkUnderFaults, ::testing::ValuesIn(fault_classes()),
                         [](const ::testing::TestParamInfo<FaultClass>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace safecell
