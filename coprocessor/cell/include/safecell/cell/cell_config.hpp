#pragma once
// The cell description as read from a cell file: what the C-space grid and (in later issues) the
// robot, cameras and obstacles are built from. Every value remembers the line it came from, so a
// value refused later can still be named in the file.

#include <string>
#include <vector>

namespace safecell {

struct SourceLine {
  std::string source;  // file path, or "built-in default cell"
  int line = 0;        // 1-based; 0 when unknown
};

struct JointConfig {
  std::string name;
  double lo_deg = 0.0;
  double hi_deg = 0.0;
  double l_m = 0.0;
  bool discretised = true;
  SourceLine range_at;
  SourceLine l_at;
};

struct CellConfig {
  std::string name;
  std::string source;
  double m_max_m = 0.0;
  SourceLine m_max_at;
  std::vector<JointConfig> joints;
  SourceLine joints_at;
};

}  // namespace safecell
