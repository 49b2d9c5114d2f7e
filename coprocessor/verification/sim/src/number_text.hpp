#pragma once
// A number as error messages show it (internal to the sim module).

#include <sstream>
#include <string>

namespace safecell {

inline std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace safecell
