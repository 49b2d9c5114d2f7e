#pragma once
// `safecell replay INCIDENT`: the sensing pipeline run again, offline, on an incident folder the
// service recorded (incident_folder.hpp): each cycle's recorded frames with the robot's recorded
// pose give a forbidden map that is compared bit for bit with the map the service sent, and the
// report of the demo is drawn from it (the cameras at the trigger with what they saw, C-space
// slices with the robot's path, the timeline of the controller's joint stream) into
// <out>/index.html. Needs the cell file and the tables the service ran with: the cell file's text
// and the grid and table fingerprints must be those recorded.

#include <ostream>
#include <string>

namespace safecell {

struct ReplayOptions {
  std::string incident_dir;
  std::string cell_path;  // empty: the cell file the incident names
  std::string lut_cache;  // empty: the default cache
  std::string out_dir;    // empty: <incident>/replay
};

// Returns 0 when every replayed map equals the one sent, 1 when one differs (each is named on
// `err` and in replay.json). Throws FileError or std::invalid_argument for an incident or setup
// it cannot replay.
int run_replay(const ReplayOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
