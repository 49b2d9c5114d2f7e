#include "safecell/controller/host/system_entropy.hpp"

#include <sys/random.h>

namespace safecell {

bool SystemEntropy::draw(std::uint64_t& value) noexcept {
  // GRND_NONBLOCK: the cycle never waits for the pool; a short read is a failure, not a retry.
  std::uint64_t bits = 0;
  if (getrandom(&bits, sizeof bits, GRND_NONBLOCK) != static_cast<ssize_t>(sizeof bits)) {
    return false;
  }
  value = bits;
  return true;
}

}  // namespace safecell
