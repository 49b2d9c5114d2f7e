// The two generated sides of safecell.v1 agree: every message round-trips
// libprotobuf -> nanopb -> libprotobuf unchanged, and what breaks the controller's bounds (the
// .options) is refused by nanopb, never truncated.

#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "safecell/protocol/nanopb_codec.hpp"
#include "safecell/test/property.hpp"
#include "safecell/v1/message.nanopb.h"  // nanopb's, from protocol/nanopb
#include "safecell/v1/message.pb.h"      // libprotobuf's, from protocol/libprotobuf

namespace safecell {
namespace {

namespace pb = ::safecell::v1;

std::uint64_t any_u64(std::mt19937_64& rng) {
  // Small and large values, so varints of every length occur.
  return rng() >> (rng() % 64);
}
std::uint32_t any_u32(std::mt19937_64& rng) { return static_cast<std::uint32_t>(any_u64(rng)); }
double any_double(std::mt19937_64& rng) {
  return std::uniform_real_distribution<double>(-10.0, 10.0)(rng);
}
std::string any_text(std::mt19937_64& rng, std::size_t max) {
  std::string text(rng() % (max + 1), ' ');
  for (char& c : text) c = static_cast<char>('a' + rng() % 26);
  return text;
}

pb::FaultCause any_cause(std::mt19937_64& rng) {
  return static_cast<pb::FaultCause>(rng() % (pb::FaultCause_MAX + 1));
}

// A random Message with the body `which` (1..9: the oneof's field numbers), within the bounds.
pb::Message random_message(int which, std::mt19937_64& rng) {
  pb::Message message;
  switch (which) {
    case 1: {
      auto& h = *message.mutable_handshake();
      h.set_protocol_version(any_u32(rng));
      h.set_session_id(rng());
      h.set_source_id(any_u32(rng));
      h.set_destination_id(any_u32(rng));
      h.set_grid_fingerprint(rng());
      h.set_lut_fingerprint(rng());
      h.set_map_cycle_us(any_u32(rng));
      h.set_control_cycle_us(any_u32(rng));
      h.set_watchdog_us(any_u32(rng));
      h.set_max_data_age_us(any_u32(rng));
      h.set_keyframe_after_cycles(any_u32(rng));
      h.set_accepted(rng() % 2 == 0);
      break;
    }
    case 2: {
      auto& c = *message.mutable_map_chunk();
      c.set_kind(static_cast<pb::MapUpdateKind>(rng() % 3));
      c.set_map_version(any_u64(rng));
      c.set_base_version(any_u64(rng));
      c.set_map_hash(rng());
      c.set_chunk_index(any_u32(rng));
      c.set_chunk_count(any_u32(rng));
      c.set_first_cell(any_u32(rng));
      c.set_end_cell(any_u32(rng));
      std::string runs(rng() % 1371, '\0');
      for (char& byte : runs) byte = static_cast<char>(rng());
      c.set_runs(runs);
      c.set_healthy_cameras(any_u32(rng));
      c.set_camera_count(any_u32(rng));
      c.set_speed_reduction_permille(any_u32(rng));
      break;
    }
    case 3:
      message.mutable_keyframe_request()->set_held_map_version(any_u64(rng));
      break;
    case 4: {
      auto& j = *message.mutable_joint_state();
      j.set_controller_time_ns(rng());
      const int joints = static_cast<int>(rng() % 9);
      for (int k = 0; k < joints; ++k) j.add_position_rad(any_double(rng));
      for (int k = 0; k < joints; ++k) j.add_velocity_rad_s(any_double(rng));
      j.set_applied_map_version(any_u64(rng));
      j.set_state(static_cast<pb::ControllerState>(rng() % 6));
      j.set_speed_scale(any_double(rng));
      j.set_critical_joint(any_u32(rng));
      j.set_has_blocking_cell(rng() % 2 == 0);
      j.set_blocking_cell(any_u32(rng));
      break;
    }
    case 5:
      message.mutable_heartbeat()->set_counter(any_u64(rng));
      break;
    case 6: {
      auto& e = *message.mutable_clock_echo();
      e.set_echo_id(any_u32(rng));
      e.set_request_sent_ns(rng());
      e.set_request_received_ns(rng());
      e.set_reply_sent_ns(rng());
      break;
    }
    case 7:
      message.mutable_stop_request()->set_cause(any_cause(rng));
      message.mutable_stop_request()->set_detail(any_text(rng, 95));
      break;
    case 8: {
      auto& s = *message.mutable_status_report();
      s.set_healthy_cameras(any_u32(rng));
      s.set_camera_count(any_u32(rng));
      s.set_camera_threshold(any_u32(rng));
      s.set_forbidden_cells(any_u32(rng));
      s.set_fusion_us(any_u32(rng));
      break;
    }
    default:
      message.mutable_fault_report()->set_cause(any_cause(rng));
      message.mutable_fault_report()->set_sequence(any_u64(rng));
      message.mutable_fault_report()->set_detail(any_text(rng, 95));
      break;
  }
  return message;
}

// libprotobuf bytes -> nanopb struct -> nanopb bytes -> libprotobuf message.
bool through_nanopb(const pb::Message& sent, pb::Message& back, std::string& why) {
  const std::string wire = sent.SerializeAsString();
  safecell_v1_Message decoded;
  if (decode_message(reinterpret_cast<const std::uint8_t*>(wire.data()), wire.size(), decoded) !=
      Status::kOk) {
    why = "nanopb refused it";
    return false;
  }
  std::vector<std::uint8_t> encoded(kMaxPayloadBytes);
  const Result<std::size_t> size = encode_message(decoded, encoded.data(), encoded.size());
  if (!size.ok()) {
    why = std::string("nanopb could not encode it: ") + to_string(size.error());
    return false;
  }
  if (!back.ParseFromArray(encoded.data(), static_cast<int>(size.value()))) {
    why = "libprotobuf could not parse nanopb's bytes";
    return false;
  }
  return true;
}

TEST(Interop, EveryMessageRoundTripsThroughNanopb) {
  test::PropertyRun run(2000);
  for (int i = 0; i < run.iterations(); ++i) {
    const int which = 1 + i % 9;
    const pb::Message sent = random_message(which, run.rng());
    pb::Message back;
    std::string why;
    ASSERT_TRUE(through_nanopb(sent, back, why)) << why << ": " << sent.ShortDebugString();
    ASSERT_TRUE(google::protobuf::util::MessageDifferencer::Equals(sent, back))
        << "sent " << sent.ShortDebugString() << "\nback " << back.ShortDebugString();
    ASSERT_LE(sent.ByteSizeLong(), kMaxPayloadBytes) << sent.ShortDebugString();
  }
}

TEST(Interop, WhatBreaksTheControllersBoundsIsRefused) {
  safecell_v1_Message decoded;
  const auto refused = [&](const pb::Message& message) {
    const std::string wire = message.SerializeAsString();
    return decode_message(reinterpret_cast<const std::uint8_t*>(wire.data()), wire.size(),
                          decoded) == Status::kInvalidArgument;
  };
  pb::Message nine_joints;
  for (int k = 0; k < 9; ++k) nine_joints.mutable_joint_state()->add_position_rad(k);
  EXPECT_TRUE(refused(nine_joints));
  pb::Message long_runs;
  long_runs.mutable_map_chunk()->set_runs(std::string(1371, 'x'));
  EXPECT_TRUE(refused(long_runs));
  pb::Message long_detail;
  long_detail.mutable_fault_report()->set_detail(std::string(96, 'x'));
  EXPECT_TRUE(refused(long_detail));
  // The negative control: at the bounds, accepted.
  pb::Message at_bounds;
  at_bounds.mutable_map_chunk()->set_runs(std::string(1370, 'x'));
  EXPECT_FALSE(refused(at_bounds));
}

TEST(Interop, TheLargestMessageFitsOneFrame) {
  std::mt19937_64 rng(3);
  pb::Message largest = random_message(2, rng);
  auto& chunk = *largest.mutable_map_chunk();
  chunk.set_map_version(~0ull);
  chunk.set_base_version(~0ull);
  chunk.set_chunk_index(~0u);
  chunk.set_chunk_count(~0u);
  chunk.set_first_cell(~0u);
  chunk.set_end_cell(~0u);
  chunk.set_healthy_cameras(~0u);
  chunk.set_camera_count(~0u);
  chunk.set_speed_reduction_permille(~0u);
  chunk.set_kind(pb::MAP_UPDATE_KIND_DELTA);
  chunk.set_runs(std::string(1370, 'x'));
  EXPECT_LE(largest.ByteSizeLong(), kMaxPayloadBytes);
  EXPECT_EQ(largest.ByteSizeLong(), static_cast<std::size_t>(safecell_v1_Message_size));
}

}  // namespace
}  // namespace safecell
