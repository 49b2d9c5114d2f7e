#include "error_text.hpp"

#include <array>
#include <charconv>
#include <cmath>

namespace safecell {

std::string number_text(double value) {
  if (std::isnan(value)) return "nan";  // whatever its sign bit
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string matrix_text(const Eigen::MatrixXd& matrix) {
  std::string text = "[";
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    text += r == 0 ? "[" : ", [";
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) {
      text += (c == 0 ? "" : ", ") + number_text(matrix(r, c));
    }
    text += "]";
  }
  return text + "]";
}

std::string point_text(const Eigen::VectorXd& point) {
  std::string text = "(";
  for (Eigen::Index i = 0; i < point.size(); ++i) {
    text += (i == 0 ? "" : ", ") + number_text(point[i]);
  }
  return text + ")";
}

std::string one_line(const std::string& text) {
  std::string line;
  for (const char c : text) {
    const bool is_break = c == '\n' || c == '\r';
    if (!is_break) line += c;
    if (is_break && !line.empty() && line.back() != ' ') line += ' ';
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

}  // namespace safecell
