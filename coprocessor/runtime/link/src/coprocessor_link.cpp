#include "safecell/link/coprocessor_link.hpp"

#include <limits>
#include <random>
#include <sstream>

#include "safecell/link/link_errors.hpp"

namespace safecell {
namespace {

std::uint64_t steady_now_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

std::uint64_t random_opening() {
  std::random_device device;
  std::uint64_t id = 0;
  while (id == 0) id = (std::uint64_t{device()} << 32) ^ device();
  return id;
}

// Until the clock is synced, the controller's times cannot be compared with ours.
constexpr ArrivalLimits kUnsyncedLimits{std::numeric_limits<std::uint64_t>::max() / 2,
                                        std::numeric_limits<std::uint64_t>::max() / 2,
                                        std::numeric_limits<std::uint64_t>::max() / 2};

// StopRequest.detail holds 96 bytes on the controller (session.options), its NUL included: a
// longer one would not decode there and count as corruption.
constexpr std::size_t kStopDetailBytes = 95;

std::string hex(std::uint64_t value) {
  std::ostringstream text;
  text << "0x" << std::hex << value;
  return text.str();
}

}  // namespace

CoprocessorLink::CoprocessorLink(const CoprocessorLinkConfig& config, DatagramTransport& transport,
                                 std::uint64_t opening, Clock clock)
    : config_(config),
      transport_(transport),
      clock_(clock ? std::move(clock) : Clock(steady_now_ns)),
      opening_(opening != 0 ? opening : random_opening()),
      session_id_(opening_),
      fingerprint_(configuration_fingerprint(config.grid_fingerprint, config.lut_fingerprint)),
      sealer_({config.coprocessor_id, config.controller_id, opening_, fingerprint_}),
      checker_({config.coprocessor_id, config.controller_id, opening_, fingerprint_},
               kUnsyncedLimits, 0),
      publisher_(config.cell_count, config.publisher),
      latch_(config.latch_window_ns),
      buffer_(kMaxFrameBytes + 1) {}

void CoprocessorLink::send_message(const v1::Message& message, std::uint64_t capture_controller_ns,
                                   std::uint8_t flags) {
  const std::string payload = message.SerializeAsString();
  const std::uint64_t send_ns = clock_sync_.offset() ? clock_sync_.to_controller(now()) : 0;
  std::vector<std::uint8_t> frame(kMaxFrameBytes);
  const Result<std::size_t> size =
      sealer_.seal(reinterpret_cast<const std::uint8_t*>(payload.data()), payload.size(), send_ns,
                   capture_controller_ns, frame.data(), frame.size(), flags);
  if (!size.ok()) {
    throw std::logic_error(std::string("link: a message does not fit one frame (") +
                           to_string(size.error()) + ")");
  }
  (void)transport_.send({frame.data(), size.value()});
}

void CoprocessorLink::open(std::chrono::milliseconds timeout) {
  // The waits are on the steady clock: they wait for the real transport, also when `now` is a
  // simulated clock that only moves when its driver says (the closed-loop validation).
  using Steady = std::chrono::steady_clock;
  const Steady::time_point deadline = Steady::now() + timeout;
  const v1::Message opening = handshake_message(0);
  // The opening goes out again every 200 ms until the session is up: the controller answers it
  // with the same challenge while that is valid, and handle() answers each new challenge once.
  while (!accepted_) {
    if (Steady::now() > deadline) {
      throw LinkSetupError("link: the controller (id " + std::to_string(config_.controller_id) +
                           ") did not answer the handshake within " +
                           std::to_string(timeout.count()) + " ms");
    }
    send_message(opening, 0, kFrameFlagHandshake);
    const Steady::time_point resend_at = Steady::now() + std::chrono::milliseconds(200);
    while (!accepted_ && !refused_because_ && Steady::now() < resend_at) {
      poll(std::chrono::milliseconds(20));
    }
    if (refused_because_) throw LinkSetupError(*refused_because_);
  }
  // The clock offset, before any map: map times are the controller's.
  for (std::uint32_t echo = 0; echo < config_.echo_samples && Steady::now() < deadline; ++echo) {
    const std::size_t before = clock_sync_.samples();
    send_clock_echo();
    const Steady::time_point give_up = Steady::now() + std::chrono::milliseconds(100);
    while (clock_sync_.samples() == before && Steady::now() < give_up) {
      poll(std::chrono::milliseconds(5));
    }
  }
  if (!clock_sync_.offset()) {
    throw LinkSetupError("link: the controller accepted the session but answered no clock echo");
  }
  checker_.set_limits(
      {std::uint64_t{config_.max_data_age_us} * 1000,
       std::uint64_t{config_.max_clock_lead_us} * 1000 + clock_sync_.offset()->uncertainty_ns,
       std::uint64_t{config_.watchdog_us} * 1000});
}

v1::Message CoprocessorLink::handshake_message(std::uint64_t challenge) const {
  v1::Message message;
  v1::Handshake& handshake = *message.mutable_handshake();
  handshake.set_protocol_version(kProtocolVersion);
  handshake.set_session_id(opening_);
  handshake.set_source_id(config_.coprocessor_id);
  handshake.set_destination_id(config_.controller_id);
  handshake.set_grid_fingerprint(config_.grid_fingerprint);
  handshake.set_lut_fingerprint(config_.lut_fingerprint);
  handshake.set_map_cycle_us(config_.map_cycle_us);
  handshake.set_control_cycle_us(config_.control_cycle_us);
  handshake.set_watchdog_us(config_.watchdog_us);
  handshake.set_max_data_age_us(config_.max_data_age_us);
  handshake.set_keyframe_after_cycles(config_.publisher.keyframe_after_cycles);
  handshake.set_challenge(challenge);
  return message;
}

void CoprocessorLink::number_frames_in(std::uint64_t id) {
  session_id_ = id;
  sealer_ = FrameSealer({config_.coprocessor_id, config_.controller_id, id, fingerprint_});
  checker_ = FrameChecker({config_.coprocessor_id, config_.controller_id, id, fingerprint_},
                          kUnsyncedLimits, now(), 0);
}

void CoprocessorLink::start_new_session() {
  opening_ = random_opening();
  answered_challenge_ = 0;
  number_frames_in(opening_);
  clock_sync_ = ClockSync();
  publisher_ = MapPublisher(config_.cell_count, config_.publisher);
  latch_ = ErrorLatch(config_.latch_window_ns);
  repair_requests_ = 0;
  accepted_ = false;
  refused_because_.reset();
  last_joint_state_.reset();
}

void CoprocessorLink::send_clock_echo() {
  v1::Message message;
  message.mutable_clock_echo()->set_echo_id(next_echo_id_++);
  message.mutable_clock_echo()->set_request_sent_ns(now());
  send_message(message, 0);
}

void CoprocessorLink::send_stop_request(v1::FaultCause cause, const std::string& detail) {
  if (!clock_sync_.offset()) throw std::logic_error("link: send_stop_request before open()");
  v1::Message message;
  message.mutable_stop_request()->set_cause(cause);
  message.mutable_stop_request()->set_detail(detail.substr(0, kStopDetailBytes));
  const std::uint64_t now_controller = clock_sync_.to_controller(now());
  send_message(message, now_controller);
}

MapUpdate CoprocessorLink::send_map(const CellSet& map, std::uint64_t capture_ns,
                                    std::uint32_t healthy_cameras, std::uint32_t camera_count,
                                    std::uint32_t speed_reduction_permille) {
  if (!clock_sync_.offset()) throw std::logic_error("link: send_map before open()");
  MapUpdate update =
      publisher_.publish(map, healthy_cameras, camera_count, speed_reduction_permille);
  const std::uint64_t capture_controller_ns = clock_sync_.to_controller(capture_ns);
  v1::Message message;
  for (const v1::MapChunk& chunk : update.chunks) {
    *message.mutable_map_chunk() = chunk;
    send_message(message, capture_controller_ns);
  }
  // The update's end, named: a controller that does not hold it asks for a repair at once.
  v1::Message end;
  end.mutable_heartbeat()->set_counter(++heartbeats_);
  end.mutable_heartbeat()->set_last_map_version(update.version);
  send_message(end, 0);
  return update;
}

std::size_t CoprocessorLink::poll(std::chrono::microseconds wait) {
  const auto until = std::chrono::steady_clock::now() + wait;
  std::size_t handled = 0;
  do {
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(
        until - std::chrono::steady_clock::now());
    const auto size = transport_.receive(buffer_, std::max(left, std::chrono::microseconds(0)));
    if (!size) return handled;
    (void)handle({buffer_.data(), std::min(*size, buffer_.size())});
    ++handled;
  } while (std::chrono::steady_clock::now() < until);
  return handled;
}

void CoprocessorLink::handle_handshake_answer(const FrameView& frame) {
  v1::Message message;
  if (frame.header.session_id != opening_ || frame.header.source_id != config_.controller_id ||
      frame.header.destination_id != config_.coprocessor_id ||
      !message.ParseFromArray(frame.payload, static_cast<int>(frame.payload_size)) ||
      !message.has_handshake()) {
    (void)latch_.record({LinkError::kMasquerade, frame.header.session_id}, now());
    return;
  }
  const v1::Handshake& answer = message.handshake();
  if (accepted_) return;  // the session is up: a late answer to a resent opening changes nothing
  if (answer.accepted()) {
    if (answer.challenge() == 0 || answer.challenge() != answered_challenge_) {
      // An acceptance of a challenge this end did not answer: not this opening's.
      (void)latch_.record({LinkError::kRepetition, answer.challenge()}, now());
      return;
    }
    accepted_ = true;
    // The controller's watchdog and data age are the session's: the joint stream is checked
    // against what the controller itself keeps to (its configuration, not this end's guess).
    if (answer.watchdog_us() > 0) config_.watchdog_us = answer.watchdog_us();
    if (answer.max_data_age_us() > 0) config_.max_data_age_us = answer.max_data_age_us();
    number_frames_in(opening_ ^ answer.challenge());
    return;
  }
  if (answer.challenge() != 0) {
    // The controller's challenge: answered once (a resent opening brings the same one again).
    if (answer.challenge() != answered_challenge_) {
      answered_challenge_ = answer.challenge();
      send_message(handshake_message(answered_challenge_), 0, kFrameFlagHandshake);
    }
    return;
  }
  std::string why = "link: the controller refused the session:";
  if (answer.protocol_version() != kProtocolVersion) {
    why += " it speaks protocol version " + std::to_string(answer.protocol_version()) +
           ", this coprocessor " + std::to_string(kProtocolVersion) + ";";
  }
  if (answer.grid_fingerprint() != config_.grid_fingerprint) {
    why += " its grid fingerprint is " + hex(answer.grid_fingerprint()) + ", ours " +
           hex(config_.grid_fingerprint) + " (the cell's grid differs: m_max, joints, ranges);";
  }
  if (answer.lut_fingerprint() != config_.lut_fingerprint) {
    why += " its LUT fingerprint is " + hex(answer.lut_fingerprint()) + ", ours " +
           hex(config_.lut_fingerprint) + " (recommission the controller with these LUTs);";
  }
  if (why.back() == ':') {
    why +=
        " its configuration agrees, but it gave no challenge (its source of session "
        "challenges failed: see its log);";
  }
  refused_because_ = why;
}

bool CoprocessorLink::handle(std::span<const std::uint8_t> datagram) {
  const std::uint64_t arrival = now();
  const Result<FrameView, LinkFault> opened =
      open_frame(datagram.data(), datagram.size(), fingerprint_);
  if (!opened.ok()) {
    (void)latch_.record(opened.error(), arrival);
    return false;
  }
  if (opened.value().is_handshake()) {
    handle_handshake_answer(opened.value());
    return false;
  }
  if (!accepted_) {
    (void)latch_.record({LinkError::kMasquerade, opened.value().header.session_id}, arrival);
    return false;
  }
  const std::uint64_t now_controller =
      clock_sync_.offset() ? clock_sync_.to_controller(arrival) : arrival;
  const Result<AcceptedFrame, LinkFault> accepted =
      checker_.check_opened(opened.value(), now_controller);
  if (!accepted.ok()) {
    (void)latch_.record(accepted.error(), arrival);
    return false;
  }
  if (accepted.value().lost > 0) {
    (void)latch_.record({LinkError::kLoss, accepted.value().lost}, arrival);
  }
  const FrameView& frame = accepted.value().frame;
  v1::Message message;
  if (!message.ParseFromArray(frame.payload, static_cast<int>(frame.payload_size))) {
    (void)latch_.record({LinkError::kCorruption, frame.header.sequence}, arrival);
    return false;
  }
  switch (message.body_case()) {
    case v1::Message::kJointState: {
      publisher_.acknowledge(message.joint_state().applied_map_version());
      ReceivedJointState received{message.joint_state(), 0};
      if (clock_sync_.offset()) {
        received.coprocessor_time_ns =
            clock_sync_.to_coprocessor(message.joint_state().controller_time_ns());
      }
      last_joint_state_ = std::move(received);
      for (const JointStateHandler& handler : on_joint_state_) handler(*last_joint_state_);
      break;
    }
    case v1::Message::kClockEcho: {
      const v1::ClockEcho& echo = message.clock_echo();
      (void)clock_sync_.add(
          {echo.request_sent_ns(), echo.request_received_ns(), echo.reply_sent_ns(), arrival});
      break;
    }
    case v1::Message::kKeyframeRequest:
      ++repair_requests_;
      publisher_.request_repair(message.keyframe_request().held_map_version());
      break;
    case v1::Message::kFaultReport:
      controller_faults_.push_back(message.fault_report());
      break;
    default:
      break;
  }
  return true;
}

}  // namespace safecell
