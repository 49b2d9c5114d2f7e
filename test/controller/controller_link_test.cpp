// The controller's end of the link alone, on the controller's own code only (nanopb, the safety
// layer, the map store), so it also runs under qemu-aarch64: a scripted coprocessor opens a
// session, sends a keyframe and deltas, and misbehaves; the link takes what is right, refuses
// what is not, and says whether the robot may move.

#include "safecell/controller/controller_link.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <vector>

#include "safecell/controller/boot_counter_entropy.hpp"
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
      : store_(MapStoreLayout::of(kCells)), link_(config(), port_, store_.store(), entropy_) {}

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
  // The session's start: the opening, and the answer to the challenge the link sent back.
  void open(test::ScriptedCoprocessor& coprocessor, std::uint64_t now) {
    deliver(coprocessor.handshake(now), now);
    deliver(coprocessor.answer(port_.sent.back(), now), now);
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
  BootCounterEntropy entropy_{1};
  ControllerLink link_;
  ScriptedCoprocessor coprocessor_;
};

TEST_F(ControllerLinkTest, NoMotionUntilASessionAndAVerifiedKeyframe) {
  EXPECT_EQ(link_.block(0), LinkBlock::kNoSession);
  open(coprocessor_, 10 * kMs);
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
  BootCounterEntropy entropy(1);
  ControllerLink link(sliced_config, port_, store_.store(), entropy);
  port_.inbox.push_back(coprocessor_.handshake(10 * kMs));
  link.poll(10 * kMs);
  port_.inbox.push_back(coprocessor_.answer(port_.sent.back(), 10 * kMs));
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
  open(coprocessor_, 10 * kMs);
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
  open(coprocessor_, 10 * kMs);
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
  open(coprocessor_, 10 * kMs);
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
  open(coprocessor_, 10 * kMs);
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
  open(coprocessor_, 10 * kMs);
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
  open(coprocessor_, 10 * kMs);
  deliver(coprocessor_.update(nullptr, 0, map_with(0, 10), 1, 19 * kMs, 20 * kMs), 21 * kMs);
  ASSERT_EQ(link_.block(22 * kMs), LinkBlock::kNone);
  test::ScriptedCoprocessor restarted(kGrid, kLuts, kSession + 1, kCells);  // a new opening
  open(restarted, 30 * kMs);
  EXPECT_TRUE(link_.session_up());
  EXPECT_EQ(link_.session_id(), restarted.session());
  EXPECT_EQ(link_.block(31 * kMs), LinkBlock::kNoMap);
  EXPECT_EQ(cell_bits::count(held().data(), 0, kCells), kCells) << "no map: all forbidden";
}

TEST_F(ControllerLinkTest, TheSessionIdIsTheOpeningXorTheControllersChallenge) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  EXPECT_FALSE(link_.session_up()) << "an opening alone opens nothing";
  const safecell_v1_Message challenge = last_sent();
  ASSERT_EQ(challenge.which_body, safecell_v1_Message_handshake_tag);
  EXPECT_FALSE(challenge.body.handshake.accepted);
  ASSERT_NE(challenge.body.handshake.challenge, 0u);
  EXPECT_EQ(challenge.body.handshake.session_id, kSession);
  // The opening sent again (lost answer, or a duplicate) gets the same challenge.
  deliver(coprocessor_.handshake(12 * kMs), 12 * kMs);
  EXPECT_EQ(last_sent().body.handshake.challenge, challenge.body.handshake.challenge);
  EXPECT_EQ(link_.challenges_given(), 1u);
  deliver(coprocessor_.answer(port_.sent.back(), 13 * kMs), 13 * kMs);
  ASSERT_TRUE(link_.session_up());
  EXPECT_TRUE(last_sent().body.handshake.accepted);
  EXPECT_EQ(last_sent().body.handshake.challenge, challenge.body.handshake.challenge);
  EXPECT_EQ(link_.session_id(), kSession ^ challenge.body.handshake.challenge);
  EXPECT_EQ(link_.latch().total(), 0u) << "an honest start is no error";
}

TEST_F(ControllerLinkTest, AnAnswerToAnExpiredOrForeignChallengeIsRefused) {
  deliver(coprocessor_.handshake(10 * kMs), 10 * kMs);
  const Bytes challenge = port_.sent.back();
  // Later than the challenge's lifetime (1 s): refused, no answer sent.
  const std::size_t sent = port_.sent.size();
  deliver(coprocessor_.answer(challenge, 1011 * kMs), 1011 * kMs);
  EXPECT_FALSE(link_.session_up());
  EXPECT_EQ(link_.last_fault().error, LinkError::kRepetition);
  EXPECT_EQ(port_.sent.size(), sent) << "a stale answer gets nothing back";
  // Another opening's challenge, answered by this opening: refused too.
  ScriptedCoprocessor other;
  test::ScriptedCoprocessor second(kGrid, kLuts, kSession + 7, kCells);
  deliver(second.handshake(1020 * kMs), 1020 * kMs);
  deliver(other.answer(port_.sent.back(), 1021 * kMs), 1021 * kMs);
  EXPECT_FALSE(link_.session_up());
  EXPECT_EQ(link_.stale_answers(), 2u);
  // The control: the second opening answering its own challenge opens.
  deliver(second.handshake(1022 * kMs), 1022 * kMs);
  deliver(second.answer(port_.sent.back(), 1023 * kMs), 1023 * kMs);
  EXPECT_TRUE(link_.session_up());
}

// Everything one session's coprocessor sent, as the network could record and replay it.
struct RecordedSession {
  std::vector<Bytes> frames;
  std::vector<std::uint64_t> map;
};

TEST_F(ControllerLinkTest, AReplayedStartOfTheLiveSessionIsRefusedAndKeepsItsMap) {
  const Bytes opening = coprocessor_.handshake(10 * kMs);
  deliver(opening, 10 * kMs);
  const Bytes answer = coprocessor_.answer(port_.sent.back(), 10 * kMs);
  deliver(answer, 10 * kMs);
  const std::uint64_t session = link_.session_id();
  const auto map = map_with(0, 10);
  deliver(coprocessor_.update(nullptr, 0, map, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  ASSERT_EQ(link_.block(22 * kMs), LinkBlock::kNone);
  deliver(opening, 25 * kMs);  // answered with a new challenge: nothing else changes
  deliver(answer, 25 * kMs);   // its challenge is used up
  EXPECT_EQ(link_.last_fault().error, LinkError::kRepetition);
  EXPECT_EQ(link_.session_id(), session);
  EXPECT_EQ(link_.block(26 * kMs), LinkBlock::kNone) << "the session and its map stay";
  EXPECT_EQ(held(), map);
}

// A recorded session replayed into a controller that restarted (its boot counter went on): the
// replayed answer does not echo the new boot's challenge, so no session opens and no map of the
// recording is taken. Negative control: a controller whose challenges restart with it (the boot
// counter not kept) takes the same recording as a session, with its map: the test would see a
// challenge that is not fresh.
TEST_F(ControllerLinkTest, ARecordedSessionReplayedIntoARestartedControllerIsRefused) {
  RecordedSession recorded;
  recorded.map = map_with(300, 700);
  {
    HostMapStore store(MapStoreLayout::of(kCells));
    MemoryPort port;
    BootCounterEntropy boot_one(1);
    ControllerLink first_boot(config(), port, store.store(), boot_one);
    ScriptedCoprocessor coprocessor;
    const auto play = [&](Bytes frame, std::uint64_t now) {
      recorded.frames.push_back(frame);
      port.inbox.push_back(std::move(frame));
      first_boot.poll(now);
    };
    play(coprocessor.handshake(10 * kMs), 10 * kMs);
    play(coprocessor.answer(port.sent.back(), 10 * kMs), 10 * kMs);
    play(coprocessor.update(nullptr, 0, recorded.map, 1, 19 * kMs, 20 * kMs), 21 * kMs);
    ASSERT_EQ(first_boot.block(22 * kMs), LinkBlock::kNone) << "the recording is of a session";
  }
  const auto replay_into = [&](std::uint32_t boot_count) {
    HostMapStore store(MapStoreLayout::of(kCells));
    MemoryPort port;
    BootCounterEntropy boot(boot_count);
    ControllerLink restarted(config(), port, store.store(), boot);
    // Replayed soon after the restart (its clock starts again), each frame as recorded.
    for (const Bytes& frame : recorded.frames) {
      port.inbox.push_back(frame);
      restarted.poll(21 * kMs);
    }
    return std::make_pair(restarted.session_up(), store.store().version());
  };
  const auto [session_after_restart, version_after_restart] = replay_into(2);
  EXPECT_FALSE(session_after_restart);
  EXPECT_EQ(version_after_restart, 0u) << "no map of the recording is taken";
  const auto [session_without_fresh_challenge, version_without_fresh_challenge] = replay_into(1);
  EXPECT_TRUE(session_without_fresh_challenge) << "negative control: the replay itself works";
  EXPECT_EQ(version_without_fresh_challenge, 1u);
}

// A recording of an earlier session, replayed into the live session of a later opening: its start
// is refused, its data frames are of another session (masquerade), the live session and its map
// stay; the errors count, and the second latches a stop named as such.
TEST_F(ControllerLinkTest, ARecordedSessionReplayedIntoALiveOneChangesNothingButTheErrorCount) {
  ScriptedCoprocessor earlier;
  std::vector<Bytes> recording;
  recording.push_back(earlier.handshake(5 * kMs));
  deliver(recording.back(), 5 * kMs);
  recording.push_back(earlier.answer(port_.sent.back(), 5 * kMs));
  deliver(recording.back(), 5 * kMs);
  recording.push_back(earlier.update(nullptr, 0, map_with(3000, 4000), 1, 6 * kMs, 6 * kMs));
  deliver(recording.back(), 6 * kMs);
  ASSERT_EQ(store_.store().version(), 1u) << "the recording is of a session";
  test::ScriptedCoprocessor live(kGrid, kLuts, kSession + 1, kCells);
  open(live, 10 * kMs);
  const auto map = map_with(0, 10);
  deliver(live.update(nullptr, 0, map, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  const std::uint64_t session = link_.session_id();
  ASSERT_EQ(link_.block(22 * kMs), LinkBlock::kNone);
  deliver(recording[0], 23 * kMs);
  deliver(recording[1], 23 * kMs);
  EXPECT_EQ(link_.session_id(), session);
  EXPECT_EQ(link_.block(24 * kMs), LinkBlock::kNone) << "one refused answer: the robot goes on";
  EXPECT_EQ(link_.latch().total(), 1u);
  deliver(recording[2], 25 * kMs);
  EXPECT_EQ(link_.last_fault().error, LinkError::kMasquerade);
  EXPECT_EQ(link_.session_id(), session);
  EXPECT_EQ(held(), map);
  EXPECT_EQ(link_.block(26 * kMs), LinkBlock::kLatched) << "the second error stops, named";
}

// A source of challenges that fails opens no session, and says why in the refusal.
TEST_F(ControllerLinkTest, NoChallengeNoSession) {
  struct FailingEntropy final : EntropyPort {
    bool draw(std::uint64_t&) noexcept override { return false; }
  } failing;
  HostMapStore store(MapStoreLayout::of(kCells));
  ControllerLink link(config(), port_, store.store(), failing);
  port_.inbox.push_back(coprocessor_.handshake(10 * kMs));
  link.poll(10 * kMs);
  EXPECT_FALSE(link.session_up());
  EXPECT_EQ(link.last_fault().error, LinkError::kWrongConfiguration);
  EXPECT_FALSE(last_sent().body.handshake.accepted);
  EXPECT_EQ(last_sent().body.handshake.challenge, 0u);
}

// The heartbeat after each update names it: an update lost whole gets a repair asked for at once
// (from the version held), once; a heartbeat naming the held version asks nothing.
TEST_F(ControllerLinkTest, AnUpdateLostWholeIsRepairedOnItsHeartbeat) {
  const auto heartbeat_naming = [this](std::uint64_t version, std::uint64_t now) {
    safecell_v1_Message message = safecell_v1_Message_init_zero;
    message.which_body = safecell_v1_Message_heartbeat_tag;
    message.body.heartbeat.last_map_version = version;
    Bytes payload(kMaxPayloadBytes);
    const Result<std::size_t> encoded = encode_message(message, payload.data(), payload.size());
    payload.resize(encoded.ok() ? encoded.value() : 0);
    return coprocessor_.seal_payload(payload, 0, now);
  };
  open(coprocessor_, 10 * kMs);
  const auto first = map_with(100, 900);
  deliver(coprocessor_.update(nullptr, 0, first, 1, 19 * kMs, 20 * kMs), 21 * kMs);
  const std::size_t sent = port_.sent.size();
  deliver(heartbeat_naming(1, 21 * kMs), 21 * kMs);
  EXPECT_EQ(port_.sent.size(), sent) << "the update named is held: nothing to ask";
  // Version 2 is lost on the way; its heartbeat comes.
  (void)coprocessor_.update(&first, 1, map_with(200, 950), 2, 29 * kMs, 30 * kMs);
  deliver(heartbeat_naming(2, 30 * kMs), 31 * kMs);
  ASSERT_EQ(last_sent().which_body, safecell_v1_Message_keyframe_request_tag);
  EXPECT_EQ(last_sent().body.keyframe_request.held_map_version, 1u);
  EXPECT_EQ(link_.losses_repaired(), 1u);
  const std::size_t asked = port_.sent.size();
  deliver(heartbeat_naming(2, 32 * kMs), 32 * kMs);
  EXPECT_EQ(port_.sent.size(), asked) << "asked once per lost update";
  // The repair, a delta from the version held, is taken; nothing was refused.
  const auto third = map_with(300, 990);
  deliver(coprocessor_.update(&first, 1, third, 3, 39 * kMs, 40 * kMs), 41 * kMs);
  EXPECT_EQ(store_.store().version(), 3u);
  EXPECT_EQ(held(), third);
  EXPECT_EQ(link_.updates_refused(), 0u);
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
