#include "safecell/base/status.hpp"

namespace safecell {

const char* to_string(Status status) noexcept {
  switch (status) {
    case Status::kOk:
      return "ok";
    case Status::kInvalidArgument:
      return "invalid argument";
    case Status::kOutOfRange:
      return "out of range";
    case Status::kCapacityExceeded:
      return "capacity exceeded";
    case Status::kOverflow:
      return "overflow";
    case Status::kEmpty:
      return "empty";
  }
  return "unknown status";
}

}  // namespace safecell
