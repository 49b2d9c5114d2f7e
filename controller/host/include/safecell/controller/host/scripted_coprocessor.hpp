#pragma once
// The coprocessor's sending side, made of the controller's own codec (nanopb, the safety layer,
// the map run coding): sealed frames for tests and benchmarks of the controller that run without
// the coprocessor's code (under qemu-aarch64 too). Hosted; throws std::logic_error when a message
// does not fit a frame (a caller's mistake).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "safecell/cspace/cspace_grid.hpp"
#include "safecell/protocol/frame_checker.hpp"
#include "safecell/v1/message.nanopb.h"

namespace safecell {

class ScriptedCoprocessor {
 public:
  using Frame = std::vector<std::uint8_t>;

  // opening: the handshake's opening number (the session id is it XOR the controller's
  // challenge).
  ScriptedCoprocessor(std::uint64_t grid_fingerprint, std::uint64_t lut_fingerprint,
                      std::uint64_t opening, CellIndex cells);

  // The session's opening handshake, sent at `now_ns`.
  Frame handshake(std::uint64_t now_ns);
  // The answer to the controller's challenge (challenge_in() of its reply to the opening). The
  // frames sealed after it are the session's.
  Frame answer(std::uint64_t challenge, std::uint64_t now_ns);
  // The challenge a controller's handshake frame carries; 0 when the frame is none, a refusal,
  // or does not open.
  static std::uint64_t challenge_in(const Frame& frame);
  // The session id once answer() was called.
  std::uint64_t session() const { return sealer_.endpoints().session_id; }
  // Every chunk of one map update, sealed at `now_ns` with the capture time `capture_ns`: a delta
  // from `base` (whose version is base_version), or a keyframe when base is null. Each chunk
  // carries at most run_bytes of runs (the protocol's most by default). wrong_hash: the hash of
  // another map, a sender fault the receiver must catch.
  std::vector<Frame> update(const std::uint64_t* base, std::uint64_t base_version,
                            const std::uint64_t* target, std::uint64_t version,
                            std::uint64_t capture_ns, std::uint64_t now_ns, bool wrong_hash = false,
                            std::size_t run_bytes = kMaxRunBytes);

  // The speed reduction (MapChunk.speed_reduction_permille) the updates from now on carry, bound
  // into their hash as the coprocessor binds it. 0 (none) at the start.
  void set_speed_reduction_permille(std::uint32_t permille) { speed_reduction_ = permille; }
  // How many of the cell's kCameras the updates from now on say are healthy (all at the start).
  void set_healthy_cameras(std::uint32_t healthy) { healthy_cameras_ = healthy; }

  static constexpr std::uint32_t kCameras = 4;  // the scripted cell's cameras

  // A payload of the caller's own making (a hostile or future sender's message), sealed as the
  // next data frame.
  Frame seal_payload(const std::uint8_t* payload, std::size_t size, std::uint64_t now_ns,
                     std::uint64_t capture_ns);

  static constexpr std::size_t kMaxRunBytes = sizeof(safecell_v1_MapChunk{}.runs.bytes);

 private:
  // A handshake frame of the opening (challenge 0) or the answer to `challenge`.
  Frame handshake_frame(std::uint64_t challenge, std::uint64_t now_ns);
  Frame seal(std::uint64_t now_ns, std::uint64_t capture_ns, std::uint8_t flags = 0);

  std::uint64_t grid_;
  std::uint64_t lut_;
  std::uint64_t opening_;
  CellIndex cells_;
  std::uint32_t speed_reduction_ = 0;
  std::uint32_t healthy_cameras_ = kCameras;
  FrameSealer sealer_;
  safecell_v1_Message message_{};
};

}  // namespace safecell
