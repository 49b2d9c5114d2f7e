#include "safecell/base/crc32.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

std::uint32_t crc_of(std::string_view text) { return crc32(text.data(), text.size()); }

// Published check values of CRC-32/ISO-HDLC (the CRC of Ethernet, zlib and PNG).
TEST(Crc32, MatchesPublishedVectors) {
  EXPECT_EQ(crc_of(""), 0x00000000u);
  EXPECT_EQ(crc_of("a"), 0xE8B7BE43u);
  EXPECT_EQ(crc_of("abc"), 0x352441C2u);
  EXPECT_EQ(crc_of("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc_of("message digest"), 0x20159D7Fu);
  EXPECT_EQ(crc_of("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
  const unsigned char zeros[32] = {};
  EXPECT_EQ(crc32(zeros, sizeof zeros), 0x190A55ADu);
}

TEST(Crc32, IncrementalEqualsOneShotForEverySplit) {
  test::PropertyRun run(200);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<std::size_t> length(0, 300);
  for (int i = 0; i < run.iterations(); ++i) {
    unsigned char data[300];
    const std::size_t size = length(run.rng());
    for (std::size_t k = 0; k < size; ++k) data[k] = static_cast<unsigned char>(byte(run.rng()));
    const std::size_t split = size == 0 ? 0 : run.rng()() % (size + 1);
    Crc32 crc;
    crc.update(data, split);
    crc.update(data + split, size - split);
    ASSERT_EQ(crc.value(), crc32(data, size)) << "size " << size << " split " << split;
  }
}

TEST(Crc32, EverySingleBitFlipChangesTheValue) {
  unsigned char frame[64];
  for (std::size_t k = 0; k < sizeof frame; ++k) frame[k] = static_cast<unsigned char>(k * 37u);
  const std::uint32_t good = crc32(frame, sizeof frame);
  for (std::size_t bit = 0; bit < sizeof frame * 8; ++bit) {
    frame[bit / 8] ^= static_cast<unsigned char>(1u << (bit % 8));
    ASSERT_NE(crc32(frame, sizeof frame), good) << "bit " << bit;
    frame[bit / 8] ^= static_cast<unsigned char>(1u << (bit % 8));
  }
}

// CRC-32/AUTOSAR (the polynomial of OPC UA Safety) from the CRC catalogue: check and residue.
TEST(SafetyCrc32, MatchesTheCatalogue) {
  const std::string_view check = "123456789";
  EXPECT_EQ(safety_crc32(check.data(), check.size()), 0x1697D06Au);
  EXPECT_EQ(safety_crc32("", 0), 0x00000000u);
  // Appending the CRC (little-endian, as the frame does) leaves the catalogue's residue.
  unsigned char framed[13] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  const std::uint32_t crc = safety_crc32(framed, 9);
  for (int k = 0; k < 4; ++k) framed[9 + k] = static_cast<unsigned char>(crc >> (8 * k));
  EXPECT_EQ(safety_crc32(framed, 13) ^ 0xFFFFFFFFu, 0x904CDDBFu);
}

// A bitwise, most-significant-bit-first reference written from the definition (polynomial
// 0xF4ACFB13, input and output reflected), independent of the table and its reflected constant.
std::uint32_t reflect(std::uint32_t value, int bits) {
  std::uint32_t out = 0;
  for (int b = 0; b < bits; ++b) out |= ((value >> b) & 1u) << (bits - 1 - b);
  return out;
}
std::uint32_t bitwise_safety_crc32(const unsigned char* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= reflect(data[i], 8) << 24;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80000000u) != 0 ? (crc << 1) ^ 0xF4ACFB13u : crc << 1;
    }
  }
  return reflect(crc, 32) ^ 0xFFFFFFFFu;
}

TEST(SafetyCrc32, EqualsTheBitwiseReference) {
  test::PropertyRun run(300);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<std::size_t> length(0, 1500);
  std::vector<unsigned char> data(1500);
  for (int i = 0; i < run.iterations(); ++i) {
    const std::size_t size = length(run.rng());
    for (std::size_t k = 0; k < size; ++k) data[k] = static_cast<unsigned char>(byte(run.rng()));
    ASSERT_EQ(safety_crc32(data.data(), size), bitwise_safety_crc32(data.data(), size))
        << "size " << size << ", first byte " << (size > 0 ? int{data[0]} : -1);
  }
}

// The CRC is linear: flipping error bits e changes it by the CRC syndrome of e alone. An error is
// undetected exactly when the syndromes of its bits XOR to zero.
template <typename Crc>
std::vector<std::uint32_t> single_bit_syndromes(std::size_t frame_bytes) {
  std::vector<unsigned char> frame(frame_bytes, 0);
  const std::uint32_t clean = Crc::of(frame.data(), frame.size());
  std::vector<std::uint32_t> syndromes;
  for (std::size_t bit = 0; bit < frame_bytes * 8; ++bit) {
    frame[bit / 8] ^= static_cast<unsigned char>(1u << (bit % 8));
    syndromes.push_back(Crc::of(frame.data(), frame.size()) ^ clean);
    frame[bit / 8] ^= static_cast<unsigned char>(1u << (bit % 8));
  }
  return syndromes;
}

// Whether two distinct bit pairs share a syndrome (an undetected 4-bit error), or a pair has the
// syndrome 0 (an undetected 2-bit error): all pair syndromes, sorted.
bool misses_an_error_of_two_or_four_bits(const std::vector<std::uint32_t>& syndromes) {
  std::vector<std::uint32_t> pairs;
  pairs.reserve(syndromes.size() * (syndromes.size() - 1) / 2);
  for (std::size_t i = 0; i < syndromes.size(); ++i) {
    for (std::size_t j = i + 1; j < syndromes.size(); ++j) {
      pairs.push_back(syndromes[i] ^ syndromes[j]);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs.front() == 0 || std::adjacent_find(pairs.begin(), pairs.end()) != pairs.end();
}

// Over the largest frame (1500 bytes): every error of 1, 2 or 3 bits is detected. (Every odd
// number of bits is, since the polynomial has the factor x + 1: checked with 3.)
TEST(SafetyCrc32, DetectsEveryErrorOfUpToThreeBitsInAFullSizeFrame) {
  const std::vector<std::uint32_t> syndromes = single_bit_syndromes<SafetyCrc32>(1500);
  const std::unordered_set<std::uint32_t> distinct(syndromes.begin(), syndromes.end());
  ASSERT_EQ(distinct.size(), syndromes.size()) << "two single-bit errors share a syndrome";
  ASSERT_EQ(distinct.count(0u), 0u) << "a single-bit error is undetected";
  // Three bits i < j < k: undetected when s_i ^ s_j is the syndrome of a third bit.
  const std::size_t bits = syndromes.size();
  std::size_t undetected = 0;
  for (std::size_t i = 0; i < bits; i += 7) {  // every 7th first bit keeps the test quick
    for (std::size_t j = i + 1; j < bits; ++j) {
      undetected += distinct.count(syndromes[i] ^ syndromes[j]);
    }
  }
  EXPECT_EQ(undetected, 0u);
}

// Two and four bits exhaustively over a 256-byte frame. (The claim for the full 1500 bytes is the
// published property of the polynomial; protocol/SECURITY.md cites it.)
TEST(SafetyCrc32, DetectsEveryTwoAndFourBitErrorInA256ByteFrame) {
  EXPECT_FALSE(misses_an_error_of_two_or_four_bits(single_bit_syndromes<SafetyCrc32>(256)));
}

// The negative control of the check above: it finds the undetected errors of a weak polynomial
// (x^32 + 1 misses two flips 32 bits apart).
TEST(SafetyCrc32, TheSyndromeCheckCatchesWeakPolynomials) {
  EXPECT_TRUE(
      misses_an_error_of_two_or_four_bits(single_bit_syndromes<ReflectedCrc32<0x80000000u>>(16)));
}

}  // namespace
}  // namespace safecell
