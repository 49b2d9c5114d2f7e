#pragma once
// The controller's trace: every safety cycle and every link event as one JSON line each, for
// fault campaigns and post-mortems (safecell-controller --trace FILE).
//
//   {"e":"cycle","t":NS,"state":"moving","fault":"none","link":"none","scale":0.84,
//    "map":12,"speed":0.41}
//   {"e":"map","t":NS,"session":"89abcdef01234567","version":12,"hash":"0123456789abcdef",
//    "degraded":0}
//   {"e":"link_error","t":NS,"error":"loss","detail":3,"errors":2,"latched":true}
//   {"e":"map_refused","t":NS,"reason":"map hash mismatch","refused":1}
//   {"e":"acknowledged","t":NS}
//   {"e":"stop_request","t":NS,"cause":"operator"}   (and "stop_request_cleared")
//
// t: the controller's monotonic clock in ns (CLOCK_MONOTONIC: on one machine the coprocessor's
// std::chrono::steady_clock, so a campaign can line its own events up with these). speed: the
// robot's fastest joint, rad/s, as read this cycle; scale and speed are null when not finite. The
// map line's hash is computed here from the held map's cells (map_hash.hpp over
// MapView::copy_dense), not copied from the update, so a campaign can compare what the controller
// holds with what the coprocessor sent; a store with degraded blocks holds more forbidden cells
// than were sent and hashes differently. Thread context: the cycle's thread. Hosted code: it writes
// to a buffered stream and keeps a dense copy of the map (allocated once); flushed every 50 ms (a
// killed program loses at most that much) and by flush().

#include <cstdint>
#include <ostream>
#include <vector>

#include "safecell/controller/controller_link.hpp"
#include "safecell/controller/map_store.hpp"
#include "safecell/controller/safety_cycle.hpp"

namespace safecell {

class CycleTrace {
 public:
  CycleTrace(std::ostream& out, CellIndex cell_count);

  // After each cycle: its line, and the events since the last (a new map, link errors, a stop
  // request set or cleared).
  void record(std::uint64_t now_ns, const CycleReport& report, const ControllerLink& link,
              const MapStore& store);
  // An operator's acknowledgement, when it is handed to the cycle.
  void acknowledged(std::uint64_t now_ns);
  void flush() { out_.flush(); }

 private:
  void map_event(std::uint64_t now_ns, const MapStore& store, std::uint64_t session);

  std::ostream& out_;
  std::vector<std::uint64_t> dense_;
  std::uint64_t map_version_ = 0;
  std::uint64_t session_ = 0;
  static constexpr std::uint64_t kFlushEveryNs = 50'000'000;
  std::uint64_t flushed_ns_ = 0;
  std::uint64_t link_errors_ = 0;
  std::uint64_t maps_refused_ = 0;
  bool stop_requested_ = false;
};

}  // namespace safecell
