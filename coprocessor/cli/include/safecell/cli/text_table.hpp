#pragma once
// Aligned plain-text tables for terminal reports.

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace safecell {

class TextTable {
 public:
  enum class Align { kLeft, kRight };

  explicit TextTable(std::vector<std::pair<std::string, Align>> columns);

  // Precondition: one cell per column (checked, throws std::invalid_argument).
  void add_row(std::vector<std::string> cells);
  void print(std::ostream& out) const;

 private:
  std::vector<std::pair<std::string, Align>> columns_;
  std::vector<std::vector<std::string>> rows_;
};

// "%.*f" without the C formatting API at call sites.
std::string fixed(double value, int decimals);
// 165375 -> "165,375".
std::string grouped(unsigned long long value);
// A 64-bit fingerprint as "0x" and 16 hex digits (JSON numbers lose precision above 2^53).
std::string hex64(std::uint64_t value);

}  // namespace safecell
