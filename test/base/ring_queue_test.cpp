#include "safecell/base/ring_queue.hpp"

#include <gtest/gtest.h>

#include <deque>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

TEST(RingQueue, IsFirstInFirstOutAndRefusesWhenFull) {
  RingQueue<int, 3> queue;
  EXPECT_TRUE(queue.try_push(1));
  EXPECT_TRUE(queue.try_push(2));
  EXPECT_TRUE(queue.try_push(3));
  EXPECT_FALSE(queue.try_push(4));
  int out = 0;
  EXPECT_TRUE(queue.try_pop(out));
  EXPECT_EQ(out, 1);
  EXPECT_TRUE(queue.try_push(4));
  EXPECT_EQ(queue[0], 2);
  EXPECT_EQ(queue[2], 4);
  EXPECT_THROW(static_cast<void>(queue[3]), test::AssertFailure);
}

TEST(RingQueue, PopFromEmptyFailsWithoutTouchingTheOutput) {
  RingQueue<int, 2> queue;
  int out = 42;
  EXPECT_FALSE(queue.try_pop(out));
  EXPECT_EQ(out, 42);
}

TEST(RingQueue, BehavesLikeABoundedDequeUnderRandomOperations) {
  test::PropertyRun run(5000);
  RingQueue<int, 7> queue;
  RingQueue<int>& erased = queue;  // code that uses a queue need not know its capacity
  std::deque<int> oracle;
  for (int step = 0; step < run.iterations(); ++step) {
    if (run.rng()() % 2 == 0) {
      const int value = static_cast<int>(run.rng()() % 1000);
      const bool pushed = erased.try_push(value);
      ASSERT_EQ(pushed, oracle.size() < 7) << "step " << step;
      if (pushed) oracle.push_back(value);
    } else {
      int out = -1;
      const bool popped = erased.try_pop(out);
      ASSERT_EQ(popped, !oracle.empty()) << "step " << step;
      if (popped) {
        ASSERT_EQ(out, oracle.front()) << "step " << step;
        oracle.pop_front();
      }
    }
    ASSERT_EQ(erased.size(), oracle.size());
    for (std::size_t k = 0; k < oracle.size(); ++k) ASSERT_EQ(erased[k], oracle[k]);
  }
}

}  // namespace
}  // namespace safecell
