// The controller's end of the link alone, on the controller's own code only (nanopb, the safety
// layer, the map store), so it also runs under qemu-aarch64: a scripted coprocessor opens a
// session, sends a keyframe and deltas, and misbehaves; the link takes what is right, refuses
// what is not, and says whether the robot may move.

#include "safecell/controller/controller_link.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <vector>

#include "safecell/controller/host/map_store_memory.hpp"
#include "safecell/cspace/cell_bits.hpp"
#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/protocol/nanopb_codec.hpp"
#include "scripted_coprocessor.hpp"

namespace safecell {
namespace {

using test::Bytes;
constexpr std::uint64_t kMs = 1'000'000;
constexpr CellIndex kCells = 5000;
constexpr std::uint64_t kGrid = 0x6121D;
constexpr std::uint64_t kLuts = 0x1075;
constexpr std::uint64_t kSession = 0xC0FFEE;

// The scripted coprocessor of this file: its grid and LUTs.
class ScriptedCoprocessor : public test::ScriptedCoprocessor {
 public:
  explicit ScriptedCoprocessor(std::uint64_t lut_fingerprint = kLuts)
      : test::ScriptedCoprocessor(kGrid, lut_fingerprint, kSession, kCells) {}
};

using test::MemoryPort;

class ControllerLinkTest : public ::testing::Test {
 protected:
  ControllerLinkTest()
      : store_(MapStoreLayout::of(kCells)), link_(config(), port_, store_.store()) {}

  static ControllerLinkConfig config() {
    ControllerLinkConfig c;
    c.grid_fingerprint = kGrid;
    c.lut_fingerprint = kLuts;
    return c;
  }
  static std::vector<std::uint64_t> map_with(CellIndex begin, CellIndex end) {
    std::vector<std::uint64_t> words(cell_bits::words_for(kCells), 0);
    cell_bits::set_range(words.data(), begin, end);
    return words;
  }
  void deliver(const Bytes& frame, std::uint64_t now) {
    port_.inbox.push_back(frame);
    link_.poll(now);
  }
  std::vector<std::uint64_t> held() const {
    std::vector<std::uint64_t> words(cell_bits::words_for(kCells));
    store_.store().view().copy_dense(words.data());
    return words;
  }
  // The last message the link sent, decoded.
  safecell_v1_Message last_sent() {
    const Bytes& frame = port_.sent.back();
    const auto opened =
        open_frame(frame.data(), frame.size(), configuration_fingerprint(kGrid, kLuts));
    EXPECT_TRUE(opened.ok());
    safecell_v1_Message message = safecell_v1_Message_init_zero;
    EXPECT_EQ(decode_message(opened.value().payload, opened.value().payload_size, message),
              Status::kOk);
    return message;
  }

  HostMapStore store_;
  MemoryPort port_;
  ControllerLink link_;
  ScriptedCoprocessor coprocessor_;
};

TEST_F(ControllerLinkTest, NoMotionUntilASessionAndAVerifiedKeyframe) {
  EXPECT_EQ(link_.block(0), LinkBlock::kNoSession);
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  ASSERT_TRUE(link_.session_up());
  EXPECT_TRUE(last_sent().body.handshake.accepted);
  EXPECT_EQ(link_.block(11 * kMs), LinkBlock::kNoMap);
  const auto first = map_with(100, 900);
  deliver(coprocessor_.update(nullptr, 0, first, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  EXPECT_EQ(link_.block(22 * kMs), LinkBlock::kNone);
  EXPECT_EQ(held(), first);
  EXPECT_EQ(link_.map_capture_ns(), 19 * kMs);
  // A delta on top; then silence beyond T_wd (100 ms) blocks motion.
  const auto second = map_with(150, 950);
  deliver(coprocessor_.update(&first, 1, second, 2, 29 * kMs, 30 * kMs), 31 * kMs);
  EXPECT_EQ(held(), second);
  EXPECT_EQ(link_.block(131 * kMs), LinkBlock::kNone);
  EXPECT_EQ(link_.block(132 * kMs), LinkBlock::kMapTooOld);
}

// A poll's map work is bounded (ControllerLinkConfig::map_work_per_poll): an update larger than
// that is applied over several polls, the held map stays whole and old until the swap, and the
// update's age counts from its capture.
TEST_F(ControllerLinkTest, AnUpdateLargerThanAPollsShareIsAppliedOverSeveralPolls) {
  ControllerLinkConfig sliced_config = config();
  sliced_config.map_work_per_poll = 8;
  ControllerLink link(sliced_config, port_, store_.store());
  port_.inbox.push_back(coprocessor_.handshake(10 * kMs));
  link.poll(10 * kMs);
  ASSERT_TRUE(link.session_up());
  std::vector<std::uint64_t> first(cell_bits::words_for(kCells), 0);
  for (CellIndex c = 0; c + 3 < kCells; c += 11) cell_bits::set_range(first.data(), c, c + 3);
  auto second = first;  // the delta clears the stripes below cell 2500
  cell_bits::clear_range(second.data(), 0, 2500);
  int polls = 0;
  std::uint64_t now = 20 * kMs;
  auto poll_until_version = [&](std::uint64_t version, const std::vector<std::uint64_t>& before) {
    while (store_.store().version() != version && polls < 10000) {
      EXPECT_EQ(held(), before);
      const std::uint64_t done = store_.store().work_done();
      link.poll(now += kMs / 4);
      ++polls;
      EXPECT_LT(store_.store().work_done() - done, 8u + kWorkPerRun + kWorkPerBlock);
    }
  };
  port_.inbox.push_back(coprocessor_.update(nullptr, 0, first, 1, 19 * kMs, 20 * kMs));
  std::vector<std::uint64_t> no_map(cell_bits::words_for(kCells), 0);
  cell_bits::set_range(no_map.data(), 0, kCells);
  poll_until_version(1, no_map);
  EXPECT_EQ(held(), first);
  EXPECT_GT(polls, 40);  // about 450 runs and 10 blocks, 8 units a poll
  EXPECT_EQ(link.map_capture_ns(), 19 * kMs);
  EXPECT_EQ(link.updates_applied(), 1u);
  polls = 0;
  port_.inbox.push_back(coprocessor_.update(&first, 1, second, 2, now - kMs, now));
  poll_until_version(2, first);
  EXPECT_EQ(held(), second);
  EXPECT_GT(polls, 20);
  EXPECT_EQ(link.updates_refused(), 0u);
  EXPECT_EQ(link.latch().total(), 0u);  // no frame was late or refused
}

// A chunk whose kind is a number this version does not name, behind a valid CRC: refused as
// corruption (not taken as a keyframe), the held map kept.
TEST_F(ControllerLinkTest, AChunkOfAnUnknownKindIsRefusedAsCorruption) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  const auto first = map_with(100, 900);
  deliver(coprocessor_.update(nullptr, 0, first, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  ASSERT_EQ(store_.store().version(), 1u);
  safecell_v1_Message message = safecell_v1_Message_init_zero;
  message.which_body = safecell_v1_Message_map_chunk_tag;
  safecell_v1_MapChunk& chunk = message.body.map_chunk;
  chunk.kind = safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_DELTA;
  chunk.map_version = 2;
  chunk.base_version = 1;
  chunk.map_hash = map_hash(first.data(), kCells);
  chunk.chunk_count = 1;
  chunk.end_cell = kCells;
  Bytes payload(kMaxPayloadBytes);
  const Result<std::size_t> size = encode_message(message, payload.data(), payload.size());
  ASSERT_TRUE(size.ok());
  payload.resize(size.value());
  // The chunk's first field is its kind (field 1, varint): 0x08 0x02 becomes 0x08 0x12 (18).
  const std::uint8_t kind_delta[] = {0x08, 0x02};
  const auto at =
      std::search(payload.begin(), payload.end(), std::begin(kind_delta), std::end(kind_delta));
  ASSERT_NE(at, payload.end());
  *(at + 1) = 0x12;
  const std::uint64_t errors = link_.latch().count(LinkError::kCorruption);
  deliver(coprocessor_.seal_payload(payload, 29 * kMs, 30 * kMs), 31 * kMs);
  EXPECT_EQ(link_.latch().count(LinkError::kCorruption), errors + 1);
  EXPECT_EQ(store_.store().version(), 1u);
  EXPECT_EQ(held(), first);
}

// A keyframe of `map` in one chunk, sealed, whose hash was bound to `bound_healthy` cameras and
// `bound_reduction` and which says `healthy` and `reduction` (they differ when a fault behind a
// valid CRC changed them).
Bytes keyframe_saying(ScriptedCoprocessor& sender, const std::vector<std::uint64_t>& map,
                      std::uint64_t version, std::uint32_t bound_healthy, std::uint32_t healthy,
                      std::uint64_t now, std::uint32_t bound_reduction = 0,
                      std::uint32_t reduction = 0) {
  safecell_v1_Message message = safecell_v1_Message_init_zero;
  message.which_body = safecell_v1_Message_map_chunk_tag;
  safecell_v1_MapChunk& chunk = message.body.map_chunk;
  chunk.kind = safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_KEYFRAME;
  chunk.map_version = version;
  chunk.map_hash = map_hash_with_speed_reduction(
      map_hash_with_cameras(map_hash(map.data(), kCells), bound_healthy, 4), bound_reduction);
  chunk.speed_reduction_permille = reduction;
  chunk.chunk_count = 1;
  std::size_t size = 0;
  chunk.end_cell = encode_keyframe_chunk(map.data(), kCells, 0, chunk.runs.bytes,
                                         sizeof(chunk.runs.bytes), size);
  chunk.runs.size = static_cast<pb_size_t>(size);
  chunk.healthy_cameras = healthy;
  chunk.camera_count = 4;
  Bytes payload(kMaxPayloadBytes);
  const Result<std::size_t> encoded = encode_message(message, payload.data(), payload.size());
  EXPECT_TRUE(encoded.ok());
  payload.resize(encoded.ok() ? encoded.value() : 0);
  return sender.seal_payload(payload, now - kMs, now);
}

// The camera counts a map was fused from are bound into its hash: a count raised behind a valid
// CRC (a corrupted encode buffer, sealed again) is refused like a changed cell, and the honest
// count of the same map is taken. A status report can lower the count, never raise it.
TEST_F(ControllerLinkTest, ACameraCountChangedBehindTheCrcIsRefused) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  const auto first = map_with(100, 900);
  deliver(coprocessor_.update(nullptr, 0, first, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  ASSERT_EQ(store_.store().version(), 1u);
  ASSERT_EQ(link_.healthy_cameras(), 4u);

  const auto second = map_with(2000, 2600);
  deliver(keyframe_saying(coprocessor_, second, 2, 1, 4, 30 * kMs), 31 * kMs);
  EXPECT_EQ(store_.store().version(), 1u);
  EXPECT_EQ(link_.hash_mismatches(), 1u);
  EXPECT_EQ(link_.healthy_cameras(), 4u);
  EXPECT_EQ(held(), first);

  // The control: the same map with the count it was bound to.
  deliver(keyframe_saying(coprocessor_, second, 3, 1, 1, 40 * kMs), 41 * kMs);
  EXPECT_EQ(store_.store().version(), 3u);
  EXPECT_EQ(link_.healthy_cameras(), 1u);
  EXPECT_EQ(held(), second);

  for (const std::uint32_t reported : {4u, 0u}) {
    safecell_v1_Message message = safecell_v1_Message_init_zero;
    message.which_body = safecell_v1_Message_status_report_tag;
    message.body.status_report.healthy_cameras = reported;
    message.body.status_report.camera_count = 4;
    Bytes payload(kMaxPayloadBytes);
    const Result<std::size_t> encoded = encode_message(message, payload.data(), payload.size());
    ASSERT_TRUE(encoded.ok());
    payload.resize(encoded.value());
    deliver(coprocessor_.seal_payload(payload, 49 * kMs, 50 * kMs), 51 * kMs);
    EXPECT_EQ(link_.healthy_cameras(), reported == 0 ? 0u : 1u) << "a report of " << reported;
  }
}

// The speed reduction a map was sent with is bound into its hash too: a reduction lowered behind
// a valid CRC is refused and the held map keeps its limit; the honest reduction is taken with
// its map, and the next map without one lifts it.
TEST_F(ControllerLinkTest, ASpeedReductionChangedBehindTheCrcIsRefused) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  const auto first = map_with(100, 900);
  deliver(keyframe_saying(coprocessor_, first, 1, 4, 4, 20 * kMs, 750, 750), 21 * kMs);
  ASSERT_EQ(store_.store().version(), 1u);
  EXPECT_DOUBLE_EQ(link_.separation_speed_limit(), 0.25);

  const auto second = map_with(2000, 2600);
  deliver(keyframe_saying(coprocessor_, second, 2, 4, 4, 30 * kMs, 750, 0), 31 * kMs);
  EXPECT_EQ(store_.store().version(), 1u);
  EXPECT_EQ(link_.hash_mismatches(), 1u);
  EXPECT_DOUBLE_EQ(link_.separation_speed_limit(), 0.25);

  // The control: the same map with the reduction it was bound to; then none.
  deliver(keyframe_saying(coprocessor_, second, 3, 4, 4, 40 * kMs, 500, 500), 41 * kMs);
  EXPECT_EQ(store_.store().version(), 3u);
  EXPECT_DOUBLE_EQ(link_.separation_speed_limit(), 0.5);
  deliver(keyframe_saying(coprocessor_, second, 4, 4, 4, 50 * kMs), 51 * kMs);
  EXPECT_EQ(store_.store().version(), 4u);
  EXPECT_DOUBLE_EQ(link_.separation_speed_limit(), 1.0);
  // A reduction of 1000 or more (never sent: the publisher refuses more) is a stop.
  deliver(keyframe_saying(coprocessor_, second, 5, 4, 4, 60 * kMs, 4000, 4000), 61 * kMs);
  EXPECT_EQ(store_.store().version(), 5u);
  EXPECT_EQ(link_.separation_speed_limit(), 0.0);
}

TEST_F(ControllerLinkTest, TheJointStreamAcknowledgesTheHeldVersion) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  deliver(coprocessor_.update(nullptr, 0, map_with(0, 10), 1, 19 * kMs, 20 * kMs), 21 * kMs);
  JointSample joints;
  joints.joint_count = 6;
  joints.position_rad[2] = 0.5;
  joints.read_time_ns = 22 * kMs;
  MotionReport motion{safecell_v1_ControllerState_CONTROLLER_STATE_SLOWED, 0.5};
  motion.critical_joint = 2;
  motion.has_blocking_cell = true;
  motion.blocking_cell = 77;
  link_.send_joint_state(joints, motion, 22 * kMs);
  const safecell_v1_Message sent = last_sent();
  ASSERT_EQ(sent.which_body, safecell_v1_Message_joint_state_tag);
  EXPECT_EQ(sent.body.joint_state.applied_map_version, 1u);
  EXPECT_EQ(sent.body.joint_state.state, safecell_v1_ControllerState_CONTROLLER_STATE_SLOWED);
  EXPECT_EQ(sent.body.joint_state.critical_joint, 2u);
  EXPECT_TRUE(sent.body.joint_state.has_blocking_cell);
  EXPECT_EQ(sent.body.joint_state.blocking_cell, 77u);
  EXPECT_EQ(sent.body.joint_state.position_rad_count, 6u);
  EXPECT_DOUBLE_EQ(sent.body.joint_state.position_rad[2], 0.5);
}

TEST_F(ControllerLinkTest, AnotherLutFingerprintIsRefusedAndNamed) {
  ScriptedCoprocessor stranger(kLuts + 1);
  deliver(stranger.handshake(10 * kMs), 10 * kMs);
  EXPECT_FALSE(link_.session_up());
  EXPECT_EQ(link_.last_fault().error, LinkError::kWrongConfiguration);
  EXPECT_EQ(link_.last_fault().detail, kLuts + 1);
  EXPECT_FALSE(last_sent().body.handshake.accepted);
  EXPECT_EQ(last_sent().body.handshake.lut_fingerprint, kLuts) << "the answer names ours";
}

TEST_F(ControllerLinkTest, StaleAndHashlessMapsAreRefusedAndTwoErrorsLatch) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  const auto first = map_with(100, 900);
  // Captured 200 ms before arrival: older than the 150 ms maximum.
  deliver(coprocessor_.update(nullptr, 0, first, 1, 10 * kMs, 210 * kMs), 210 * kMs);
  EXPECT_EQ(link_.last_fault().error, LinkError::kDelay);
  EXPECT_EQ(store_.store().version(), 0u);
  EXPECT_FALSE(link_.latch().latched());
  // A map without capture time cannot be aged: refused, and the second error latches.
  deliver(coprocessor_.update(nullptr, 0, first, 2, 0, 220 * kMs), 220 * kMs);
  EXPECT_EQ(store_.store().version(), 0u);
  EXPECT_EQ(link_.block(221 * kMs), LinkBlock::kLatched);
  link_.acknowledge();
  deliver(coprocessor_.update(nullptr, 0, first, 3, 229 * kMs, 230 * kMs), 231 * kMs);
  EXPECT_EQ(link_.block(232 * kMs), LinkBlock::kNone);
}

TEST_F(ControllerLinkTest, ANewSessionForgetsTheHeldMap) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  deliver(coprocessor_.update(nullptr, 0, map_with(0, 10), 1, 19 * kMs, 20 * kMs), 21 * kMs);
  ASSERT_EQ(link_.block(22 * kMs), LinkBlock::kNone);
  test::ScriptedCoprocessor restarted(kGrid, kLuts, kSession + 1, kCells);  // a new session id
  deliver(restarted.handshake(30 * kMs), 30 * kMs);
  EXPECT_EQ(link_.block(31 * kMs), LinkBlock::kNoMap);
  EXPECT_EQ(cell_bits::count(held().data(), 0, kCells), kCells) << "no map: all forbidden";
}

TEST_F(ControllerLinkTest, AReplayedHandshakeOfTheSessionIsARepetitionAndKeepsTheMap) {
  const Bytes handshake = coprocessor_.handshake(10 * kMs);
  deliver(handshake, 10 * kMs);
  const auto map = map_with(0, 10);
  deliver(coprocessor_.update(nullptr, 0, map, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  ASSERT_EQ(link_.block(22 * kMs), LinkBlock::kNone);
  deliver(handshake, 25 * kMs);
  EXPECT_EQ(link_.last_fault().error, LinkError::kRepetition);
  EXPECT_EQ(link_.block(26 * kMs), LinkBlock::kNone) << "the session and its map stay";
  EXPECT_EQ(held(), map);
}

TEST_F(ControllerLinkTest, OversizeDatagramsAndGarbageAreCorruption) {
  deliver(Bytes(kMaxFrameBytes + 200, 0xAB), 1 * kMs);
  EXPECT_EQ(link_.last_fault().error, LinkError::kCorruption);
  deliver(Bytes(3, 0), 2 * kMs);
  EXPECT_EQ(link_.last_fault().error, LinkError::kCorruption);
  EXPECT_EQ(link_.block(3 * kMs), LinkBlock::kLatched);
}

}  // namespace
}  // namespace safecell
