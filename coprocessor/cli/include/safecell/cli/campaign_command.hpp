#pragma once
// `safecell campaign`: the fault campaign of ../shared/SAFETY.md on loopback with real processes
// (campaign/fault_campaign.hpp): every fault class (or those asked for) in a trial of a few
// seconds against the safecell-controller program, its table printed, campaign.json written.

#include <ostream>
#include <string>

namespace safecell {

struct CampaignOptions {
  std::string faults;  // comma-separated class names; empty: all
  std::string cell_path;
  std::string lut_cache;
  std::string out_dir = "safecell-campaign";
  std::string controller_program;
  double settle_s = 2.0;
  double fault_s = 1.5;
  double recover_s = 4.0;
  double rate = 0.3;
  unsigned long long seed = 1;
  bool json = false;
  // The negative control: the controller's watchdog and data age limit (ms); 0: the campaign's.
  double test_only_controller_limits_ms = 0.0;
};

// 0 when every trial passed, 1 when one failed (named on `err`, in the table and the JSON).
int run_campaign(const CampaignOptions& options, std::ostream& out, std::ostream& err);

}  // namespace safecell
