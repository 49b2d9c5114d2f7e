#include "safecell/features/feature_mask.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "safecell/compute/cpu_clones.hpp"

namespace safecell {
namespace {

constexpr int kMaxSide = 65535;

// Bits first..last (0..63, inclusive) of a word.
std::uint64_t bit_span(int first, int last) {
  const std::uint64_t upto_last =
      last == 63 ? ~std::uint64_t{0} : (std::uint64_t{1} << (last + 1)) - 1;
  return upto_last & ~((std::uint64_t{1} << first) - 1);
}

}  // namespace

FeatureMask::FeatureMask(int columns, int rows)
    : columns_(columns), rows_(rows), words_per_row_((columns + 63) / 64) {
  if (columns < 1 || rows < 1 || columns > kMaxSide || rows > kMaxSide) {
    throw std::invalid_argument("feature mask size must be 1..65535 cells each way, got " +
                                std::to_string(columns) + " x " + std::to_string(rows));
  }
  words_.assign(static_cast<std::size_t>(rows) * static_cast<std::size_t>(words_per_row_), 0);
}

FeatureMask FeatureMask::from_image(const cv::Mat& mask) {
  if (mask.empty() || mask.type() != CV_8UC1) {
    throw std::invalid_argument("a feature mask image must be a non-empty CV_8UC1 image");
  }
  FeatureMask result(mask.cols, mask.rows);
  for (int row = 0; row < mask.rows; ++row) {
    const auto* pixels = mask.ptr<std::uint8_t>(row);
    for (int column = 0; column < mask.cols; ++column) {
      if (pixels[column] != 0) result.set(column, row);
    }
  }
  return result;
}

namespace {

// Calls apply(word, bits) for the bits of every word the rectangle (clipped to the mask) covers,
// until it returns false; returns whether it never did.
template <typename Mask, typename Apply>
bool for_rect_words(Mask& mask, const FeatureRect& rect, Apply apply) {
  const int col1 = std::min<int>(rect.col1, mask.columns() - 1);
  const int row1 = std::min<int>(rect.row1, mask.rows() - 1);
  if (rect.col0 > col1 || rect.row0 > row1) return true;
  const int first_word = rect.col0 >> 6;
  const int last_word = col1 >> 6;
  if (first_word == last_word) {  // the common case: a grid of up to 64 columns
    const std::uint64_t bits = bit_span(rect.col0 & 63, col1 & 63);
    for (int row = rect.row0; row <= row1; ++row) {
      if (!apply(mask.row_words(row)[first_word], bits)) return false;
    }
    return true;
  }
  for (int row = rect.row0; row <= row1; ++row) {
    for (int word = first_word; word <= last_word; ++word) {
      const int first = word == first_word ? rect.col0 & 63 : 0;
      const int last = word == last_word ? col1 & 63 : 63;
      if (!apply(mask.row_words(row)[word], bit_span(first, last))) return false;
    }
  }
  return true;
}

}  // namespace

void FeatureMask::set_rect(const FeatureRect& rect) {
  for_rect_words(*this, rect, [](std::uint64_t& word, std::uint64_t bits) {
    word |= bits;
    return true;
  });
}

void FeatureMask::reset_rect(const FeatureRect& rect) {
  for_rect_words(*this, rect, [](std::uint64_t& word, std::uint64_t bits) {
    word &= ~bits;
    return true;
  });
}

bool FeatureMask::all_in_rect(const FeatureRect& rect) const {
  return for_rect_words(*this, rect, [](const std::uint64_t& word, std::uint64_t bits) {
    return (word & bits) == bits;
  });
}

bool FeatureMask::any_in_rect(const FeatureRect& rect) const {
  // for_rect_words stops at the first word that has a bit of the rectangle set.
  return !for_rect_words(*this, rect, [](const std::uint64_t& word, std::uint64_t bits) {
    return (word & bits) == 0;
  });
}

std::uint64_t FeatureMask::block_start_bits(int size) {
  if (size < 1 || size > 64 || !std::has_single_bit(static_cast<unsigned>(size))) {
    throw std::invalid_argument("block size must be a power of two 1..64, got " +
                                std::to_string(size));
  }
  std::uint64_t bits = 0;
  for (int bit = 0; bit < 64; bit += size) bits |= std::uint64_t{1} << bit;
  return bits;
}

void FeatureMask::clear() { std::fill(words_.begin(), words_.end(), 0); }

SAFECELL_CPU_CLONES std::size_t FeatureMask::count() const {
  std::size_t total = 0;
  for (const std::uint64_t word : words_) total += static_cast<std::size_t>(std::popcount(word));
  return total;
}

bool FeatureMask::any() const {
  return std::any_of(words_.begin(), words_.end(), [](std::uint64_t word) { return word != 0; });
}

bool FeatureMask::intersects(const FeatureMask& other) const {
  check_same_shape(other);
  for (std::size_t i = 0; i < words_.size(); ++i) {
    if ((words_[i] & other.words_[i]) != 0) return true;
  }
  return false;
}

FeatureMask& FeatureMask::operator|=(const FeatureMask& other) {
  check_same_shape(other);
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] |= other.words_[i];
  return *this;
}

FeatureMask& FeatureMask::operator&=(const FeatureMask& other) {
  check_same_shape(other);
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= other.words_[i];
  return *this;
}

FeatureMask& FeatureMask::subtract(const FeatureMask& other) {
  check_same_shape(other);
  for (std::size_t i = 0; i < words_.size(); ++i) words_[i] &= ~other.words_[i];
  return *this;
}

cv::Mat FeatureMask::to_image() const {
  cv::Mat image(rows_, columns_, CV_8UC1, cv::Scalar(0));
  for (int row = 0; row < rows_; ++row) {
    auto* pixels = image.ptr<std::uint8_t>(row);
    for (int column = 0; column < columns_; ++column) {
      if (test(column, row)) pixels[column] = 255;
    }
  }
  return image;
}

std::vector<FeatureRect> FeatureMask::rectangles() const {
  std::vector<FeatureRect> rects;
  append_rectangles(rects);
  return rects;
}

void FeatureMask::append_rectangles(std::vector<FeatureRect>& out) const {
  // Scratch per thread: the table build calls this for every C-space cell, part and camera, and
  // fresh vectors each time cost more than the scan.
  thread_local std::vector<FeatureRect> open;  // rectangles that reach the previous row
  thread_local std::vector<FeatureRect> next;
  open.clear();
  const auto words_per_row = static_cast<std::size_t>(words_per_row_);
  for (int row = 0; row < rows_; ++row) {
    const std::uint64_t* words = row_words(row);
    // A row like the one above (common in silhouettes, which are unions of rectangles): its runs
    // are those of the open rectangles, each of which grows by this row.
    if (row > 0 && std::equal(words, words + words_per_row, row_words(row - 1))) {
      for (FeatureRect& rect : open) rect.row1 = static_cast<std::uint16_t>(row);
      continue;
    }
    next.clear();
    // Runs of set bits, found a word at a time; a run may continue into the next word.
    int run_start = -1;
    const auto close_run = [&](int end) {
      const auto col0 = static_cast<std::uint16_t>(run_start);
      const auto col1 = static_cast<std::uint16_t>(end - 1);
      const auto above = std::find_if(open.begin(), open.end(), [&](const FeatureRect& rect) {
        return rect.col0 == col0 && rect.col1 == col1;
      });
      if (above != open.end()) {
        FeatureRect grown = *above;
        grown.row1 = static_cast<std::uint16_t>(row);
        next.push_back(grown);
        open.erase(above);
      } else {
        const auto r = static_cast<std::uint16_t>(row);
        next.push_back(FeatureRect{col0, r, col1, r});
      }
      run_start = -1;
    };
    for (int word = 0; word < words_per_row_; ++word) {
      std::uint64_t bits = words[word];
      int offset = 0;  // bits below `offset` of this word are handled
      while (offset < 64) {
        if (run_start < 0) {
          if (bits == 0) break;
          const int zeros = std::countr_zero(bits);
          run_start = word * 64 + offset + zeros;
          bits >>= zeros;
          offset += zeros;
        }
        const int ones = std::countr_one(bits);
        offset += ones;
        if (offset >= 64) break;  // the run may go on in the next word
        bits >>= ones;
        close_run(word * 64 + offset);
      }
    }
    if (run_start >= 0) close_run(std::min(columns_, words_per_row_ * 64));
    out.insert(out.end(), open.begin(), open.end());  // those that end at the row above
    open.swap(next);
  }
  out.insert(out.end(), open.begin(), open.end());
}

void FeatureMask::check_same_shape(const FeatureMask& other) const {
  if (other.columns_ != columns_ || other.rows_ != rows_) {
    throw std::invalid_argument("feature masks of different sizes: " + std::to_string(columns_) +
                                " x " + std::to_string(rows_) + " and " +
                                std::to_string(other.columns_) + " x " +
                                std::to_string(other.rows_));
  }
}

void FeatureMask::dilate(int columns, int rows) {
  const auto words = static_cast<std::size_t>(words_per_row_);
  const int spare = words_per_row_ * 64 - columns_;  // unused bits at the end of each row
  const std::uint64_t last_word_bits = ~std::uint64_t{0} >> spare;
  std::vector<std::uint64_t> row(words);
  for (int r = 0; r < rows_; ++r) {
    std::uint64_t* out = row_words(r);
    for (int step = 0; step < columns; ++step) {
      std::copy(out, out + words, row.begin());
      for (std::size_t w = 0; w < words; ++w) {
        std::uint64_t grown = row[w] | (row[w] << 1) | (row[w] >> 1);
        if (w > 0) grown |= row[w - 1] >> 63;
        if (w + 1 < words) grown |= row[w + 1] << 63;
        out[w] = grown;
      }
      out[words - 1] &= last_word_bits;
    }
  }
  const std::vector<std::uint64_t> grown_rows = words_;
  for (int r = 0; r < rows_; ++r) {
    std::uint64_t* out = row_words(r);
    for (int from = std::max(0, r - rows); from <= std::min(rows_ - 1, r + rows); ++from) {
      const std::uint64_t* in = grown_rows.data() + static_cast<std::size_t>(from) * words;
      for (std::size_t w = 0; w < words; ++w) out[w] |= in[w];
    }
  }
}

}  // namespace safecell
