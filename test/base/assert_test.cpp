#include "safecell/base/assert.hpp"

#include <gtest/gtest.h>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

int checked_half(int even) {
  SAFECELL_ASSERT(even % 2 == 0);
  return even / 2;
}

TEST(Assert, PassesWhenTheConditionHolds) { EXPECT_EQ(checked_half(8), 4); }

TEST(Assert, CallsTheInstalledHandlerWithTheExpression) {
  try {
    static_cast<void>(checked_half(3));
    FAIL() << "no assertion raised";
  } catch (const test::AssertFailure& failure) {
    EXPECT_NE(std::string(failure.what()).find("even % 2 == 0"), std::string::npos)
        << failure.what();
  }
}

}  // namespace
}  // namespace safecell
