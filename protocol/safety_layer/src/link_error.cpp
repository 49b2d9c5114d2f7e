#include "safecell/protocol/link_error.hpp"

namespace safecell {

const char* to_string(LinkError error) noexcept {
  switch (error) {
    case LinkError::kNone:
      return "none";
    case LinkError::kCorruption:
      return "corruption";
    case LinkError::kRepetition:
      return "repetition";
    case LinkError::kIncorrectSequence:
      return "incorrect sequence";
    case LinkError::kLoss:
      return "loss";
    case LinkError::kDelay:
      return "delay";
    case LinkError::kInsertion:
      return "insertion";
    case LinkError::kMasquerade:
      return "masquerade";
    case LinkError::kAddressing:
      return "addressing";
    case LinkError::kWrongConfiguration:
      return "wrong configuration";
    case LinkError::kTimeout:
      return "timeout";
  }
  return "unknown link error";
}

}  // namespace safecell
