#pragma once
// Values as error messages show them: the shortest text that reads back as the same double.

#include <Eigen/Core>
#include <string>

namespace safecell {

std::string number_text(double value);

// "[[1, 0, 0], [0, 1, 0]]", row by row.
std::string matrix_text(const Eigen::MatrixXd& matrix);

// "(u, v)", "(x, y, z)".
std::string point_text(const Eigen::VectorXd& point);

// The text with its line breaks turned into spaces (OpenCV's messages span lines).
std::string one_line(const std::string& text);

}  // namespace safecell
