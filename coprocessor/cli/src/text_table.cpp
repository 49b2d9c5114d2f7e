#include "safecell/cli/text_table.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace safecell {

TextTable::TextTable(std::vector<std::pair<std::string, Align>> columns)
    : columns_(std::move(columns)) {}

void TextTable::add_row(std::vector<std::string> cells) {
  if (cells.size() != columns_.size()) {
    throw std::invalid_argument("TextTable row has " + std::to_string(cells.size()) +
                                " cells, expected " + std::to_string(columns_.size()));
  }
  rows_.push_back(std::move(cells));
}

void TextTable::print(std::ostream& out) const {
  std::vector<std::size_t> widths;
  for (const auto& column : columns_) widths.push_back(column.first.size());
  for (const auto& row : rows_) {
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  }
  const auto print_row = [&](const auto& cell_at) {
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      const bool left = columns_[c].second == Align::kLeft;
      const bool last = c + 1 == columns_.size();
      // No padding after the last column: lines end without trailing blanks.
      const int width = left && last ? 0 : static_cast<int>(widths[c]);
      out << (c == 0 ? "" : "  ") << (left ? std::left : std::right) << std::setw(width)
          << cell_at(c);
    }
    out << std::right << '\n';
  };
  print_row([&](std::size_t c) { return columns_[c].first; });
  for (const auto& row : rows_) print_row([&](std::size_t c) { return row[c]; });
}

std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

std::string grouped(unsigned long long value) {
  std::string digits = std::to_string(value);
  for (auto at = static_cast<std::ptrdiff_t>(digits.size()) - 3; at > 0; at -= 3) {
    digits.insert(static_cast<std::size_t>(at), ",");
  }
  return digits;
}

std::string hex64(std::uint64_t value) {
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace safecell
