#include "stop_explanations.hpp"

#include "safecell/cli/text_table.hpp"

namespace safecell {

std::vector<IncidentExplanation> report_stop_explanations(
    SensingService& service, const std::function<double(std::uint64_t)>& seconds_of,
    std::ostream& log, IncidentFeed* incidents) {
  std::vector<IncidentExplanation> reported;
  for (const StopExplanation& stop : service.take_stop_explanations()) {
    const double time_s = seconds_of(stop.coprocessor_time_ns);
    std::string line = std::string(stop.stopped ? "stopped" : "slowed down");
    if (stop.critical_joint != 0) line += " for joint " + std::to_string(stop.critical_joint);
    line += ": " + stop.text;
    if (stop.begins) log << fixed(time_s, 2) << " s " << line << '\n';
    if (incidents != nullptr) incidents->stop_explanation(time_s, line);
    reported.push_back({time_s, std::move(line)});
  }
  return reported;
}

}  // namespace safecell
