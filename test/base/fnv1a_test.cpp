#include "safecell/base/fnv1a.hpp"

#include <gtest/gtest.h>

namespace safecell {
namespace {

TEST(Fnv1a64, MatchesPublishedVectors) {
  EXPECT_EQ(Fnv1a64{}.value(), 0xCBF29CE484222325ull);
  Fnv1a64 a;
  a.add_byte('a');
  EXPECT_EQ(a.value(), 0xAF63DC4C8601EC8Cull);
  Fnv1a64 foobar;
  for (const char c : {'f', 'o', 'o', 'b', 'a', 'r'}) foobar.add_byte(static_cast<std::uint8_t>(c));
  EXPECT_EQ(foobar.value(), 0x85944171F73967E8ull);
}

TEST(Fnv1a64, HashesIntegersLittleEndian) {
  Fnv1a64 bytes;
  for (const int b : {0x04, 0x03, 0x02, 0x01}) bytes.add_byte(static_cast<std::uint8_t>(b));
  Fnv1a64 word;
  word.add_u32(0x01020304u);
  EXPECT_EQ(word.value(), bytes.value());
}

TEST(Fnv1a64, TreatsBothZerosAlikeAndOtherValuesApart) {
  Fnv1a64 plus, minus, tiny;
  plus.add_double(0.0);
  minus.add_double(-0.0);
  tiny.add_double(5e-324);
  EXPECT_EQ(plus.value(), minus.value());
  EXPECT_NE(plus.value(), tiny.value());
}

}  // namespace
}  // namespace safecell
