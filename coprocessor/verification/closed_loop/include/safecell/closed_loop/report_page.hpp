#pragma once
// The report folder's index.html: one page with the verdict, the figures and the pictures, so a
// person who opens the folder sees what happened without reading code. Paths are relative to the
// folder; text is escaped. Once loaded, the page marks how many pictures loaded
// (<html data-pictures-loaded="N of M">) and names any that did not in a red line.

#include <string>
#include <utility>
#include <vector>

namespace safecell {

struct ReportPicture {
  std::string path;     // relative to the report folder
  std::string caption;  // what to look at in it
};

struct ReportPage {
  std::string title;
  std::string verdict;  // one sentence: did the run do what it must
  bool passed = true;   // colours the verdict
  std::string story;    // what happened, in a paragraph
  std::vector<std::pair<std::string, std::string>> figures;  // name, value
  ReportPicture
      film;  // a video (WebM or MP4) shown above the pictures; none when its path is empty
  std::vector<ReportPicture> pictures;
};

std::string report_page_html(const ReportPage& page);

}  // namespace safecell
