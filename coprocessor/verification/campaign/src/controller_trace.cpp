#include "safecell/campaign/controller_trace.hpp"

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "safecell/files/atomic_write.hpp"

namespace safecell {
namespace {

std::uint64_t hex_field(const nlohmann::json& line, const char* field) {
  return std::stoull(line.at(field).get<std::string>(), nullptr, 16);
}

// A number, or null for one the controller could not state (not finite).
double number_or_nan(const nlohmann::json& value) {
  return value.is_null() ? std::numeric_limits<double>::quiet_NaN() : value.get<double>();
}

void add_event(ControllerTrace& trace, const nlohmann::json& line) {
  const std::string event = line.at("e").get<std::string>();
  const auto t = line.at("t").get<std::uint64_t>();
  if (event == "cycle") {
    TraceCycle cycle;
    cycle.t_ns = t;
    cycle.state = line.at("state").get<std::string>();
    cycle.fault = line.at("fault").get<std::string>();
    cycle.link = line.at("link").get<std::string>();
    cycle.scale = number_or_nan(line.at("scale"));
    cycle.map_version = line.at("map").get<std::uint64_t>();
    cycle.speed_rad_s = number_or_nan(line.at("speed"));
    // The map events come before the cycle line they were seen in.
    if (!trace.maps.empty() && trace.maps.back().version == cycle.map_version) {
      cycle.session = trace.maps.back().session;
    }
    trace.cycles.push_back(std::move(cycle));
  } else if (event == "map") {
    trace.maps.push_back({t, hex_field(line, "session"), line.at("version").get<std::uint64_t>(),
                          hex_field(line, "hash"), line.at("degraded").get<std::uint32_t>()});
  } else if (event == "link_error") {
    trace.link_errors.push_back({t, line.at("error").get<std::string>(),
                                 line.at("latched").get<bool>(),
                                 line.at("errors").get<std::uint64_t>()});
  } else if (event == "map_refused") {
    trace.map_refusals.push_back(
        {t, line.at("reason").get<std::string>(), line.at("refused").get<std::uint64_t>()});
  } else if (event == "acknowledged") {
    trace.acknowledged_ns.push_back(t);
  } else if (event == "stop_request") {
    trace.stop_requests.push_back({t, line.at("cause").get<std::string>()});
  } else if (event != "stop_request_cleared") {
    throw std::invalid_argument("unknown event \"" + event + "\"");
  }
}

}  // namespace

ControllerTrace read_controller_trace(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw FileError(file, "cannot be read (no controller trace)");
  ControllerTrace trace;
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty()) continue;
    const bool unterminated = in.eof();  // getline met the end before a newline
    try {
      add_event(trace, nlohmann::json::parse(line));
    } catch (const std::exception& error) {
      if (unterminated) break;  // the last line, cut short by a kill
      throw FileError(file, "line " + std::to_string(number) +
                                " is not a controller trace event (" + error.what() + ")");
    }
  }
  return trace;
}

}  // namespace safecell
