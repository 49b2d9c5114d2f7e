#pragma once
// A UDP proxy that misbehaves on purpose, seeded, for the link's integration tests and fault
// campaigns: between side A (the coprocessor) and side B (the controller) on loopback it drops,
// duplicates, reorders, delays, corrupts (bit flips), inserts foreign frames and cuts the link,
// at rates per direction, and says what it did as JSON. The kernel drops UDP datagrams with a bad
// checksum, so corruption can only be tested like this, above the transport (../shared/SAFETY.md).
// Thread context: runs its own thread between start() and stop(); counts() may be read any time.

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

namespace safecell {

struct FaultRates {
  double drop = 0.0;       // probability per datagram
  double duplicate = 0.0;  // sent twice
  double reorder = 0.0;    // held back and sent after the next datagram
  double delay = 0.0;      // held back for delay_by
  double flip = 0.0;       // 1..max_flipped_bits random bits flipped
  double insert = 0.0;     // a foreign frame (another session and source) sent before it
  // A copy of it sent first, sealed with a valid CRC but under another session id: what a stale
  // or second coprocessor with the same ids and configuration would send (a masquerade). Needs
  // FaultProxySettings::configuration_fingerprint; frames it cannot open are passed on as they are.
  double foreign_session = 0.0;
  // Bits flipped in its payload and the frame sealed again with a valid CRC: corruption the CRC
  // cannot see (what a faulty device between the ends that re-frames data would do), left to
  // the message's decoding and the map hash. Needs configuration_fingerprint, as above.
  double resealed_flip = 0.0;
  std::chrono::microseconds delay_by{60'000};
  int max_flipped_bits = 8;
  // A slow stretch: every datagram from delay_after (since start) for delay_for is held back by
  // delay_by, in order (the data arrives too old rather than out of order). Zero: none.
  std::chrono::milliseconds delay_after{0};
  std::chrono::milliseconds delay_for{0};
  // The link cut: nothing passes from cut_after (since start) for cut_for. Zero: no cut.
  std::chrono::milliseconds cut_after{0};
  std::chrono::milliseconds cut_for{0};
};

struct FaultProxySettings {
  std::string ip = "127.0.0.1";
  std::uint16_t listen_a = 0;  // the port side A sends to (0: any free port)
  std::uint16_t listen_b = 0;  // the port side B sends to
  std::uint16_t peer_a = 0;    // side A's port (0: learnt from its first datagram)
  std::uint16_t peer_b = 0;    // side B's port (0: learnt from its first datagram)
  FaultRates a_to_b;
  FaultRates b_to_a;
  std::uint64_t seed = 1;
  // The session's implicit CRC fingerprint (configuration_fingerprint(grid, LUTs)), for
  // FaultRates::foreign_session; 0: unknown.
  std::uint64_t configuration_fingerprint = 0;
};

struct FaultCounts {
  std::uint64_t received = 0;
  std::uint64_t forwarded = 0;
  std::uint64_t dropped = 0;
  std::uint64_t duplicated = 0;
  std::uint64_t reordered = 0;
  std::uint64_t delayed = 0;
  std::uint64_t flipped = 0;
  std::uint64_t inserted = 0;
  std::uint64_t foreign_session = 0;
  std::uint64_t resealed_flipped = 0;
  std::uint64_t cut = 0;
  // Every datagram B (or A) received that is not exactly one A (or B) sent: flipped, inserted.
  std::uint64_t altered() const { return flipped + inserted + foreign_session + resealed_flipped; }
};

class FaultProxy {
 public:
  // Binds both ports; throws std::runtime_error naming the port when it cannot.
  explicit FaultProxy(const FaultProxySettings& settings);
  ~FaultProxy();
  FaultProxy(const FaultProxy&) = delete;
  FaultProxy& operator=(const FaultProxy&) = delete;

  void start();
  void stop();
  // New rates from now on, for both directions (a campaign switches a fault on and off). Safe
  // from any thread; takes effect on the proxy's thread a moment later (before the next
  // datagram it handles once the call has returned, on a running proxy).
  void set_rates(const FaultRates& a_to_b, const FaultRates& b_to_a);

  std::uint16_t port_a() const;  // where side A sends
  std::uint16_t port_b() const;  // where side B sends
  FaultCounts counts_a_to_b() const;
  FaultCounts counts_b_to_a() const;
  // {"seed":..,"a_to_b":{"received":..,...},"b_to_a":{...}}
  std::string report_json() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace safecell
