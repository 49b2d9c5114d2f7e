#include "safecell/cellsets/leb128.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// Every reader gives back what was appended, each moving past exactly its own bytes: values of
// one byte (the fast path of read_short_leb128) and of every longer length.
TEST(Leb128, EveryReaderGivesBackWhatWasAppended) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const int bits = std::uniform_int_distribution<int>(1, 64)(run.rng());
    const std::uint64_t value = run.rng()() >> (64 - bits);
    std::vector<std::uint8_t> bytes;
    append_leb128(bytes, value);
    append_leb128(bytes, 5);  // what follows must be left alone
    const std::string input = "value " + std::to_string(value);

    const std::uint8_t* at = bytes.data();
    EXPECT_EQ(read_leb128(at), value) << input;
    EXPECT_EQ(read_leb128(at), 5U) << input;
    at = bytes.data();
    EXPECT_EQ(read_short_leb128(at), value) << input;
    EXPECT_EQ(read_short_leb128(at), 5U) << input;
    at = bytes.data();
    std::uint64_t checked = 0;
    ASSERT_TRUE(read_leb128_checked(at, bytes.data() + bytes.size(), 10, checked)) << input;
    EXPECT_EQ(checked, value) << input;
    EXPECT_EQ(at, bytes.data() + bytes.size() - 1) << input;
  }
}

TEST(Leb128, TheCheckedReaderRefusesLongFormsAndCutValues) {
  std::uint64_t value = 0;
  const std::vector<std::uint8_t> padded = {0x85, 0x00};  // 5 with a trailing zero byte
  const std::uint8_t* at = padded.data();
  EXPECT_FALSE(read_leb128_checked(at, padded.data() + padded.size(), 10, value));
  const std::vector<std::uint8_t> cut = {0x85, 0x81};  // the last byte says more follows
  at = cut.data();
  EXPECT_FALSE(read_leb128_checked(at, cut.data() + cut.size(), 10, value));
  const std::vector<std::uint8_t> two = {0x80, 0x01};  // 128 in two bytes, allowed one
  at = two.data();
  EXPECT_FALSE(read_leb128_checked(at, two.data() + two.size(), 1, value));
}

}  // namespace
}  // namespace safecell
