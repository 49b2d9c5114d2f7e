#include "safecell/controller/host/scripted_coprocessor.hpp"

#include <stdexcept>

#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/protocol/nanopb_codec.hpp"

namespace safecell {
namespace {}  // namespace

ScriptedCoprocessor::ScriptedCoprocessor(std::uint64_t grid_fingerprint,
                                         std::uint64_t lut_fingerprint, std::uint64_t opening,
                                         CellIndex cells)
    : grid_(grid_fingerprint),
      lut_(lut_fingerprint),
      opening_(opening),
      cells_(cells),
      sealer_({1, 2, opening, configuration_fingerprint(grid_fingerprint, lut_fingerprint)}) {}

ScriptedCoprocessor::Frame ScriptedCoprocessor::handshake(std::uint64_t now_ns) {
  return handshake_frame(0, now_ns);
}

ScriptedCoprocessor::Frame ScriptedCoprocessor::answer(std::uint64_t challenge,
                                                       std::uint64_t now_ns) {
  Frame frame = handshake_frame(challenge, now_ns);
  sealer_ = FrameSealer({1, 2, opening_ ^ challenge, configuration_fingerprint(grid_, lut_)});
  return frame;
}

ScriptedCoprocessor::Frame ScriptedCoprocessor::handshake_frame(std::uint64_t challenge,
                                                                std::uint64_t now_ns) {
  sealer_ = FrameSealer({1, 2, opening_, configuration_fingerprint(grid_, lut_)});
  message_ = safecell_v1_Message_init_zero;
  message_.which_body = safecell_v1_Message_handshake_tag;
  message_.body.handshake.protocol_version = kProtocolVersion;
  message_.body.handshake.session_id = opening_;
  message_.body.handshake.grid_fingerprint = grid_;
  message_.body.handshake.lut_fingerprint = lut_;
  message_.body.handshake.challenge = challenge;
  return seal(now_ns, 0, kFrameFlagHandshake);
}

std::uint64_t ScriptedCoprocessor::challenge_in(const Frame& frame) {
  const Result<FrameView, LinkFault> opened = open_frame(frame.data(), frame.size(), 0);
  if (!opened.ok() || !opened.value().is_handshake()) return 0;
  safecell_v1_Message message = safecell_v1_Message_init_zero;
  if (decode_message(opened.value().payload, opened.value().payload_size, message) != Status::kOk ||
      message.which_body != safecell_v1_Message_handshake_tag) {
    return 0;
  }
  return message.body.handshake.challenge;
}

std::vector<ScriptedCoprocessor::Frame> ScriptedCoprocessor::update(
    const std::uint64_t* base, std::uint64_t base_version, const std::uint64_t* target,
    std::uint64_t version, std::uint64_t capture_ns, std::uint64_t now_ns, bool wrong_hash,
    std::size_t run_bytes) {
  if (run_bytes == 0 || run_bytes > kMaxRunBytes) {
    throw std::logic_error("ScriptedCoprocessor::update: run_bytes out of range");
  }
  std::vector<safecell_v1_MapChunk> chunks;
  CellIndex from = 0;
  do {
    safecell_v1_MapChunk chunk = safecell_v1_MapChunk_init_zero;
    chunk.kind = base != nullptr ? safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_DELTA
                                 : safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_KEYFRAME;
    chunk.map_version = version;
    chunk.base_version = base != nullptr ? base_version : 0;
    chunk.map_hash =
        map_hash_with_speed_reduction(
            map_hash_with_cameras(map_hash(target, cells_), healthy_cameras_, kCameras),
            speed_reduction_) ^
        (wrong_hash ? 1U : 0U);
    chunk.chunk_index = static_cast<std::uint32_t>(chunks.size());
    chunk.first_cell = from;
    chunk.healthy_cameras = healthy_cameras_;
    chunk.camera_count = kCameras;
    chunk.speed_reduction_permille = speed_reduction_;
    std::size_t size = 0;
    chunk.end_cell =
        base != nullptr
            ? encode_delta_chunk(base, target, cells_, from, chunk.runs.bytes, run_bytes, size)
            : encode_keyframe_chunk(target, cells_, from, chunk.runs.bytes, run_bytes, size);
    if (chunk.end_cell <= from) {
      throw std::logic_error("ScriptedCoprocessor::update: no run fits the chunk");
    }
    chunk.runs.size = static_cast<pb_size_t>(size);
    from = chunk.end_cell;
    chunks.push_back(chunk);
  } while (from < cells_);
  std::vector<Frame> frames;
  for (safecell_v1_MapChunk& chunk : chunks) {
    chunk.chunk_count = static_cast<std::uint32_t>(chunks.size());
    message_ = safecell_v1_Message_init_zero;
    message_.which_body = safecell_v1_Message_map_chunk_tag;
    message_.body.map_chunk = chunk;
    frames.push_back(seal(now_ns, capture_ns));
  }
  return frames;
}

ScriptedCoprocessor::Frame ScriptedCoprocessor::seal_payload(const std::uint8_t* payload,
                                                             std::size_t size, std::uint64_t now_ns,
                                                             std::uint64_t capture_ns) {
  Frame frame(kMaxFrameBytes);
  const Result<std::size_t> sealed =
      sealer_.seal(payload, size, now_ns, capture_ns, frame.data(), frame.size());
  if (!sealed.ok()) throw std::logic_error("ScriptedCoprocessor: the payload does not seal");
  frame.resize(sealed.value());
  return frame;
}

ScriptedCoprocessor::Frame ScriptedCoprocessor::seal(std::uint64_t now_ns, std::uint64_t capture_ns,
                                                     std::uint8_t flags) {
  std::uint8_t payload[kMaxPayloadBytes];
  const Result<std::size_t> encoded = encode_message(message_, payload, sizeof payload);
  if (!encoded.ok()) throw std::logic_error("ScriptedCoprocessor: the message does not encode");
  Frame frame(kMaxFrameBytes);
  const Result<std::size_t> size =
      sealer_.seal(payload, encoded.value(), now_ns, capture_ns, frame.data(), frame.size(), flags);
  if (!size.ok()) throw std::logic_error("ScriptedCoprocessor: the frame does not seal");
  frame.resize(size.value());
  return frame;
}

}  // namespace safecell
