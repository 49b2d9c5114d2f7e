#pragma once
// Session challenges from the Linux kernel's random number generator (getrandom(2)): fresh across
// restarts with no state of its own. Hosted (the core's EntropyPort on Linux).
// Thread context: the controller's cycle task. Does not block once the kernel's pool is
// initialised (at boot); before that, and on any error, draw() fails and no session opens.

#include <cstdint>

#include "safecell/controller/entropy_port.hpp"

namespace safecell {

class SystemEntropy final : public EntropyPort {
 public:
  SystemEntropy() = default;
  bool draw(std::uint64_t& value) noexcept override;
};

}  // namespace safecell
