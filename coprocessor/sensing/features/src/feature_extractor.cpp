#include "safecell/features/feature_extractor.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "exact_divisor.hpp"
#include "image_checks.hpp"
#include "row_kernels.hpp"
#include "safecell/features/noise_cut.hpp"

namespace safecell {
namespace {

using row_kernels::kBlock;
using row_kernels::kMaxPartialRows;

constexpr int kRingRows = 3;

int round_up_to_block(int count) { return (count + kBlock - 1) / kBlock * kBlock; }

std::int64_t pixels_per_cell(const FeatureGrid& grid) {
  return std::int64_t{grid.cell_width_px()} * grid.cell_height_px();
}

std::uint8_t clamped_to_feature(std::int64_t value) {
  return static_cast<std::uint8_t>(std::min<std::int64_t>(value, 255));
}

// The contrast feature of every (max, min), at contrast_index(max, min): round(255 span /
// (max + min)), ties up, 0 when max + min = 0; looked up, not divided, once per cell.
using ContrastTable = std::array<std::uint8_t, std::size_t{256} * 256>;

std::size_t contrast_index(int maximum, int minimum) {
  return static_cast<std::size_t>(maximum) * 256 + static_cast<std::size_t>(minimum);
}

const ContrastTable& contrast_table() {
  static const ContrastTable table = [] {
    ContrastTable entries{};
    for (int maximum = 1; maximum < 256; ++maximum) {
      for (int minimum = 0; minimum <= maximum; ++minimum) {
        const int brightness = maximum + minimum;
        entries[contrast_index(maximum, minimum)] = static_cast<std::uint8_t>(
            (2 * 255 * (maximum - minimum) + brightness) / (2 * brightness));
      }
    }
    return entries;
  }();
  return table;
}

bool fits(const FeatureImages& images, const FeatureGrid& grid) {
  if (images.grid != grid) return false;
  return std::all_of(images.planes.begin(), images.planes.end(), [&](const cv::Mat& plane) {
    return plane.type() == CV_8UC1 && plane.rows == grid.rows() && plane.cols == grid.columns();
  });
}

}  // namespace

class FeatureExtractor::Pass {
 public:
  Pass(const FeatureGrid& grid, std::uint8_t noise_cut_mask);
  void run(const cv::Mat& frame, FeatureImages& images);

 private:
  template <typename T>
  T* ring_row(std::vector<T>& ring, int row) const;
  void smooth_frame_row(const cv::Mat& frame, int row);
  void add_row(int y);
  void reset_columns();
  void reset_cells();
  void fold_columns_into_cells();
  void write_cell_row(int cell_row, FeatureImages& images) const;

  FeatureGrid grid_;
  int smoothed_count_;      // entries of a smoothed row computed: columns -1 .. width, rounded up
  int column_count_;        // entries of a per-column row computed: the width, rounded up
  std::size_t row_length_;  // every scratch row: smoothed_count_ and a block of slack
  std::uint8_t noise_cut_mask_;
  // Ring buffers of three rows (row k in slot k mod 3; rows outside the frame are its edge
  // rows): the noise-cut frame rows with their edges replicated (entry i is column
  // clamp(i - 2)), and the LoG's state, the rows smoothed along (H) and then also across (S)
  // (entry i is column i - 1).
  std::vector<std::uint8_t> padded_rows_;
  std::vector<std::int16_t> smoothed_along_;
  std::vector<std::int16_t> smoothed_;
  // Per-column partial sums over the last rows (at most kMaxPartialRows) ...
  std::vector<std::uint16_t> column_sum_;
  std::vector<std::uint32_t> column_square_sum_;
  std::vector<std::uint8_t> column_min_;
  std::vector<std::uint8_t> column_max_;
  std::vector<std::uint16_t> column_log_sum_;
  int partial_rows_ = 0;
  // ... folded into the cells of the current cell row: their statistics over the rows so far.
  std::vector<std::int64_t> cell_sum_;
  std::vector<std::int64_t> cell_square_sum_;
  std::vector<std::int64_t> cell_log_sum_;
  std::vector<std::uint8_t> cell_min_;
  std::vector<std::uint8_t> cell_max_;
  // The scalings' divisors, fixed by the cell size.
  ExactDivisor average_divisor_;
  ExactDivisor variance_divisor_;
  ExactDivisor edge_count_divisor_;
};

FeatureExtractor::Pass::Pass(const FeatureGrid& grid, std::uint8_t noise_cut_mask)
    : grid_(grid),
      smoothed_count_(round_up_to_block(grid.image_width_px() + 2)),
      column_count_(round_up_to_block(grid.image_width_px())),
      row_length_(static_cast<std::size_t>(smoothed_count_ + kBlock)),
      noise_cut_mask_(noise_cut_mask),
      padded_rows_(kRingRows * row_length_, 0),
      smoothed_along_(kRingRows * row_length_, 0),
      smoothed_(kRingRows * row_length_, 0),
      column_sum_(row_length_, 0),
      column_square_sum_(row_length_, 0),
      column_min_(row_length_, 0),
      column_max_(row_length_, 0),
      column_log_sum_(row_length_, 0),
      cell_sum_(static_cast<std::size_t>(grid.columns())),
      cell_square_sum_(static_cast<std::size_t>(grid.columns())),
      cell_log_sum_(static_cast<std::size_t>(grid.columns())),
      cell_min_(static_cast<std::size_t>(grid.columns())),
      cell_max_(static_cast<std::size_t>(grid.columns())),
      average_divisor_(2 * pixels_per_cell(grid)),
      variance_divisor_(pixels_per_cell(grid) * pixels_per_cell(grid) * kVarianceDivisor),
      edge_count_divisor_(pixels_per_cell(grid) * kEdgeCountDivisor) {}

void FeatureExtractor::Pass::run(const cv::Mat& frame, FeatureImages& images) {
  // Rows -2 .. 1 make S(-1) and S(0); the S of rows -3 and -2 they also make are never read.
  for (int row = -2; row <= 1; ++row) smooth_frame_row(frame, row);
  const int cell_height_px = grid_.cell_height_px();
  for (int cell_row = 0; cell_row < grid_.rows(); ++cell_row) {
    reset_cells();
    reset_columns();
    for (int y = cell_row * cell_height_px; y < (cell_row + 1) * cell_height_px; ++y) {
      smooth_frame_row(frame, y + 2);  // S(y + 1), the last row the LoG of row y needs
      add_row(y);                      // row y's padded copy is still in the ring
      if (partial_rows_ == kMaxPartialRows) fold_columns_into_cells();
    }
    if (partial_rows_ > 0) fold_columns_into_cells();
    write_cell_row(cell_row, images);
  }
}

template <typename T>
T* FeatureExtractor::Pass::ring_row(std::vector<T>& ring, int row) const {
  const int slot = (row % kRingRows + kRingRows) % kRingRows;
  return ring.data() + static_cast<std::size_t>(slot) * row_length_;
}

// The padded, noise-cut frame row, H(row) and S(row - 1); rows outside the frame are its edge
// rows.
void FeatureExtractor::Pass::smooth_frame_row(const cv::Mat& frame, int row) {
  const std::uint8_t* pixels = frame.ptr<std::uint8_t>(std::clamp(row, 0, frame.rows - 1));
  const int width = frame.cols;
  std::uint8_t* padded = ring_row(padded_rows_, row);
  row_kernels::copy_cut(pixels, padded + 2, noise_cut_mask_, width);
  padded[0] = padded[2];
  padded[1] = padded[2];
  padded[width + 2] = padded[width + 1];
  padded[width + 3] = padded[width + 1];
  row_kernels::smooth_new_row(padded, ring_row(smoothed_along_, row - 2),
                              ring_row(smoothed_along_, row - 1), ring_row(smoothed_along_, row),
                              ring_row(smoothed_, row - 1), smoothed_count_);
}

void FeatureExtractor::Pass::add_row(int y) {
  row_kernels::add_row_to_columns(ring_row(padded_rows_, y) + 2, ring_row(smoothed_, y - 1),
                                  ring_row(smoothed_, y), ring_row(smoothed_, y + 1),
                                  column_sum_.data(), column_square_sum_.data(), column_min_.data(),
                                  column_max_.data(), column_log_sum_.data(), column_count_);
  ++partial_rows_;
}

void FeatureExtractor::Pass::reset_columns() {
  std::fill(column_sum_.begin(), column_sum_.end(), 0);
  std::fill(column_square_sum_.begin(), column_square_sum_.end(), 0);
  std::fill(column_min_.begin(), column_min_.end(), 255);
  std::fill(column_max_.begin(), column_max_.end(), 0);
  std::fill(column_log_sum_.begin(), column_log_sum_.end(), 0);
  partial_rows_ = 0;
}

void FeatureExtractor::Pass::reset_cells() {
  std::fill(cell_sum_.begin(), cell_sum_.end(), 0);
  std::fill(cell_square_sum_.begin(), cell_square_sum_.end(), 0);
  std::fill(cell_log_sum_.begin(), cell_log_sum_.end(), 0);
  std::fill(cell_min_.begin(), cell_min_.end(), 255);
  std::fill(cell_max_.begin(), cell_max_.end(), 0);
}

// The column rows are read up to kFoldChunk - 1 entries past the image's width: they are
// row_length_ long, at least a block more than the width.
void FeatureExtractor::Pass::fold_columns_into_cells() {
  static_assert(row_kernels::kFoldChunk <= kBlock);
  row_kernels::fold_columns(column_sum_.data(), column_square_sum_.data(), column_log_sum_.data(),
                            column_min_.data(), column_max_.data(), grid_.cell_width_px(),
                            grid_.columns(), cell_sum_.data(), cell_square_sum_.data(),
                            cell_log_sum_.data(), cell_min_.data(), cell_max_.data());
  reset_columns();
}

// The scalings of feature_images.hpp, n the pixels per cell: average (2 sum + n) / 2n, variance
// (n sum(p^2) - sum^2) / (16 n^2), edge count sum(|LoG|) / 4n, each clamped to 255.
void FeatureExtractor::Pass::write_cell_row(int cell_row, FeatureImages& images) const {
  auto* average = images[Feature::kAverage].ptr<std::uint8_t>(cell_row);
  auto* variance = images[Feature::kVariance].ptr<std::uint8_t>(cell_row);
  auto* span = images[Feature::kSpan].ptr<std::uint8_t>(cell_row);
  auto* contrast = images[Feature::kContrast].ptr<std::uint8_t>(cell_row);
  auto* edge_count = images[Feature::kEdgeCount].ptr<std::uint8_t>(cell_row);
  const std::int64_t n = pixels_per_cell(grid_);
  const ContrastTable& contrasts = contrast_table();
  for (std::size_t column = 0; column < cell_sum_.size(); ++column) {
    const std::int64_t sum = cell_sum_[column];
    average[column] = clamped_to_feature(average_divisor_.quotient(2 * sum + n));
    variance[column] =
        clamped_to_feature(variance_divisor_.quotient(n * cell_square_sum_[column] - sum * sum));
    span[column] = static_cast<std::uint8_t>(cell_max_[column] - cell_min_[column]);
    contrast[column] = contrasts[contrast_index(cell_max_[column], cell_min_[column])];
    edge_count[column] = clamped_to_feature(edge_count_divisor_.quotient(cell_log_sum_[column]));
  }
}

FeatureExtractor::FeatureExtractor(const FeatureGrid& grid, int noise_bits)
    : grid_(grid),
      noise_bits_(noise_bits),
      pass_(std::make_unique<Pass>(grid, noise_cut_mask(noise_bits))) {}

FeatureExtractor::~FeatureExtractor() = default;
FeatureExtractor::FeatureExtractor(FeatureExtractor&&) noexcept = default;
FeatureExtractor& FeatureExtractor::operator=(FeatureExtractor&&) noexcept = default;

FeatureImages FeatureExtractor::extract(const cv::Mat& frame) {
  FeatureImages images(grid_);
  extract(frame, images);
  return images;
}

void FeatureExtractor::extract(const cv::Mat& frame, FeatureImages& images) {
  check_gray_image_of_size(frame, cv::Size(grid_.image_width_px(), grid_.image_height_px()),
                           "frame", "the feature grid's image size");
  if (!fits(images, grid_)) images = FeatureImages(grid_);
  pass_->run(frame, images);
}

}  // namespace safecell
