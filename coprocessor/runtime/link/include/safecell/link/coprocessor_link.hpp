#pragma once
// The coprocessor's end of the link: opens the session (the handshake of protocol version 2: an
// opening, the controller's challenge, the answer echoing it, the acceptance; handshake.proto),
// keeps the clock offset to the
// controller (ClockEcho), sends each cycle's map update and takes in the joint stream with its
// acknowledgements.
//
// Clocks: the controller's clock is the link's reference. Frames to the controller carry times
// converted into it (ClockSync), and the joint stream's times are the controller's own, so both
// ends check data age against one clock; `now` here is the coprocessor's steady clock (or the
// one a test injects).
// Thread context: one link thread; not synchronised.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "safecell/link/clock_sync.hpp"
#include "safecell/link/datagram_transport.hpp"
#include "safecell/link/map_publisher.hpp"
#include "safecell/protocol/error_latch.hpp"
#include "safecell/protocol/frame_checker.hpp"
#include "safecell/v1/message.pb.h"

namespace safecell {

struct CoprocessorLinkConfig {
  std::uint32_t cell_count = 0;  // of the grid the maps are cells of
  std::uint32_t coprocessor_id = 1;
  std::uint32_t controller_id = 2;
  std::uint64_t grid_fingerprint = 0;
  std::uint64_t lut_fingerprint = 0;
  std::uint32_t map_cycle_us = 33'333;
  std::uint32_t control_cycle_us = 4'000;
  std::uint32_t watchdog_us = 100'000;
  std::uint32_t max_data_age_us = 150'000;
  std::uint32_t max_clock_lead_us = 5'000;
  MapPublisherSettings publisher;
  std::uint32_t echo_samples = 8;  // echoes at session start
  std::uint64_t latch_window_ns = kDefaultLatchWindowNs;
};

// The last joint state the controller sent, with its time in the coprocessor's clock.
struct ReceivedJointState {
  v1::JointState state;
  std::uint64_t coprocessor_time_ns = 0;
};

class CoprocessorLink {
 public:
  using Clock = std::function<std::uint64_t()>;  // ns, monotonic

  // opening: the handshake's opening number, random per opening (0 draws one; a test may fix
  // it). clock: the coprocessor's; steady_clock if empty.
  CoprocessorLink(const CoprocessorLinkConfig& config, DatagramTransport& transport,
                  std::uint64_t opening = 0, Clock clock = {});

  // Handshake, then config.echo_samples clock echoes. Throws LinkSetupError when the controller
  // refuses (naming what differs) or does not answer within `timeout`.
  void open(std::chrono::milliseconds timeout);

  // Forgets the session (a controller that restarted knows it no more): a new random opening
  // number, the sequence, clock offset, error latch and map versions from the start; open()
  // again next. The joint-state handlers stay.
  void start_new_session();

  // Sends this cycle's map, its data captured at `capture_ns` (coprocessor clock), with the
  // protective separation's speed reduction (MapPublisher::publish), then a heartbeat naming its
  // version (session.proto).
  MapUpdate send_map(const CellSet& map, std::uint64_t capture_ns, std::uint32_t healthy_cameras,
                     std::uint32_t camera_count, std::uint32_t speed_reduction_permille = 0);
  // Sends one clock echo request (call now and then: drift).
  void send_clock_echo();
  // Asks the controller to stop (a clean shutdown, an operator): it holds the robot, latched,
  // until its operator acknowledges. `detail` is cut to what one frame's field holds.
  void send_stop_request(v1::FaultCause cause, const std::string& detail);

  // Adds a handler called with every joint state of the session as it arrives (the smart
  // buffer's feed, a recorder), on the thread that polls, in the order added.
  using JointStateHandler = std::function<void(const ReceivedJointState&)>;
  void on_joint_state(JointStateHandler handler) { on_joint_state_.push_back(std::move(handler)); }

  // Handles what arrives within `wait` (returns early after the first datagram when `wait` is 0);
  // returns how many datagrams it handled.
  std::size_t poll(std::chrono::microseconds wait);

  // The session's id once the controller accepted it (opening number XOR its challenge), the
  // opening number before.
  std::uint64_t session_id() const { return session_id_; }
  // The configuration given, with the controller's watchdog and maximum data age once it has
  // accepted the session (its handshake answer names them).
  const CoprocessorLinkConfig& config() const { return config_; }
  // Why the controller refused the session, once it has (open() then throws).
  const std::optional<std::string>& refused_because() const { return refused_because_; }
  const ClockSync& clock_sync() const { return clock_sync_; }
  const MapPublisher& publisher() const { return publisher_; }
  const ErrorLatch& latch() const { return latch_; }
  const std::optional<ReceivedJointState>& last_joint_state() const { return last_joint_state_; }
  // Faults the controller reported, in order.
  const std::vector<v1::FaultReport>& controller_faults() const { return controller_faults_; }
  // The controller's requests for a repair (KeyframeRequest): one per map update it refused or
  // found torn, from the start of the session.
  std::uint64_t repair_requests() const { return repair_requests_; }

 private:
  std::uint64_t now() const { return clock_(); }
  void send_message(const v1::Message& message, std::uint64_t capture_controller_ns,
                    std::uint8_t flags = 0);
  // Handles one datagram; true when it was a valid frame of the session.
  bool handle(std::span<const std::uint8_t> datagram);
  void handle_handshake_answer(const FrameView& frame);
  // The opening (challenge 0) or the answer to a challenge.
  v1::Message handshake_message(std::uint64_t challenge) const;
  // Sealer and checker for frames in session `id`.
  void number_frames_in(std::uint64_t id);

  CoprocessorLinkConfig config_;
  DatagramTransport& transport_;
  Clock clock_;
  std::uint64_t opening_;
  std::uint64_t session_id_;
  std::uint64_t fingerprint_;
  std::uint64_t answered_challenge_ = 0;  // the last challenge answered (0: none yet)
  FrameSealer sealer_;
  FrameChecker checker_;
  ClockSync clock_sync_;
  MapPublisher publisher_;
  ErrorLatch latch_;
  bool accepted_ = false;
  std::optional<std::string> refused_because_;
  std::uint32_t next_echo_id_ = 1;
  std::uint64_t repair_requests_ = 0;
  std::uint64_t heartbeats_ = 0;
  std::optional<ReceivedJointState> last_joint_state_;
  std::vector<JointStateHandler> on_joint_state_;
  std::vector<v1::FaultReport> controller_faults_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace safecell
