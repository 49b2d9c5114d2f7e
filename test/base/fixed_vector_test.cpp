#include "safecell/base/fixed_vector.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// Counts live instances, to prove that elements are constructed and destroyed exactly once.
struct Tracked {
  static inline int live = 0;
  int value;
  explicit Tracked(int v) : value(v) { ++live; }
  Tracked(const Tracked& other) : value(other.value) { ++live; }
  Tracked& operator=(const Tracked&) = default;
  ~Tracked() { --live; }
};

// Code that fills a vector without knowing its capacity.
int fill_squares(FixedVector<int>& out, int count) {
  int pushed = 0;
  for (int i = 0; i < count && out.try_push_back(i * i); ++i) ++pushed;
  return pushed;
}

TEST(FixedVector, RefusesToGrowPastItsCapacity) {
  FixedVector<int, 4> squares;
  EXPECT_EQ(fill_squares(squares, 10), 4);
  EXPECT_TRUE(squares.full());
  EXPECT_FALSE(squares.try_push_back(99));
  EXPECT_EQ(squares.size(), 4u);
  EXPECT_EQ(squares.capacity(), 4u);
  EXPECT_EQ(squares[3], 9);
  EXPECT_EQ(squares.back(), 9);
}

TEST(FixedVector, CheckedAccessOutsideTheSizeAsserts) {
  FixedVector<int, 2> values;
  ASSERT_TRUE(values.try_push_back(1));
  EXPECT_THROW(static_cast<void>(values[1]), test::AssertFailure);
  values.pop_back();
  EXPECT_THROW(values.pop_back(), test::AssertFailure);
}

TEST(FixedVector, CopiesOwnTheirElements) {
  FixedVector<int, 3> original;
  ASSERT_TRUE(original.try_push_back(7));
  FixedVector<int, 3> copy = original;
  copy[0] = 8;
  EXPECT_EQ(original[0], 7);
  EXPECT_EQ(copy[0], 8);
  original = copy;
  EXPECT_EQ(original[0], 8);
}

TEST(FixedVector, ConstructsAndDestroysEachElementOnce) {
  {
    FixedVector<Tracked, 5> items;
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(items.try_push_back(Tracked(i)));
    EXPECT_EQ(Tracked::live, 5);
    items.pop_back();
    EXPECT_EQ(Tracked::live, 4);
    FixedVector<Tracked, 5> copy = items;
    EXPECT_EQ(Tracked::live, 8);
    copy.clear();
    EXPECT_EQ(Tracked::live, 4);
  }
  EXPECT_EQ(Tracked::live, 0);
}

TEST(FixedVector, AssignReportsTruncation) {
  const int values[] = {1, 2, 3, 4};
  FixedVector<int, 3> target;
  EXPECT_FALSE(target.assign(values, values + 4));
  EXPECT_EQ(target.size(), 3u);
  EXPECT_TRUE(target.assign(values, values + 2));
  EXPECT_EQ(target.size(), 2u);
}

TEST(FixedVector, BehavesLikeAStdVectorUnderRandomOperations) {
  test::PropertyRun run(2000);
  FixedVector<int, 16> fixed;
  std::vector<int> oracle;
  for (int step = 0; step < run.iterations(); ++step) {
    const auto op = run.rng()() % 4;
    if (op <= 1) {
      const int value = static_cast<int>(run.rng()() % 1000);
      const bool pushed = fixed.try_push_back(value);
      ASSERT_EQ(pushed, oracle.size() < 16) << "step " << step;
      if (pushed) oracle.push_back(value);
    } else if (op == 2 && !oracle.empty()) {
      fixed.pop_back();
      oracle.pop_back();
    } else if (op == 3 && run.rng()() % 8 == 0) {
      fixed.clear();
      oracle.clear();
    }
    ASSERT_EQ(std::vector<int>(fixed.begin(), fixed.end()), oracle) << "step " << step;
  }
}

}  // namespace
}  // namespace safecell
