#pragma once
// The coprocessor's side of the link, scripted with the controller's own encoder (nanopb, the
// safety layer), and datagrams in memory: for the controller tests, which run under qemu-aarch64
// too and so use no coprocessor code.

#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <vector>

#include "safecell/controller/link_port.hpp"
#include "safecell/cspace/map_chunk.hpp"
#include "safecell/cspace/map_hash.hpp"
#include "safecell/protocol/frame.hpp"
#include "safecell/protocol/nanopb_codec.hpp"
#include "safecell/v1/message.nanopb.h"

namespace safecell::test {

using Bytes = std::vector<std::uint8_t>;

// Datagrams in memory: what the test puts in, the link receives; what the link sends, the test
// reads.
class MemoryPort final : public LinkPort {
 public:
  bool send(const std::uint8_t* data, std::size_t size) noexcept override {
    sent.emplace_back(data, data + size);
    return true;
  }
  std::size_t receive(std::uint8_t* buffer, std::size_t capacity) noexcept override {
    if (inbox.empty()) return 0;
    const Bytes next = inbox.front();
    inbox.pop_front();
    if (next.size() > capacity) return capacity + 1;
    for (std::size_t i = 0; i < next.size(); ++i) buffer[i] = next[i];
    return next.size();
  }
  std::deque<Bytes> inbox;
  std::vector<Bytes> sent;
};

// The coprocessor's side, scripted with the controller's own encoder.
class ScriptedCoprocessor {
 public:
  ScriptedCoprocessor(std::uint64_t grid_fingerprint, std::uint64_t lut_fingerprint,
                      std::uint64_t session, CellIndex cells)
      : grid_(grid_fingerprint),
        lut_(lut_fingerprint),
        session_(session),
        cells_(cells),
        sealer_({1, 2, session, configuration_fingerprint(grid_fingerprint, lut_fingerprint)}) {}

  Bytes handshake(std::uint64_t now) {
    message_ = safecell_v1_Message_init_zero;
    message_.which_body = safecell_v1_Message_handshake_tag;
    message_.body.handshake.protocol_version = kProtocolVersion;
    message_.body.handshake.session_id = session_;
    message_.body.handshake.grid_fingerprint = grid_;
    message_.body.handshake.lut_fingerprint = lut_;
    return seal(now, 0, kFrameFlagHandshake);
  }
  // One chunk holding the whole update (the grid must be small enough for one frame).
  // wrong_hash: the hash of another map (a sender fault the receiver must catch).
  Bytes update(const std::vector<std::uint64_t>* base, std::uint64_t base_version,
               const std::vector<std::uint64_t>& target, std::uint64_t version,
               std::uint64_t capture, std::uint64_t now, bool wrong_hash = false) {
    message_ = safecell_v1_Message_init_zero;
    message_.which_body = safecell_v1_Message_map_chunk_tag;
    safecell_v1_MapChunk& chunk = message_.body.map_chunk;
    chunk.kind = base ? safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_DELTA
                      : safecell_v1_MapUpdateKind_MAP_UPDATE_KIND_KEYFRAME;
    chunk.map_version = version;
    chunk.base_version = base ? base_version : 0;
    chunk.map_hash = map_hash(target.data(), cells_) ^ (wrong_hash ? 1u : 0u);
    chunk.chunk_count = 1;
    chunk.end_cell = cells_;
    chunk.healthy_cameras = 4;
    chunk.camera_count = 4;
    std::size_t size = 0;
    const CellIndex end = base ? encode_delta_chunk(base->data(), target.data(), cells_, 0,
                                                    chunk.runs.bytes, sizeof chunk.runs.bytes, size)
                               : encode_keyframe_chunk(target.data(), cells_, 0, chunk.runs.bytes,
                                                       sizeof chunk.runs.bytes, size);
    EXPECT_EQ(end, cells_);
    chunk.runs.size = static_cast<pb_size_t>(size);
    return seal(now, capture);
  }

 private:
  Bytes seal(std::uint64_t now, std::uint64_t capture, std::uint8_t flags = 0) {
    std::uint8_t payload[kMaxPayloadBytes];
    const Result<std::size_t> encoded = encode_message(message_, payload, sizeof payload);
    EXPECT_TRUE(encoded.ok());
    Bytes frame(kMaxFrameBytes);
    const Result<std::size_t> size =
        sealer_.seal(payload, encoded.value_or(0), now, capture, frame.data(), frame.size(), flags);
    EXPECT_TRUE(size.ok());
    frame.resize(size.value_or(0));
    return frame;
  }

  std::uint64_t grid_;
  std::uint64_t lut_;
  std::uint64_t session_;
  CellIndex cells_;
  FrameSealer sealer_;
  safecell_v1_Message message_{};
};

}  // namespace safecell::test
