#include "safecell/tables/cell_to_pixels_table.hpp"

#include <stdexcept>
#include <string>

namespace safecell {
namespace {

struct OwnedArrays {
  std::vector<std::uint64_t> offsets;
  std::vector<FeatureRect> rects;
};

}  // namespace

CellToPixelsTable::CellToPixelsTable(int columns, int rows, std::vector<std::uint64_t> offsets,
                                     std::vector<FeatureRect> rects)
    : columns_(columns), rows_(rows) {
  auto owned = std::make_shared<OwnedArrays>(OwnedArrays{std::move(offsets), std::move(rects)});
  offsets_ = owned->offsets;
  rects_ = owned->rects;
  storage_ = std::move(owned);
  check();
}

CellToPixelsTable::CellToPixelsTable(int columns, int rows, std::span<const std::uint64_t> offsets,
                                     std::span<const FeatureRect> rects,
                                     std::shared_ptr<const void> storage)
    : columns_(columns),
      rows_(rows),
      offsets_(offsets),
      rects_(rects),
      storage_(std::move(storage)) {
  check();
}

void CellToPixelsTable::check() const {
  if (columns_ < 1 || rows_ < 1) throw std::invalid_argument("LUT-1: empty feature grid");
  if (offsets_.empty() || offsets_.front() != 0 || offsets_.back() != rects_.size()) {
    throw std::invalid_argument("LUT-1: the offsets do not span the rectangles");
  }
  for (std::size_t i = 1; i < offsets_.size(); ++i) {
    if (offsets_[i] < offsets_[i - 1]) {
      throw std::invalid_argument("LUT-1: offsets fall at cell " + std::to_string(i - 1));
    }
  }
  for (const auto& rect : rects_) {
    if (rect.col0 > rect.col1 || rect.row0 > rect.row1 || rect.col1 >= columns_ ||
        rect.row1 >= rows_) {
      throw std::invalid_argument("LUT-1: a rectangle leaves the " + std::to_string(columns_) +
                                  " x " + std::to_string(rows_) + " feature grid");
    }
  }
}

void CellToPixelsTable::add_to(CellIndex cell, FeatureMask& mask) const {
  for (const auto& rect : rects_of(cell)) mask.set_rect(rect);
}

std::uint64_t CellToPixelsTable::covered_pairs() const {
  std::uint64_t pairs = 0;
  for (const auto& rect : rects_) {
    pairs += std::uint64_t{rect.col1 - rect.col0 + 1U} * std::uint64_t{rect.row1 - rect.row0 + 1U};
  }
  return pairs;
}

FeatureMask CellToPixelsTable::mask_of(CellIndex cell) const {
  FeatureMask mask(columns_, rows_);
  add_to(cell, mask);
  return mask;
}

}  // namespace safecell
