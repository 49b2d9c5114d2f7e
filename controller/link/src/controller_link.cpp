#include "safecell/controller/controller_link.hpp"

#include "safecell/protocol/nanopb_codec.hpp"

namespace safecell {
namespace {

// Precondition: the chunk's kind is a keyframe or a delta (known_kind()).
MapChunkHeader chunk_header_of(const safecell_v1_MapChunk& chunk) noexcept {
  MapChunkHeader header;
  header.kind = wire_enum(chunk.kind) == safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_DELTA
                    ? MapChunkKind::kDelta
                    : MapChunkKind::kKeyframe;
  header.map_version = chunk.map_version;
  header.base_version = chunk.base_version;
  // The hash on the link binds the chunk's camera counts and speed reduction (map_hash.hpp); the
  // store checks what is left against the map it rebuilt, so a changed count or reduction is
  // refused like a changed cell.
  header.map_hash = map_hash_with_cameras(
      map_hash_with_speed_reduction(chunk.map_hash, chunk.speed_reduction_permille),
      chunk.healthy_cameras, chunk.camera_count);
  header.chunk_index = chunk.chunk_index;
  header.chunk_count = chunk.chunk_count;
  header.first_cell = chunk.first_cell;
  header.end_cell = chunk.end_cell;
  return header;
}

bool known_kind(const safecell_v1_MapChunk& chunk) noexcept {
  const auto kind = wire_enum(chunk.kind);
  return kind == safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_KEYFRAME ||
         kind == safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_DELTA;
}

}  // namespace

const char* to_string(LinkBlock block) noexcept {
  switch (block) {
    case LinkBlock::kNone:
      return "none";
    case LinkBlock::kNoSession:
      return "no session";
    case LinkBlock::kNoMap:
      return "no verified map";
    case LinkBlock::kMapTooOld:
      return "no map within the watchdog time";
    case LinkBlock::kLatched:
      return "link errors latched";
    case LinkBlock::kStopRequested:
      return "stop requested";
  }
  return "unknown";
}

const char* fault_cause_name(safecell_v1_FaultCause cause) noexcept {
  switch (cause) {
    case safecell_v1_FaultCause_FAULT_CAUSE_OPERATOR:
      return "operator";
    case safecell_v1_FaultCause_FAULT_CAUSE_CAMERAS:
      return "cameras";
    case safecell_v1_FaultCause_FAULT_CAUSE_WATCHDOG:
      return "watchdog";
    default:
      return "other";
  }
}

ControllerLink::ControllerLink(const ControllerLinkConfig& config, LinkPort& port, MapStore& store,
                               EntropyPort& entropy) noexcept
    : config_(config),
      port_(port),
      store_(store),
      entropy_(entropy),
      limits_{config.max_data_age_ns, config.max_clock_lead_ns, config.watchdog_ns},
      fingerprint_(configuration_fingerprint(config.grid_fingerprint, config.lut_fingerprint)),
      checker_(LinkEndpoints{}, limits_, 0),
      sealer_(LinkEndpoints{}),
      latch_(config.latch_window_ns) {}

bool ControllerLink::poll(std::uint64_t now_ns) noexcept {
  const int limit = config_.max_frames_per_poll < 1                   ? 1
                    : config_.max_frames_per_poll > kMaxFramesPerPoll ? kMaxFramesPerPoll
                                                                      : config_.max_frames_per_poll;
  budget_ = config_.map_work_per_poll;
  if (store_.busy()) map_outcome(store_.work(budget_), now_ns);
  for (int frame = 0; frame < limit; ++frame) {
    if (store_.chunk_in_work() || (frame > 0 && budget_ < kWorkPerFrame)) return true;
    const std::size_t size = port_.receive(datagram_, sizeof datagram_);
    if (size == 0) return store_.busy();
    budget_ = budget_ > kWorkPerFrame ? budget_ - kWorkPerFrame : 0;
    handle_datagram(datagram_, size, now_ns);
  }
  return true;
}

void ControllerLink::detected(const LinkFault& fault, std::uint64_t now_ns) noexcept {
  last_fault_ = fault;
  (void)latch_.record(fault, now_ns);
}

void ControllerLink::handle_datagram(const std::uint8_t* data, std::size_t size,
                                     std::uint64_t now_ns) noexcept {
  const Result<FrameView, LinkFault> opened = open_frame(data, size, fingerprint_);
  if (!opened.ok()) {
    detected(opened.error(), now_ns);
    return;
  }
  if (opened.value().is_handshake()) {
    handle_handshake(opened.value(), now_ns);
    return;
  }
  if (!session_up_) {
    detected({LinkError::kMasquerade, opened.value().header.session_id}, now_ns);
    return;
  }
  const Result<AcceptedFrame, LinkFault> accepted = checker_.check_opened(opened.value(), now_ns);
  if (!accepted.ok()) {
    detected(accepted.error(), now_ns);
    return;
  }
  if (accepted.value().lost > 0) detected({LinkError::kLoss, accepted.value().lost}, now_ns);
  handle_message(accepted.value().frame, now_ns);
}

void ControllerLink::handle_handshake(const FrameView& frame, std::uint64_t now_ns) noexcept {
  const FrameHeader& header = frame.header;
  if (header.destination_id != config_.controller_id) {
    detected({LinkError::kAddressing, header.destination_id}, now_ns);
    return;
  }
  if (header.source_id != config_.coprocessor_id) {
    detected({LinkError::kInsertion, header.source_id}, now_ns);
    return;
  }
  if (decode_message(frame.payload, frame.payload_size, incoming_) != Status::kOk ||
      incoming_.which_body != safecell_v1_Message_handshake_tag) {
    detected({LinkError::kCorruption, 0}, now_ns);
    return;
  }
  const safecell_v1_Handshake& offered = incoming_.body.handshake;
  const std::uint64_t opening = header.session_id;
  LinkFault refusal{};
  if (offered.protocol_version != kProtocolVersion) {
    refusal = {LinkError::kWrongConfiguration, offered.protocol_version};
  } else if (offered.grid_fingerprint != config_.grid_fingerprint) {
    refusal = {LinkError::kWrongConfiguration, offered.grid_fingerprint};
  } else if (offered.lut_fingerprint != config_.lut_fingerprint) {
    refusal = {LinkError::kWrongConfiguration, offered.lut_fingerprint};
  } else if (offered.session_id != opening || opening == 0) {
    refusal = {LinkError::kMasquerade, offered.session_id};
  }
  if (refusal.error != LinkError::kNone) {
    // Refused with this end's configuration named, so the coprocessor can say what differs; the
    // session in place, if any, stays as it is.
    detected(refusal, now_ns);
    answer_handshake(opening, false, 0, now_ns);
    return;
  }
  if (offered.challenge == 0) {
    // An opening: it gets this opening's challenge; nothing else changes.
    if (!challenge_for(opening, now_ns)) {
      detected({LinkError::kWrongConfiguration, 0}, now_ns);  // no fresh challenge: no session
      answer_handshake(opening, false, 0, now_ns);
      return;
    }
    answer_handshake(opening, false, challenge_, now_ns);
    return;
  }
  if (!challenge_pending(opening, now_ns) || offered.challenge != challenge_) {
    // Not the answer to the challenge this controller gave out last (a recording of an earlier
    // opening, a duplicate, or too late): refused without an answer, the session in place kept.
    ++stale_answers_;
    detected({LinkError::kRepetition, offered.challenge}, now_ns);
    return;
  }
  open_session(now_ns);
}

bool ControllerLink::challenge_pending(std::uint64_t opening, std::uint64_t now_ns) const noexcept {
  return challenge_ != 0 && opening == opening_ &&
         now_ns - challenge_ns_ <= config_.challenge_lifetime_ns;
}

bool ControllerLink::challenge_for(std::uint64_t opening, std::uint64_t now_ns) noexcept {
  if (challenge_pending(opening, now_ns)) {
    return true;  // the same opening again (its frame resent): the same challenge
  }
  challenge_ = 0;
  opening_ = 0;
  // The session id (opening XOR challenge) must be neither 0 nor the opening itself.
  for (int attempt = 0; attempt < 4; ++attempt) {
    std::uint64_t drawn = 0;
    if (!entropy_.draw(drawn)) return false;
    if (drawn != 0 && drawn != opening) {
      challenge_ = drawn;
      opening_ = opening;
      challenge_ns_ = now_ns;
      ++challenges_given_;
      return true;
    }
  }
  return false;
}

void ControllerLink::open_session(std::uint64_t now_ns) noexcept {
  const std::uint64_t opening = opening_;
  const std::uint64_t challenge = challenge_;
  // The challenge is used up: an answer to it again is a repetition.
  opening_ = 0;
  challenge_ = 0;
  // A new session: the held map belongs to the old one (or none) and is forgotten. Its frames
  // are numbered from 1 in both directions.
  const LinkEndpoints endpoints{config_.controller_id, config_.coprocessor_id, opening ^ challenge,
                                fingerprint_};
  session_up_ = true;
  session_id_ = endpoints.session_id;
  checker_ = FrameChecker(endpoints, limits_, now_ns, 0);
  sealer_ = FrameSealer(endpoints);
  store_.reset();
  map_applied_ns_ = 0;
  update_version_ = 0;
  repair_through_ = 0;
  answer_handshake(opening, true, challenge, now_ns);
}

void ControllerLink::answer_handshake(std::uint64_t opening, bool accepted, std::uint64_t challenge,
                                      std::uint64_t now_ns) noexcept {
  reply_ = safecell_v1_Message_init_zero;
  reply_.which_body = safecell_v1_Message_handshake_tag;
  safecell_v1_Handshake& answer = reply_.body.handshake;
  answer.protocol_version = kProtocolVersion;
  answer.session_id = opening;
  answer.source_id = config_.controller_id;
  answer.destination_id = config_.coprocessor_id;
  answer.grid_fingerprint = config_.grid_fingerprint;
  answer.lut_fingerprint = config_.lut_fingerprint;
  answer.watchdog_us = static_cast<std::uint32_t>(config_.watchdog_ns / 1000);
  answer.max_data_age_us = static_cast<std::uint32_t>(config_.max_data_age_ns / 1000);
  answer.accepted = accepted;
  answer.challenge = challenge;
  // Handshake frames go out in the opening's number, each its own (the session's sealer numbers
  // only the session's frames).
  FrameSealer handshake_sealer(
      {config_.controller_id, config_.coprocessor_id, opening, fingerprint_});
  send(handshake_sealer, now_ns, now_ns, kFrameFlagHandshake);
}

void ControllerLink::handle_message(const FrameView& frame, std::uint64_t now_ns) noexcept {
  if (decode_message(frame.payload, frame.payload_size, incoming_) != Status::kOk) {
    // CRC-valid but not a Message within bounds: a sender fault; refused like corruption.
    detected({LinkError::kCorruption, frame.header.sequence}, now_ns);
    return;
  }
  switch (incoming_.which_body) {
    case safecell_v1_Message_map_chunk_tag:
      if (frame.header.capture_time_ns == 0) {
        detected({LinkError::kDelay, 0}, now_ns);  // a map whose age cannot be checked
        break;
      }
      if (!known_kind(incoming_.body.map_chunk)) {
        // Neither a keyframe nor a delta (a sender of another version, or a fault behind a
        // valid CRC): refused like corruption, never guessed.
        detected({LinkError::kCorruption, frame.header.sequence}, now_ns);
        break;
      }
      handle_map_chunk(incoming_.body.map_chunk, frame, now_ns);
      break;
    case safecell_v1_Message_clock_echo_tag: {
      const safecell_v1_ClockEcho request = incoming_.body.clock_echo;
      reply_ = safecell_v1_Message_init_zero;
      reply_.which_body = safecell_v1_Message_clock_echo_tag;
      reply_.body.clock_echo.echo_id = request.echo_id;
      reply_.body.clock_echo.request_sent_ns = request.request_sent_ns;
      reply_.body.clock_echo.request_received_ns = now_ns;
      reply_.body.clock_echo.reply_sent_ns = now_ns;
      send(sealer_, now_ns, now_ns);
      break;
    }
    case safecell_v1_Message_stop_request_tag: {
      // The stop holds whatever the cause; a cause this version does not name is kept as
      // unspecified (the number itself is not a value of the enum).
      stop_requested_ = true;
      const auto cause = wire_enum(incoming_.body.stop_request.cause);
      stop_cause_ = cause >= _safecell_v1_FaultCause_MIN && cause <= _safecell_v1_FaultCause_MAX
                        ? static_cast<safecell_v1_FaultCause>(cause)
                        : safecell_v1_FaultCause_FAULT_CAUSE_UNSPECIFIED;
      break;
    }
    case safecell_v1_Message_status_report_tag:
      // A report can only lower the count: it is not bound to a map as a chunk's count is, so a
      // report saying more cameras than the held map was fused from is not believed.
      if (incoming_.body.status_report.healthy_cameras < healthy_cameras_) {
        healthy_cameras_ = incoming_.body.status_report.healthy_cameras;
      }
      break;
    case safecell_v1_Message_heartbeat_tag: {
      // The update it names is not held and no repair was asked for it: it was lost (whole, or
      // its end). Asked now, the next update repairs instead of being refused.
      const std::uint64_t sent = incoming_.body.heartbeat.last_map_version;
      if (sent > store_.version() && sent > repair_through_) {
        ++losses_repaired_;
        request_repair(sent, now_ns);
      }
      break;
    }
    default:  // messages meant for the coprocessor: nothing to do
      break;
  }
}

void ControllerLink::handle_map_chunk(const safecell_v1_MapChunk& chunk, const FrameView& frame,
                                      std::uint64_t now_ns) noexcept {
  // The chunk's runs stay in incoming_ while the store works on them: poll() reads no frame
  // until the store has the chunk's outcome.
  update_healthy_cameras_ = chunk.healthy_cameras;
  update_camera_count_ = chunk.camera_count;
  update_speed_reduction_permille_ = chunk.speed_reduction_permille;
  update_version_ = chunk.map_version;
  MapOffer offer = store_.accept(chunk_header_of(chunk), chunk.runs.bytes, chunk.runs.size,
                                 frame.header.capture_time_ns);
  if (offer.outcome == MapOutcome::kWorking) offer = store_.work(budget_);
  map_outcome(offer, now_ns);
}

void ControllerLink::map_outcome(const MapOffer& offer, std::uint64_t now_ns) noexcept {
  if (offer.outcome == MapOutcome::kApplied) {
    map_applied_ns_ = now_ns;
    healthy_cameras_ = update_healthy_cameras_;
    camera_count_ = update_camera_count_;
    speed_reduction_permille_ = update_speed_reduction_permille_;
    ++updates_applied_;
    return;
  }
  if (offer.outcome != MapOutcome::kRefused) return;
  ++updates_refused_;
  last_map_refusal_ = offer.refusal;
  if (offer.refusal == MapRefusal::kHashMismatch) ++hash_mismatches_;
  // The coprocessor bases each delta on the update it sent last (MapPublisher): any update that
  // is not taken whole, and any base this end does not hold, asks it for a repair from the
  // version held here. (A version not above the held one is a repetition: nothing to repair.)
  if (offer.refusal != MapRefusal::kStaleVersion) request_repair(update_version_, now_ns);
}

void ControllerLink::request_repair(std::uint64_t through, std::uint64_t now_ns) noexcept {
  if (through > repair_through_) repair_through_ = through;
  reply_ = safecell_v1_Message_init_zero;
  reply_.which_body = safecell_v1_Message_keyframe_request_tag;
  reply_.body.keyframe_request.held_map_version = store_.version();
  send(sealer_, now_ns, now_ns);
}

void ControllerLink::send_joint_state(const JointSample& joints, const MotionReport& motion,
                                      std::uint64_t now_ns) noexcept {
  if (!session_up_) return;
  reply_ = safecell_v1_Message_init_zero;
  reply_.which_body = safecell_v1_Message_joint_state_tag;
  safecell_v1_JointState& out = reply_.body.joint_state;
  const std::uint32_t count = joints.joint_count <= 8 ? joints.joint_count : 8;
  out.controller_time_ns = joints.read_time_ns;
  out.position_rad_count = static_cast<pb_size_t>(count);
  out.velocity_rad_s_count = static_cast<pb_size_t>(count);
  for (std::uint32_t j = 0; j < count; ++j) {
    out.position_rad[j] = joints.position_rad[j];
    out.velocity_rad_s[j] = joints.velocity_rad_s[j];
  }
  out.applied_map_version = store_.version();
  out.state = motion.state;
  out.speed_scale = motion.speed_scale;
  out.critical_joint = motion.critical_joint;
  out.has_blocking_cell = motion.has_blocking_cell;
  out.blocking_cell = motion.has_blocking_cell ? motion.blocking_cell : 0U;
  out.applied_map_time_ns = store_.version() != 0 ? map_applied_ns_ : 0;
  send(sealer_, joints.read_time_ns, now_ns);
}

void ControllerLink::send(FrameSealer& sealer, std::uint64_t capture_ns, std::uint64_t now_ns,
                          std::uint8_t flags) noexcept {
  const Result<std::size_t> encoded = encode_message(reply_, payload_, sizeof payload_);
  if (!encoded.ok()) return;
  const Result<std::size_t> sealed = sealer.seal(payload_, encoded.value(), now_ns, capture_ns,
                                                 outgoing_, sizeof outgoing_, flags);
  if (sealed.ok()) (void)port_.send(outgoing_, sealed.value());
}

LinkBlock ControllerLink::block(std::uint64_t now_ns) const noexcept {
  if (latch_.latched()) return LinkBlock::kLatched;
  if (stop_requested_) return LinkBlock::kStopRequested;
  if (!session_up_) return LinkBlock::kNoSession;
  if (store_.version() == 0) return LinkBlock::kNoMap;
  if (now_ns < map_applied_ns_ || now_ns - map_applied_ns_ > config_.watchdog_ns) {
    return LinkBlock::kMapTooOld;
  }
  return LinkBlock::kNone;
}

void ControllerLink::acknowledge() noexcept {
  latch_.acknowledge();
  stop_requested_ = false;
  stop_cause_ = safecell_v1_FaultCause_FAULT_CAUSE_UNSPECIFIED;
}

}  // namespace safecell
