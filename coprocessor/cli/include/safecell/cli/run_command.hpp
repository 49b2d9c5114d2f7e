#pragma once
// `safecell run`: the coprocessor service on the cell file's cameras (capture devices, video
// files, image folders with their times, GStreamer pipelines, network streams) and the link to a
// safecell-controller at a given address: each frame set through the sensing pipeline, its map
// sent to the controller, the same live status line as the demo. Recordings (folders, video
// files) play at their recorded pace. It runs until SIGINT or SIGTERM, --seconds, or until every
// camera has stopped delivering; then the controller gets a stop request (it holds the robot,
// latched until its operator acknowledges), never a silent loss of the link.

#include <cstddef>
#include <ostream>
#include <string>

namespace safecell {

struct RunOptions {
  std::string cell_path;                       // required: the cameras' sources are in it
  std::string lut_cache;                       // empty: the default cache folder
  std::string controller = "127.0.0.1:47701";  // the controller's link address (its link.listen)
  std::string listen = "0.0.0.0:47700";        // this end's (the controller's link.coprocessor)
  std::string reference_dir;                   // <camera>.png per camera (the empty cell)
  bool record_reference = false;    // instead: record it at the start (nobody may be in the cell)
  std::size_t reference_sets = 30;  // frame sets whose median is the recorded reference
  double seconds = 0.0;             // 0: until stopped
  std::string out_dir = "safecell-run";  // the recorded reference, incidents/, run_summary.json
  // The incident recorder keeps this many seconds before each stop or fault (0: off). Each second
  // holds every camera's frames: about 50 MB a second for four 704 x 576 cameras at 30 frames/s.
  double incident_seconds = 2.0;
  // The robot's joint acceleration limit (all joints), rad/s^2: bounds the joint stream's
  // interpolation error at an exposure. Too small a value hides real motion, so the default is
  // above what arms of this class reach.
  double max_acceleration_rad_s2 = 20.0;
  double fps = 30.0;                // the map rate announced in the handshake
  double sync_error_ms = 2.0;       // cameras exposed further apart make their view unknown
  double connect_timeout_s = 30.0;  // waiting for the controller's answer
  // A controller silent this long (no joint state) has restarted or gone: a new session is
  // opened (a restarted controller knows the old one no more and holds the robot meanwhile).
  double new_session_after_s = 1.0;
};

// Returns 0 after a clean stop. Throws CellError, FileError, LutFileError, LinkSetupError
// (the controller refused or never answered) and std::invalid_argument (bad options) for the
// command line to turn into its exit code.
int run_service(const RunOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
