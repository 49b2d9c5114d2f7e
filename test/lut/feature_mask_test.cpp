#include "safecell/features/feature_mask.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "safecell/test/property.hpp"

namespace safecell {
namespace {

// A mask of random blobs: rectangles and single cells.
FeatureMask random_mask(std::mt19937_64& rng, int columns, int rows) {
  FeatureMask mask(columns, rows);
  std::uniform_int_distribution<int> column(0, columns - 1);
  std::uniform_int_distribution<int> row(0, rows - 1);
  const int blobs = std::uniform_int_distribution<int>(0, 12)(rng);
  for (int i = 0; i < blobs; ++i) {
    const int c0 = column(rng);
    const int r0 = row(rng);
    const int c1 = std::min(columns - 1, c0 + std::uniform_int_distribution<int>(0, 20)(rng));
    const int r1 = std::min(rows - 1, r0 + std::uniform_int_distribution<int>(0, 20)(rng));
    mask.set_rect(FeatureRect{static_cast<std::uint16_t>(c0), static_cast<std::uint16_t>(r0),
                              static_cast<std::uint16_t>(c1), static_cast<std::uint16_t>(r1)});
  }
  for (int i = 0; i < 30; ++i) mask.set(column(rng), row(rng));
  return mask;
}

TEST(FeatureMask, SetRectEqualsCellByCell) {
  test::PropertyRun run(200);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = std::uniform_int_distribution<int>(1, 200)(run.rng());
    const int rows = std::uniform_int_distribution<int>(1, 80)(run.rng());
    FeatureMask mask(columns, rows);
    std::vector<std::vector<bool>> oracle(static_cast<std::size_t>(rows),
                                          std::vector<bool>(static_cast<std::size_t>(columns)));
    for (int k = 0; k < 5; ++k) {
      std::uniform_int_distribution<int> c(0, columns - 1);
      std::uniform_int_distribution<int> r(0, rows - 1);
      int c0 = c(run.rng()), c1 = c(run.rng()), r0 = r(run.rng()), r1 = r(run.rng());
      if (c0 > c1) std::swap(c0, c1);
      if (r0 > r1) std::swap(r0, r1);
      mask.set_rect(FeatureRect{static_cast<std::uint16_t>(c0), static_cast<std::uint16_t>(r0),
                                static_cast<std::uint16_t>(c1), static_cast<std::uint16_t>(r1)});
      for (int y = r0; y <= r1; ++y) {
        for (int x = c0; x <= c1; ++x)
          oracle[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] = true;
      }
    }
    std::size_t set = 0;
    for (int y = 0; y < rows; ++y) {
      for (int x = 0; x < columns; ++x) {
        ASSERT_EQ(mask.test(x, y), oracle[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)])
            << x << "," << y << " in " << columns << " x " << rows;
        set += oracle[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] ? 1U : 0U;
      }
    }
    EXPECT_EQ(mask.count(), set);
  }
}

TEST(FeatureMask, RectanglesCoverTheMaskExactlyWithoutOverlap) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = i % 3 == 0 ? 64 : std::uniform_int_distribution<int>(1, 150)(run.rng());
    const int rows = std::uniform_int_distribution<int>(1, 70)(run.rng());
    const FeatureMask mask = random_mask(run.rng(), columns, rows);
    FeatureMask rebuilt(columns, rows);
    std::size_t area = 0;
    for (const auto& rect : mask.rectangles()) {
      ASSERT_LE(rect.col0, rect.col1);
      ASSERT_LE(rect.row0, rect.row1);
      area += static_cast<std::size_t>(rect.col1 - rect.col0 + 1) *
              static_cast<std::size_t>(rect.row1 - rect.row0 + 1);
      rebuilt.set_rect(rect);
    }
    EXPECT_EQ(rebuilt, mask);
    EXPECT_EQ(area, mask.count()) << "rectangles overlap";
  }
}

// The runs [first, last] of set cells in a row, cell by cell.
std::vector<std::pair<int, int>> runs_of(const FeatureMask& mask, int row) {
  std::vector<std::pair<int, int>> runs;
  for (int c = 0; c < mask.columns(); ++c) {
    if (!mask.test(c, row)) continue;
    if (c > 0 && mask.test(c - 1, row)) {
      runs.back().second = c;
    } else {
      runs.emplace_back(c, c);
    }
  }
  return runs;
}

// A run continues the rectangle above only when the row above has a run of the same extent: so
// there are as many rectangles as runs that do not. Rows repeated (as in silhouettes, unions of
// rectangles) and appending after what `out` holds.
TEST(FeatureMask, RectanglesMergeEveryRunWithTheSameRunAbove) {
  test::PropertyRun run(300);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = i % 3 == 0 ? 64 : std::uniform_int_distribution<int>(1, 150)(run.rng());
    const int rows = std::uniform_int_distribution<int>(1, 70)(run.rng());
    FeatureMask mask = random_mask(run.rng(), columns, rows);
    for (int r = 1; r < rows; ++r) {  // some rows copied from the one above
      if (std::bernoulli_distribution(0.3)(run.rng())) {
        std::copy_n(mask.row_words(r - 1), mask.words_per_row(), mask.row_words(r));
      }
    }
    std::size_t starting_runs = 0;
    for (int r = 0; r < rows; ++r) {
      const auto above = r > 0 ? runs_of(mask, r - 1) : std::vector<std::pair<int, int>>{};
      for (const auto& run_here : runs_of(mask, r)) {
        if (std::find(above.begin(), above.end(), run_here) == above.end()) ++starting_runs;
      }
    }
    const FeatureRect earlier{1, 2, 3, 4};
    std::vector<FeatureRect> out{earlier};
    mask.append_rectangles(out);
    ASSERT_EQ(out.size(), starting_runs + 1) << columns << " x " << rows;
    EXPECT_EQ(out.front(), earlier);
    const std::vector<FeatureRect> rects = mask.rectangles();
    EXPECT_TRUE(std::equal(rects.begin(), rects.end(), out.begin() + 1, out.end()));
  }
}

TEST(FeatureMask, DilateEqualsGrowingEveryCellByHand) {
  test::PropertyRun run(100);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = std::uniform_int_distribution<int>(1, 150)(run.rng());
    const int rows = std::uniform_int_distribution<int>(1, 40)(run.rng());
    const int grow_columns = std::uniform_int_distribution<int>(0, 5)(run.rng());
    const int grow_rows = std::uniform_int_distribution<int>(0, 5)(run.rng());
    FeatureMask mask(columns, rows);
    const int cells = std::uniform_int_distribution<int>(0, 12)(run.rng());
    for (int k = 0; k < cells; ++k) {
      mask.set(std::uniform_int_distribution<int>(0, columns - 1)(run.rng()),
               std::uniform_int_distribution<int>(0, rows - 1)(run.rng()));
    }
    FeatureMask oracle(columns, rows);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        if (!mask.test(c, r)) continue;
        for (int y = std::max(0, r - grow_rows); y <= std::min(rows - 1, r + grow_rows); ++y) {
          for (int x = std::max(0, c - grow_columns); x <= std::min(columns - 1, c + grow_columns);
               ++x) {
            oracle.set(x, y);
          }
        }
      }
    }
    mask.dilate(grow_columns, grow_rows);
    ASSERT_EQ(mask, oracle) << columns << " x " << rows << " grown by " << grow_columns << ", "
                            << grow_rows;
  }
}

TEST(FeatureMask, FullBlocksAreTheAlignedBlocksAllInTheMask) {
  test::PropertyRun run(150);
  for (int i = 0; i < run.iterations(); ++i) {
    const int columns = std::uniform_int_distribution<int>(1, 140)(run.rng());
    const int rows = std::uniform_int_distribution<int>(1, 40)(run.rng());
    const int size = 1 << std::uniform_int_distribution<int>(0, 6)(run.rng());
    FeatureMask mask(columns, rows);
    // Mostly set, so that full blocks of every size occur.
    const double density = std::uniform_real_distribution<double>(0.7, 1.0)(run.rng());
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < columns; ++c) {
        if (std::bernoulli_distribution(density)(run.rng())) mask.set(c, r);
      }
    }
    std::vector<std::pair<int, int>> expected;
    for (int y = 0; y * size < rows; ++y) {
      for (int x = 0; x * size < columns; ++x) {
        const FeatureRect block{static_cast<std::uint16_t>(x * size),
                                static_cast<std::uint16_t>(y * size),
                                static_cast<std::uint16_t>(x * size + size - 1),
                                static_cast<std::uint16_t>(y * size + size - 1)};
        if (mask.all_in_rect(block)) expected.emplace_back(x, y);
      }
    }
    std::vector<std::pair<int, int>> found;
    EXPECT_FALSE(mask.for_each_full_block(size, [&](int x, int y) {
      found.emplace_back(x, y);
      return false;
    }));
    ASSERT_EQ(found, expected) << columns << " x " << rows << " cells, blocks of " << size;
    if (!expected.empty()) {
      int visits = 0;
      EXPECT_TRUE(mask.for_each_full_block(size, [&](int, int) { return ++visits == 1; }));
      EXPECT_EQ(visits, 1) << "stops when the visitor says so";
    }
  }
  FeatureMask mask(8, 8);
  EXPECT_THROW(mask.for_each_full_block(3, [](int, int) { return false; }), std::invalid_argument);
  EXPECT_THROW(mask.for_each_full_block(128, [](int, int) { return false; }),
               std::invalid_argument);
}

TEST(FeatureMask, SetOperations) {
  FeatureMask a(70, 3);
  FeatureMask b(70, 3);
  a.set(1, 0);
  a.set(65, 2);
  b.set(65, 2);
  b.set(69, 1);
  EXPECT_TRUE(a.intersects(b));
  FeatureMask both = a;
  both &= b;
  EXPECT_EQ(both.count(), 1U);
  FeatureMask either = a;
  either |= b;
  EXPECT_EQ(either.count(), 3U);
  either.subtract(b);
  EXPECT_EQ(either, [] {
    FeatureMask m(70, 3);
    m.set(1, 0);
    return m;
  }());
  EXPECT_THROW(a |= FeatureMask(64, 3), std::invalid_argument);
}

TEST(FeatureMask, ImageRoundTrip) {
  test::PropertyRun run(20);
  for (int i = 0; i < run.iterations(); ++i) {
    const FeatureMask mask = random_mask(run.rng(), 64, 64);
    EXPECT_EQ(FeatureMask::from_image(mask.to_image()), mask);
  }
  EXPECT_THROW(FeatureMask(0, 4), std::invalid_argument);
  EXPECT_THROW(FeatureMask::from_image(cv::Mat(4, 4, CV_16UC1)), std::invalid_argument);
}

}  // namespace
}  // namespace safecell
