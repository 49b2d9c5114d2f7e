#include "safecell/base/result.hpp"

#include <gtest/gtest.h>

#include <string>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

Result<int> parse_digit(char c) {
  if (c < '0' || c > '9') return Status::kInvalidArgument;
  return c - '0';
}

Result<int> sum_of_digits(const char* text) {
  int sum = 0;
  for (; *text != '\0'; ++text) {
    SAFECELL_TRY_ASSIGN(const int digit, parse_digit(*text));
    sum += digit;
  }
  return sum;
}

Status require_even(int value) { return value % 2 == 0 ? Status::kOk : Status::kOutOfRange; }

Status both_even(int a, int b) {
  SAFECELL_TRY(require_even(a));
  SAFECELL_TRY(require_even(b));
  return Status::kOk;
}

TEST(Result, CarriesAValueOrAnError) {
  const Result<int> ok = parse_digit('7');
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok.value(), 7);
  const Result<int> bad = parse_digit('x');
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), Status::kInvalidArgument);
  EXPECT_EQ(bad.value_or(-1), -1);
}

TEST(Result, WrongAccessAsserts) {
  const Result<int> bad = parse_digit('x');
  EXPECT_THROW(static_cast<void>(bad.value()), test::AssertFailure);
  const Result<int> ok = parse_digit('1');
  EXPECT_THROW(static_cast<void>(ok.error()), test::AssertFailure);
}

TEST(Result, TryMacrosPropagateTheFirstError) {
  EXPECT_EQ(sum_of_digits("123").value(), 6);
  EXPECT_EQ(sum_of_digits("12a3").error(), Status::kInvalidArgument);
  EXPECT_EQ(both_even(2, 4), Status::kOk);
  EXPECT_EQ(both_even(2, 5), Status::kOutOfRange);
}

TEST(Result, CopiesNonTrivialValues) {
  Result<std::string> a = std::string("left");
  Result<std::string> b = Status::kEmpty;
  b = a;
  EXPECT_EQ(b.value(), "left");
  a = Result<std::string>(Status::kOverflow);
  EXPECT_EQ(a.error(), Status::kOverflow);
  EXPECT_EQ(b.value(), "left");
}

TEST(Status, EveryCodeHasAName) {
  for (const Status status : {Status::kOk, Status::kInvalidArgument, Status::kOutOfRange,
                              Status::kCapacityExceeded, Status::kOverflow, Status::kEmpty}) {
    EXPECT_STRNE(to_string(status), "unknown status");
  }
}

}  // namespace
}  // namespace safecell
