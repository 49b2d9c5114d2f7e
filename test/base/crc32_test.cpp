#include "safecell/base/crc32.hpp"

#include <gtest/gtest.h>

#include <string_view>

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

}  // namespace
}  // namespace safecell
