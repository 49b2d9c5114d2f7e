// The safety layer's frame: layout, and corruption of every kind the CRC guarantees to catch
// (../shared/SAFETY.md): every single-bit flip of a full-size frame, and 10^6 seeded random
// corruptions of up to five bits, bursts of up to 32 bits and changed lengths.

#include "safecell/protocol/frame.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

constexpr std::uint64_t kFingerprint = 0x5AFEC0DE12345678ull;

FrameHeader some_header() {
  FrameHeader header;
  header.source_id = 7;
  header.destination_id = 9;
  header.session_id = 0x0123456789ABCDEFull;
  header.sequence = 42;
  header.send_time_ns = 1'000'000'123;
  header.capture_time_ns = 999'000'000;
  return header;
}

std::vector<std::uint8_t> frame_with_payload(std::size_t payload_size, std::uint64_t seed = 1) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> payload(payload_size);
  for (auto& byte : payload) byte = static_cast<std::uint8_t>(rng());
  std::vector<std::uint8_t> frame(kMaxFrameBytes);
  const Result<std::size_t> size = write_frame(some_header(), kFingerprint, payload.data(),
                                               payload.size(), frame.data(), frame.size());
  EXPECT_TRUE(size.ok());
  frame.resize(size.value_or(0));
  return frame;
}

std::string hex_of(const std::vector<std::uint8_t>& bytes, std::size_t first, std::size_t count) {
  std::string text;
  for (std::size_t i = first; i < first + count && i < bytes.size(); ++i) {
    constexpr char kDigits[] = "0123456789abcdef";
    text += kDigits[bytes[i] >> 4];
    text += kDigits[bytes[i] & 15];
  }
  return text;
}

TEST(Frame, LayoutByHand) {
  const std::uint8_t payload[3] = {0xAA, 0xBB, 0xCC};
  std::uint8_t frame[64];
  const Result<std::size_t> size =
      write_frame(some_header(), kFingerprint, payload, 3, frame, sizeof frame);
  ASSERT_TRUE(size.ok());
  EXPECT_EQ(size.value(), 51u);
  EXPECT_EQ(frame[0], 51);  // length, little-endian
  EXPECT_EQ(frame[1], 0);
  EXPECT_EQ(frame[2], kProtocolVersion);
  EXPECT_EQ(frame[3], 0);
  EXPECT_EQ(frame[4], 7);      // source
  EXPECT_EQ(frame[8], 9);      // destination
  EXPECT_EQ(frame[12], 0xEF);  // session, low byte first
  EXPECT_EQ(frame[19], 0x01);
  EXPECT_EQ(frame[20], 42);  // sequence
  EXPECT_EQ(frame[44], 0xAA);
  EXPECT_EQ(frame[46], 0xCC);
  const std::uint32_t crc = frame_crc(frame, 51, kFingerprint);
  EXPECT_EQ(frame[47], crc & 0xFF);
  EXPECT_EQ(frame[50], crc >> 24);
}

TEST(Frame, OpensWhatWasWritten) {
  const std::vector<std::uint8_t> frame = frame_with_payload(100);
  const Result<FrameView, LinkFault> opened = open_frame(frame.data(), frame.size(), kFingerprint);
  ASSERT_TRUE(opened.ok());
  const FrameHeader& header = opened.value().header;
  EXPECT_EQ(header.source_id, 7u);
  EXPECT_EQ(header.destination_id, 9u);
  EXPECT_EQ(header.session_id, 0x0123456789ABCDEFull);
  EXPECT_EQ(header.sequence, 42u);
  EXPECT_EQ(header.send_time_ns, 1'000'000'123u);
  EXPECT_EQ(header.capture_time_ns, 999'000'000u);
  EXPECT_EQ(opened.value().payload_size, 100u);
  EXPECT_EQ(opened.value().payload, frame.data() + kFrameHeaderBytes);
}

TEST(Frame, RefusesOversizePayloadsAndSmallBuffers) {
  std::vector<std::uint8_t> payload(kMaxPayloadBytes + 1);
  std::vector<std::uint8_t> out(2000);
  EXPECT_EQ(
      write_frame(some_header(), 0, payload.data(), payload.size(), out.data(), out.size()).error(),
      Status::kCapacityExceeded);
  EXPECT_EQ(write_frame(some_header(), 0, payload.data(), 10, out.data(), 57).error(),
            Status::kCapacityExceeded);
  EXPECT_TRUE(write_frame(some_header(), 0, payload.data(), 10, out.data(), 58).ok());
}

TEST(Frame, AnUnknownVersionIsRefusedWithItsVersion) {
  // The next version, and the one before (version 1 opened a session without the controller's
  // challenge).
  for (const std::uint8_t version : {std::uint8_t{kProtocolVersion + 1}, std::uint8_t{1}}) {
    std::vector<std::uint8_t> frame = frame_with_payload(10);
    frame[2] = version;
    const auto opened = open_frame(frame.data(), frame.size(), kFingerprint);
    ASSERT_FALSE(opened.ok());
    EXPECT_EQ(opened.error().error, LinkError::kWrongConfiguration);
    EXPECT_EQ(opened.error().detail, version);
  }
}

TEST(Frame, ADifferentImplicitFingerprintFailsTheCrc) {
  const std::vector<std::uint8_t> frame = frame_with_payload(10);
  const auto opened = open_frame(frame.data(), frame.size(), kFingerprint ^ 1);
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.error().error, LinkError::kCorruption);
}

TEST(Frame, HandshakeFramesUseFingerprintZeroSoEitherEndCanOpenThem) {
  FrameHeader header = some_header();
  header.flags = kFrameFlagHandshake;
  std::uint8_t frame[64];
  const Result<std::size_t> size = write_frame(header, kFingerprint, nullptr, 0, frame, 64);
  ASSERT_TRUE(size.ok());
  const auto opened = open_frame(frame, size.value(), kFingerprint ^ 0xFF);
  ASSERT_TRUE(opened.ok());
  EXPECT_TRUE(opened.value().is_handshake());
  // Undefined flag bits are refused, on writing and on reading.
  header.flags = 0x02;
  EXPECT_EQ(write_frame(header, 0, nullptr, 0, frame, 64).error(), Status::kInvalidArgument);
}

TEST(Frame, EverySingleBitFlipOfAFullSizeFrameIsRefused) {
  std::vector<std::uint8_t> frame = frame_with_payload(kMaxPayloadBytes);
  ASSERT_EQ(frame.size(), kMaxFrameBytes);
  for (std::size_t bit = 0; bit < frame.size() * 8; ++bit) {
    frame[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    ASSERT_FALSE(open_frame(frame.data(), frame.size(), kFingerprint).ok()) << "bit " << bit;
    frame[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
  }
  EXPECT_TRUE(open_frame(frame.data(), frame.size(), kFingerprint).ok());
}

// A corruption the CRC is guaranteed to catch: up to 5 flipped bits anywhere (Hamming distance
// 6), a burst within 32 consecutive bits, or a frame cut short or padded.
struct Corruption {
  std::string what;
  std::vector<std::uint8_t> frame;
};

Corruption corrupt(const std::vector<std::uint8_t>& clean, std::mt19937_64& rng) {
  Corruption c{"", clean};
  const std::size_t bits = clean.size() * 8;
  const auto flip = [&](std::size_t bit) {
    c.frame[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    c.what += " " + std::to_string(bit);
  };
  switch (rng() % 3) {
    case 0: {  // 1..5 distinct bits
      const int count = 1 + static_cast<int>(rng() % 5);
      std::vector<std::size_t> chosen;
      while (static_cast<int>(chosen.size()) < count) {
        const std::size_t bit = rng() % bits;
        if (std::find(chosen.begin(), chosen.end(), bit) == chosen.end()) chosen.push_back(bit);
      }
      c.what = "bits";
      for (const std::size_t bit : chosen) flip(bit);
      break;
    }
    case 1: {  // a burst: first and last bit flipped, any pattern between, span <= 32
      const std::size_t span = 1 + rng() % 32;
      const std::size_t first = rng() % (bits - span + 1);
      c.what = "burst";
      flip(first);
      for (std::size_t bit = first + 1; bit + 1 < first + span; ++bit) {
        if (rng() % 2 == 0) flip(bit);
      }
      if (span > 1) flip(first + span - 1);
      break;
    }
    default: {  // truncated or extended by 1..8 bytes
      const std::size_t change = 1 + rng() % 8;
      if (rng() % 2 == 0) {
        c.what = "cut by " + std::to_string(change);
        c.frame.resize(c.frame.size() - change);
      } else {
        c.what = "padded by " + std::to_string(change);
        c.frame.resize(c.frame.size() + change, static_cast<std::uint8_t>(rng()));
      }
    }
  }
  return c;
}

TEST(Frame, AMillionRandomCorruptionsAreRefused) {
  test::PropertyRun run(1'000'000);
  std::vector<std::vector<std::uint8_t>> frames;
  for (const std::size_t payload : {0u, 1u, 60u, 700u, 1452u}) {
    frames.push_back(frame_with_payload(payload, payload));
  }
  for (int i = 0; i < run.iterations(); ++i) {
    const std::vector<std::uint8_t>& clean = frames[static_cast<std::size_t>(i) % frames.size()];
    const Corruption c = corrupt(clean, run.rng());
    ASSERT_FALSE(open_frame(c.frame.data(), c.frame.size(), kFingerprint).ok())
        << "frame of " << clean.size() << " bytes, " << c.what << ", header "
        << hex_of(c.frame, 0, 16);
  }
}

TEST(Frame, HostileLengthsNeverReadOutOfRange) {
  std::vector<std::uint8_t> frame = frame_with_payload(20);
  // Length field claiming more than was received, less, zero, the maximum.
  for (const std::uint16_t claimed :
       {std::uint16_t{0}, std::uint16_t{47}, std::uint16_t{67}, std::uint16_t{69},
        std::uint16_t{1500}, std::uint16_t{0xFFFF}}) {
    frame[0] = static_cast<std::uint8_t>(claimed);
    frame[1] = static_cast<std::uint8_t>(claimed >> 8);
    const auto opened = open_frame(frame.data(), frame.size(), kFingerprint);
    ASSERT_FALSE(opened.ok()) << "claimed " << claimed;
    EXPECT_EQ(opened.error().error, LinkError::kCorruption);
  }
  EXPECT_FALSE(open_frame(nullptr, 100, kFingerprint).ok());
  EXPECT_FALSE(open_frame(frame.data(), 10, kFingerprint).ok());
}

}  // namespace
}  // namespace safecell
