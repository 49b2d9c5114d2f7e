#pragma once
// The controller core's source of session challenges: the controller's own contribution to every
// session it opens, so that no recording of an earlier session can open one (protocol/SECURITY.md,
// "The session start"). What a challenge must be is fresh, not secret: a value this controller
// has never given out before, across restarts too. Backends: getrandom(2) on Linux
// (controller/host), a hardware random number generator on a target that has one, else
// BootCounterEntropy (a boot counter kept in non-volatile memory).
// Thread context: the controller's cycle (or link) task; must not block or allocate.

#include <cstdint>

namespace safecell {

class EntropyPort {
 public:
  EntropyPort() = default;
  EntropyPort(const EntropyPort&) = delete;
  EntropyPort& operator=(const EntropyPort&) = delete;

  // Writes 64 fresh bits into `value`. False when the source failed or is used up: the
  // controller then opens no session (it answers no opening).
  virtual bool draw(std::uint64_t& value) noexcept = 0;

 protected:
  ~EntropyPort() = default;
};

}  // namespace safecell
