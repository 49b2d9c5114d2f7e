#pragma once
// The service's stop explanations in a service loop (safecell run, the demo): the first of each
// slow-down or stop goes to the log, every one to the incident recorder.
// Thread context: the service's thread. Private to the CLI.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>
#include <vector>

#include "incident_feed.hpp"
#include "safecell/service/sensing_service.hpp"

namespace safecell {

// Takes the service's new explanations; `seconds_of` turns a coprocessor time into the run's
// seconds. incidents: nullptr when none are recorded. Returns them as logged, with their times.
std::vector<IncidentExplanation> report_stop_explanations(
    SensingService& service, const std::function<double(std::uint64_t)>& seconds_of,
    std::ostream& log, IncidentFeed* incidents);

}  // namespace safecell
