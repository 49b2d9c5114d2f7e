// Golden frames, checked in under test/protocol/golden/v<version>/: every later build must still
// decode their payloads to the same messages (the messages only ever grow), open the frames of
// the current protocol version, and refuse those of older versions naming the version (their
// session rules are not kept any more; message.proto). Each version's were written once by the
// disabled test below:
//   build/host/test/protocol/test_protocol_interop --gtest_also_run_disabled_tests
//     --gtest_filter='GoldenFrames.DISABLED_WriteTheCurrentVersion'
// Never rewrite them for a change of the protocol; a change that breaks them is a new version
// (version 2, the controller's challenge, added golden/v2/ and left golden/v1/ as it was).

#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "safecell/protocol/frame.hpp"
#include "safecell/protocol/nanopb_codec.hpp"
#include "safecell/v1/message.pb.h"

namespace safecell {
namespace {

namespace pb = ::safecell::v1;

constexpr std::uint64_t kGoldenFingerprint = 0x0123456789ABCDEFull;
constexpr std::uint64_t kGoldenChallenge = 0xC4A1100E5EED0002ull;

struct Golden {
  std::string name;
  pb::Message message;
};

// A delta of one chunk onto the version before.
pb::Message map_chunk_message(std::uint64_t version, std::uint64_t hash) {
  pb::Message m;
  auto& c = *m.mutable_map_chunk();
  c.set_kind(pb::MAP_UPDATE_KIND_DELTA);
  c.set_map_version(version);
  c.set_base_version(version - 1);
  c.set_map_hash(hash);
  c.set_chunk_index(0);
  c.set_chunk_count(1);
  c.set_first_cell(0);
  c.set_end_cell(100);
  c.set_runs(std::string("\x00\x03\x04\x0B\x59\x03", 6));
  c.set_healthy_cameras(4);
  c.set_camera_count(4);
  return m;
}

pb::Message handshake_message(std::uint32_t version, bool accepted, std::uint64_t challenge) {
  pb::Message m;
  auto& h = *m.mutable_handshake();
  h.set_protocol_version(version);
  h.set_session_id(0x5AFEC0DE00000001ull);
  h.set_source_id(1);
  h.set_destination_id(2);
  h.set_grid_fingerprint(0x1111222233334444ull);
  h.set_lut_fingerprint(0x5555666677778888ull);
  h.set_map_cycle_us(33333);
  h.set_control_cycle_us(4000);
  h.set_watchdog_us(100000);
  h.set_max_data_age_us(150000);
  h.set_keyframe_after_cycles(10);
  h.set_accepted(accepted);
  h.set_challenge(challenge);
  return m;
}

// Every message but the handshake, as version 1 wrote them (the same in every version).
std::vector<Golden> session_messages() {
  std::vector<Golden> all;
  all.push_back({"map_chunk", map_chunk_message(12, 0xEF0E2F9EF4C41E07ull)});
  {
    pb::Message m;
    m.mutable_keyframe_request()->set_held_map_version(11);
    all.push_back({"keyframe_request", m});
  }
  {
    pb::Message m;
    auto& j = *m.mutable_joint_state();
    j.set_controller_time_ns(123456789012ull);
    for (double q : {0.1, -0.2, 0.3, -0.4, 0.5, -0.6}) j.add_position_rad(q);
    for (double v : {1.0, 0.0, -1.0, 0.5, 0.0, 0.25}) j.add_velocity_rad_s(v);
    j.set_applied_map_version(12);
    j.set_state(pb::CONTROLLER_STATE_SLOWED);
    j.set_speed_scale(0.5);
    all.push_back({"joint_state", m});
  }
  {
    pb::Message m;
    m.mutable_heartbeat()->set_counter(77);
    all.push_back({"heartbeat", m});
  }
  {
    pb::Message m;
    auto& e = *m.mutable_clock_echo();
    e.set_echo_id(5);
    e.set_request_sent_ns(1000);
    e.set_request_received_ns(2000);
    e.set_reply_sent_ns(2500);
    all.push_back({"clock_echo", m});
  }
  {
    pb::Message m;
    m.mutable_stop_request()->set_cause(pb::FAULT_CAUSE_OPERATOR);
    m.mutable_stop_request()->set_detail("stop button on the pendant");
    all.push_back({"stop_request", m});
  }
  {
    pb::Message m;
    auto& s = *m.mutable_status_report();
    s.set_healthy_cameras(3);
    s.set_camera_count(4);
    s.set_camera_threshold(2);
    s.set_forbidden_cells(1234);
    s.set_fusion_us(180);
    all.push_back({"status_report", m});
  }
  {
    pb::Message m;
    m.mutable_fault_report()->set_cause(pb::FAULT_CAUSE_MAP_REFUSED);
    m.mutable_fault_report()->set_sequence(99);
    m.mutable_fault_report()->set_detail("hash mismatch");
    all.push_back({"fault_report", m});
  }
  // Added with MapChunk.speed_reduction_permille (field 12): a map sent with the robot slowed to
  // half its top speed by the protective separation.
  pb::Message slowed = map_chunk_message(13, 0x5C1D0A7E3B9F2468ull);
  slowed.mutable_map_chunk()->set_speed_reduction_permille(500);
  all.push_back({"map_chunk_slowed", slowed});
  return all;
}

// The golden messages of a protocol version, in the order their frames were numbered.
std::vector<Golden> golden_messages(std::uint32_t version) {
  std::vector<Golden> all;
  if (version == 1) {
    all.push_back({"handshake", handshake_message(1, true, 0)});
  } else {
    // The four frames of a session's start (handshake.proto).
    all.push_back({"handshake_opening", handshake_message(version, false, 0)});
    all.push_back({"handshake_challenge", handshake_message(version, false, kGoldenChallenge)});
    all.push_back({"handshake_answer", handshake_message(version, false, kGoldenChallenge)});
    all.push_back({"handshake_accepted", handshake_message(version, true, kGoldenChallenge)});
  }
  for (Golden& golden : session_messages()) all.push_back(std::move(golden));
  if (version >= 2) {
    // Added with Heartbeat.last_map_version (field 2): the heartbeat after map update 12.
    pb::Message m;
    m.mutable_heartbeat()->set_counter(78);
    m.mutable_heartbeat()->set_last_map_version(12);
    all.push_back({"heartbeat_after_map", m});
  }
  return all;
}

std::filesystem::path golden_path(std::uint32_t version, const std::string& name) {
  return std::filesystem::path(SAFECELL_GOLDEN_DIR) / ("v" + std::to_string(version)) /
         (name + ".frame");
}

FrameHeader golden_header(std::uint64_t sequence) {
  FrameHeader header;
  header.source_id = 1;
  header.destination_id = 2;
  header.session_id = 0x5AFEC0DE00000001ull;
  header.sequence = sequence;
  header.send_time_ns = 1'000'000'000ull * sequence;
  header.capture_time_ns = 1'000'000'000ull * sequence - 20'000'000ull;
  return header;
}

std::vector<std::uint8_t> read_golden(std::uint32_t version, const std::string& name) {
  std::ifstream in(golden_path(version, name), std::ios::binary);
  EXPECT_TRUE(in.good()) << "missing " << golden_path(version, name);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The payload decodes on both sides to the golden message.
void expect_payload_decodes(const std::uint8_t* payload, std::size_t size, const Golden& golden) {
  safecell_v1_Message controller_side;
  ASSERT_EQ(decode_message(payload, size, controller_side), Status::kOk) << golden.name;
  EXPECT_EQ(controller_side.which_body, static_cast<pb_size_t>(golden.message.body_case()))
      << golden.name;
  if (golden.message.has_map_chunk()) {
    EXPECT_EQ(controller_side.body.map_chunk.speed_reduction_permille,
              golden.message.map_chunk().speed_reduction_permille())
        << golden.name;
  }
  if (golden.message.has_handshake()) {
    EXPECT_EQ(controller_side.body.handshake.challenge, golden.message.handshake().challenge());
  }
  pb::Message coprocessor_side;
  ASSERT_TRUE(coprocessor_side.ParseFromArray(payload, static_cast<int>(size)));
  EXPECT_TRUE(google::protobuf::util::MessageDifferencer::Equals(coprocessor_side, golden.message))
      << golden.name << ": " << coprocessor_side.ShortDebugString();
}

TEST(GoldenFrames, DISABLED_WriteTheCurrentVersion) {
  std::filesystem::create_directories(golden_path(kProtocolVersion, "x").parent_path());
  std::uint64_t sequence = 1;
  for (const Golden& golden : golden_messages(kProtocolVersion)) {
    const std::string payload = golden.message.SerializeAsString();
    std::vector<std::uint8_t> frame(kMaxFrameBytes);
    const bool handshake = golden.message.has_handshake();
    FrameHeader header = golden_header(sequence++);
    header.flags = handshake ? kFrameFlagHandshake : 0;
    const Result<std::size_t> size = write_frame(
        header, kGoldenFingerprint, reinterpret_cast<const std::uint8_t*>(payload.data()),
        payload.size(), frame.data(), frame.size());
    ASSERT_TRUE(size.ok());
    std::ofstream out(golden_path(kProtocolVersion, golden.name), std::ios::binary);
    out.write(reinterpret_cast<const char*>(frame.data()),
              static_cast<std::streamsize>(size.value()));
    ASSERT_TRUE(out.good()) << golden_path(kProtocolVersion, golden.name);
  }
}

TEST(GoldenFrames, EveryGoldenFrameOfTheCurrentVersionOpensAndDecodesOnBothSides) {
  std::uint64_t sequence = 1;
  for (const Golden& golden : golden_messages(kProtocolVersion)) {
    const std::vector<std::uint8_t> frame = read_golden(kProtocolVersion, golden.name);
    const Result<FrameView, LinkFault> opened =
        open_frame(frame.data(), frame.size(), kGoldenFingerprint);
    ASSERT_TRUE(opened.ok()) << golden.name << ": " << to_string(opened.error().error);
    EXPECT_EQ(opened.value().header.sequence, sequence) << golden.name;
    EXPECT_EQ(opened.value().header.capture_time_ns, golden_header(sequence).capture_time_ns);
    EXPECT_EQ(opened.value().is_handshake(), golden.message.has_handshake()) << golden.name;
    ++sequence;
    expect_payload_decodes(opened.value().payload, opened.value().payload_size, golden);
  }
}

// Version 1's frames: refused as another version (a version-1 end does not answer the
// controller's challenge), while their payloads, read past the header, decode as they did.
TEST(GoldenFrames, FramesOfVersion1AreRefusedNamingItAndTheirPayloadsStillDecode) {
  for (const Golden& golden : golden_messages(1)) {
    const std::vector<std::uint8_t> frame = read_golden(1, golden.name);
    ASSERT_GT(frame.size(), kFrameOverheadBytes) << golden.name;
    const Result<FrameView, LinkFault> opened =
        open_frame(frame.data(), frame.size(), kGoldenFingerprint);
    ASSERT_FALSE(opened.ok()) << golden.name;
    EXPECT_EQ(opened.error().error, LinkError::kWrongConfiguration) << golden.name;
    EXPECT_EQ(opened.error().detail, 1u) << golden.name;
    expect_payload_decodes(frame.data() + kFrameHeaderBytes, frame.size() - kFrameOverheadBytes,
                           golden);
  }
}

TEST(GoldenFrames, AFrameOfAnotherVersionIsRefusedNamingIt) {
  std::vector<std::uint8_t> frame = read_golden(kProtocolVersion, "heartbeat");
  ASSERT_GT(frame.size(), 3u);
  frame[2] = 7;
  const Result<FrameView, LinkFault> opened =
      open_frame(frame.data(), frame.size(), kGoldenFingerprint);
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().error, LinkError::kWrongConfiguration);
  EXPECT_EQ(opened.error().detail, 7u);
}

}  // namespace
}  // namespace safecell
