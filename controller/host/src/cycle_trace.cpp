#include "safecell/controller/host/cycle_trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "safecell/cspace/map_hash.hpp"

namespace safecell {
namespace {

// Fixed-point text without the stream's locale or state: "0.842"; null for a value that is not
// finite (a reader must not take it for a number, least of all a speed scale of 0).
void put_fixed(std::ostream& out, double value) {
  if (!std::isfinite(value)) {
    out << "null";
    return;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  out << text;
}

double fastest_joint(const RobotJoints& joints) {
  double fastest = 0.0;
  for (std::uint32_t j = 0; j < joints.joint_count && j < kMaxJoints; ++j) {
    fastest = std::max(fastest, std::fabs(joints.velocity_rad_s[j]));
  }
  return fastest;
}

}  // namespace

CycleTrace::CycleTrace(std::ostream& out, CellIndex cell_count)
    : out_(out), dense_(cell_bits::words_for(cell_count)) {}

void CycleTrace::map_event(std::uint64_t now_ns, const MapStore& store, std::uint64_t session) {
  const MapView view = store.view();
  view.copy_dense(dense_.data());
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(map_hash(dense_.data(), view.cell_count())));
  char session_hex[17];
  std::snprintf(session_hex, sizeof session_hex, "%016llx",
                static_cast<unsigned long long>(session));
  out_ << R"({"e":"map","t":)" << now_ns << R"(,"session":")" << session_hex << R"(","version":)"
       << store.version() << R"(,"hash":")" << hash << R"(","degraded":)" << store.degraded_blocks()
       << "}\n";
}

void CycleTrace::record(std::uint64_t now_ns, const CycleReport& report, const ControllerLink& link,
                        const MapStore& store) {
  if (store.version() != map_version_ || link.session_id() != session_) {
    map_version_ = store.version();
    session_ = link.session_id();
    if (map_version_ != 0) map_event(now_ns, store, session_);
  }
  const ErrorLatch& latch = link.latch();
  if (latch.total() != link_errors_) {
    link_errors_ = latch.total();
    const LinkFault& fault = link.last_fault();
    out_ << R"({"e":"link_error","t":)" << now_ns << R"(,"error":")" << to_string(fault.error)
         << R"(","detail":)" << fault.detail << R"(,"errors":)" << link_errors_ << R"(,"latched":)"
         << (latch.latched() ? "true" : "false") << "}\n";
  }
  if (link.updates_refused() != maps_refused_) {
    maps_refused_ = link.updates_refused();
    out_ << R"({"e":"map_refused","t":)" << now_ns << R"(,"reason":")"
         << to_string(link.last_map_refusal()) << R"(","refused":)" << maps_refused_ << "}\n";
  }
  if (link.stop_requested() != stop_requested_) {
    stop_requested_ = link.stop_requested();
    if (stop_requested_) {
      out_ << R"({"e":"stop_request","t":)" << now_ns << R"(,"cause":")"
           << fault_cause_name(link.stop_cause()) << "\"}\n";
    } else {
      out_ << R"({"e":"stop_request_cleared","t":)" << now_ns << "}\n";
    }
  }
  out_ << R"({"e":"cycle","t":)" << now_ns << R"(,"state":")" << to_string(report.state)
       << R"(","fault":")" << to_string(report.fault) << R"(","link":")"
       << to_string(report.link_block) << R"(","scale":)";
  put_fixed(out_, report.speed_scale);
  out_ << R"(,"map":)" << report.map_version << R"(,"speed":)";
  put_fixed(out_, fastest_joint(report.joints));
  out_ << "}\n";
  if (now_ns - flushed_ns_ >= kFlushEveryNs) {
    out_.flush();
    flushed_ns_ = now_ns;
  }
}

void CycleTrace::acknowledged(std::uint64_t now_ns) {
  out_ << R"({"e":"acknowledged","t":)" << now_ns << "}\n";
}

}  // namespace safecell
