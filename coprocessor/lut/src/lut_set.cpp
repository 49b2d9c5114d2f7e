#include "safecell/lut/lut_set.hpp"

namespace safecell {

const char* to_string(LutSource source) {
  switch (source) {
    case LutSource::kModel:
      return "model";
    case LutSource::kRecorded:
      return "recorded";
  }
  return "unknown";
}

}  // namespace safecell
