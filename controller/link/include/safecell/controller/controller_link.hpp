#pragma once
// The controller's end of the link: the session with the coprocessor, the map updates it brings,
// and the joint stream (with the map acknowledgement) it sends back.
//
//   handshake   the coprocessor opens a session (handshake frames, implicit fingerprint 0); the
//               controller checks the protocol version, both fingerprints and the ids against its
//               own configuration, answers an opening with a fresh challenge from its
//               EntropyPort, and takes the session only from the answer that echoes its current
//               challenge (handshake.proto, protocol/SECURITY.md). Anything else (a recorded
//               opening's answer, a challenge given out to another opening or expired) is
//               refused as a repetition and leaves a session in place as it is. A new session
//               forgets the held map: no motion until a keyframe of the new session is verified.
//   data frames checked by the safety layer (frame_checker.hpp); map chunks go to the
//               MapStore; clock echoes are answered at once; stop requests are latched.
// Every detected communication error is counted and fed to the error latch (a second one within
// the window latches a stop until acknowledge()).
//
// Clocks: all `now_ns` are the controller's monotonic clock, and so are the frame times the
// coprocessor sends (it converts its own clock with the offset it measures by ClockEcho), so the
// data-age check needs no clock of the coprocessor's here.
// Thread context: the controller's cycle task; not synchronised. Real-time: no allocation; poll()
// does a bounded amount of work (ControllerLinkConfig::map_work_per_poll).

#include <cstddef>
#include <cstdint>

#include "safecell/controller/entropy_port.hpp"
#include "safecell/controller/link_port.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/protocol/error_latch.hpp"
#include "safecell/protocol/frame_checker.hpp"
#include "safecell/v1/message.nanopb.h"

namespace safecell {

struct ControllerLinkConfig {
  std::uint32_t controller_id = 2;
  std::uint32_t coprocessor_id = 1;
  std::uint64_t grid_fingerprint = 0;       // CspaceGrid::fingerprint() of the controller's grid
  std::uint64_t lut_fingerprint = 0;        // the LUTs the cell was commissioned with
  std::uint64_t watchdog_ns = 100'000'000;  // T_wd: no map update applied for longer stops
  std::uint64_t max_data_age_ns = 150'000'000;  // a frame's capture older than this is refused
  std::uint64_t max_clock_lead_ns = 5'000'000;  // the coprocessor's clock-offset uncertainty
  std::uint64_t latch_window_ns = kDefaultLatchWindowNs;
  // How long a challenge given out waits for its answer; a later answer is refused (the
  // coprocessor opens again and gets a new one).
  std::uint64_t challenge_lifetime_ns = 1'000'000'000;
  // The link's share of a control cycle, in MapStore work units (map_store.hpp; a frame read and
  // checked costs kWorkPerFrame): an update larger than that is applied over several cycles, and
  // the frames after it wait in the transport's buffer. Its measured age includes the delay.
  // The default keeps a slice near 5 us on a host core (safecell-controller-bench).
  std::uint32_t map_work_per_poll = 128;
  // Frames handled per poll() at most (1 .. kMaxFramesPerPoll).
  int max_frames_per_poll = 4;
};

// A frame read, its CRC and its checks, and its message decoded, in MapStore work units.
inline constexpr std::uint32_t kWorkPerFrame = 32;

// The joints of one control cycle, as the controller read them.
struct JointSample {
  std::uint32_t joint_count = 0;
  double position_rad[8]{};
  double velocity_rad_s[8]{};
  std::uint64_t read_time_ns = 0;  // controller clock
};

// Why the link does not allow motion now (kNone: it does).
enum class LinkBlock : std::uint8_t {
  kNone = 0,
  kNoSession,      // no handshake accepted yet
  kNoMap,          // session up, no keyframe verified yet
  kMapTooOld,      // no map update applied within T_wd
  kLatched,        // a second error within the window; needs acknowledge()
  kStopRequested,  // the coprocessor or an operator asked for a stop; needs acknowledge()
};

const char* to_string(LinkBlock block) noexcept;

// The cause of a stop request by name ("operator", "cameras", "watchdog"; "other"). Never null.
const char* fault_cause_name(safecell_v1_FaultCause cause) noexcept;

// What the cycle commanded, for the joint state.
struct MotionReport {
  safecell_v1_ControllerState state = safecell_v1_ControllerState_CONTROLLER_STATE_UNSPECIFIED;
  double speed_scale = 0.0;          // 0..1
  std::uint32_t critical_joint = 0;  // the joint deciding a slow-down or stop, from 1 (0: none)
  bool has_blocking_cell = false;    // the forbidden cell in its way, when there is one
  CellIndex blocking_cell = 0;
};

class ControllerLink {
 public:
  static constexpr int kMaxFramesPerPoll = 64;

  ControllerLink(const ControllerLinkConfig& config, LinkPort& port, MapStore& store,
                 EntropyPort& entropy) noexcept;

  // One slice: goes on with the map update in work, then handles the frames waiting on the port,
  // within config.map_work_per_poll and config.max_frames_per_poll (one frame always gets through
  // when no chunk is in work, so a budget below kWorkPerFrame still makes progress). Returns
  // false when the link is idle (the store has no work and the port had no frame left), true when
  // more may wait.
  bool poll(std::uint64_t now_ns) noexcept;

  // Sends this cycle's joint state and what the cycle did with it; it carries the held map's
  // version as the acknowledgement.
  void send_joint_state(const JointSample& joints, const MotionReport& motion,
                        std::uint64_t now_ns) noexcept;

  LinkBlock block(std::uint64_t now_ns) const noexcept;
  // Clears the error latch and a requested stop (an operator's acknowledgement).
  void acknowledge() noexcept;

  bool session_up() const noexcept { return session_up_; }
  // The session's id: the coprocessor's opening number XOR this controller's challenge.
  std::uint64_t session_id() const noexcept { return session_id_; }
  // Openings answered with a challenge, and answers refused for not echoing the current one.
  std::uint64_t challenges_given() const noexcept { return challenges_given_; }
  std::uint64_t stale_answers() const noexcept { return stale_answers_; }
  // The capture time of the held map's data (controller clock); 0 without a map.
  std::uint64_t map_capture_ns() const noexcept { return store_.capture_ns(); }
  // The held map's cameras: healthy ones (a status report may lower it) and the cell's count.
  std::uint32_t healthy_cameras() const noexcept { return healthy_cameras_; }
  std::uint32_t camera_count() const noexcept { return camera_count_; }
  // The speed scale the held map allows (MapChunk.speed_reduction_permille, bound into its hash):
  // 1 without a reduction, 0 for 1000 permille or more (a stop). The cycle commands no more.
  double separation_speed_limit() const noexcept {
    return speed_reduction_permille_ >= 1000
               ? 0.0
               : 1.0 - static_cast<double>(speed_reduction_permille_) * 1e-3;
  }
  const ErrorLatch& latch() const noexcept { return latch_; }
  const LinkFault& last_fault() const noexcept { return last_fault_; }
  MapRefusal last_map_refusal() const noexcept { return last_map_refusal_; }
  std::uint64_t updates_applied() const noexcept { return updates_applied_; }
  std::uint64_t updates_refused() const noexcept { return updates_refused_; }
  // Whole updates whose map differed from the sender's: the controller stops on each (SAFETY.md).
  std::uint64_t hash_mismatches() const noexcept { return hash_mismatches_; }
  // Updates found lost by the heartbeat that follows each (a repair asked for at once).
  std::uint64_t losses_repaired() const noexcept { return losses_repaired_; }
  // The coprocessor asked the robot stopped (a clean shutdown, its operator), until acknowledged.
  bool stop_requested() const noexcept { return stop_requested_; }
  safecell_v1_FaultCause stop_cause() const noexcept { return stop_cause_; }

 private:
  void handle_datagram(const std::uint8_t* data, std::size_t size, std::uint64_t now_ns) noexcept;
  void handle_handshake(const FrameView& frame, std::uint64_t now_ns) noexcept;
  // The challenge for an opening: the one given out to this opening while it is valid, else a
  // fresh one. False when the entropy source failed.
  bool challenge_for(std::uint64_t opening, std::uint64_t now_ns) noexcept;
  // True while the challenge given out last is unused, was given to `opening` and is not older
  // than its lifetime.
  bool challenge_pending(std::uint64_t opening, std::uint64_t now_ns) const noexcept;
  // Takes the session of the opening whose challenge was answered.
  void open_session(std::uint64_t now_ns) noexcept;
  // Sends the handshake answer to `opening`: this end's configuration, accepted or not, and the
  // challenge (0 in a refusal).
  void answer_handshake(std::uint64_t opening, bool accepted, std::uint64_t challenge,
                        std::uint64_t now_ns) noexcept;
  void handle_message(const FrameView& frame, std::uint64_t now_ns) noexcept;
  void handle_map_chunk(const safecell_v1_MapChunk& chunk, const FrameView& frame,
                        std::uint64_t now_ns) noexcept;
  void map_outcome(const MapOffer& offer, std::uint64_t now_ns) noexcept;
  // Asks the coprocessor for a repair from the held version (KeyframeRequest), counting every
  // update up to `through` as asked for.
  void request_repair(std::uint64_t through, std::uint64_t now_ns) noexcept;
  void detected(const LinkFault& fault, std::uint64_t now_ns) noexcept;
  // Encodes reply_ and sends it sealed by `sealer`.
  void send(FrameSealer& sealer, std::uint64_t capture_ns, std::uint64_t now_ns,
            std::uint8_t flags = 0) noexcept;

  ControllerLinkConfig config_;
  LinkPort& port_;
  MapStore& store_;
  EntropyPort& entropy_;
  ArrivalLimits limits_;
  std::uint64_t fingerprint_;

  bool session_up_ = false;
  std::uint64_t session_id_ = 0;
  // The opening waiting for its answer (0: none), the challenge given to it and when.
  std::uint64_t opening_ = 0;
  std::uint64_t challenge_ = 0;
  std::uint64_t challenge_ns_ = 0;
  std::uint64_t challenges_given_ = 0;
  std::uint64_t stale_answers_ = 0;
  FrameChecker checker_;
  FrameSealer sealer_;
  ErrorLatch latch_;
  LinkFault last_fault_{};
  bool stop_requested_ = false;
  safecell_v1_FaultCause stop_cause_ = safecell_v1_FaultCause_FAULT_CAUSE_UNSPECIFIED;

  std::uint64_t map_applied_ns_ = 0;
  std::uint32_t healthy_cameras_ = 0;
  std::uint32_t camera_count_ = 0;
  std::uint32_t update_healthy_cameras_ = 0;
  std::uint32_t update_camera_count_ = 0;              // of the chunk in work in the store
  std::uint32_t speed_reduction_permille_ = 0;         // of the held map
  std::uint32_t update_speed_reduction_permille_ = 0;  // of the chunk in work in the store
  std::uint32_t budget_ = 0;                           // this poll's work units left
  MapRefusal last_map_refusal_ = MapRefusal::kNone;
  std::uint64_t updates_applied_ = 0;
  std::uint64_t updates_refused_ = 0;
  std::uint64_t hash_mismatches_ = 0;
  std::uint64_t update_version_ = 0;   // of the chunk in work in the store
  std::uint64_t repair_through_ = 0;   // updates up to this version have a repair asked for
  std::uint64_t losses_repaired_ = 0;  // repairs asked for on a heartbeat

  // Scratch (static size: no heap, no large stack frames in the cycle).
  std::uint8_t datagram_[kMaxFrameBytes + 1]{};
  std::uint8_t payload_[kMaxPayloadBytes]{};
  std::uint8_t outgoing_[kMaxFrameBytes]{};
  safecell_v1_Message incoming_{};
  safecell_v1_Message reply_{};
};

}  // namespace safecell
