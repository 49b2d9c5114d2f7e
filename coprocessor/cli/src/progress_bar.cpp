#include "progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "safecell/cli/text_table.hpp"

namespace safecell {
namespace {

constexpr int kBarWidth = 30;

}  // namespace

ProgressBar::ProgressBar(std::ostream& out, bool interactive)
    : out_(out), interactive_(interactive), stage_start_(Clock::now()) {}

ProgressBar::~ProgressBar() { finish(); }

bool ProgressBar::stderr_is_terminal() { return ::isatty(STDERR_FILENO) == 1; }

void ProgressBar::update(const std::string& stage, double fraction_done) {
  const auto now = Clock::now();
  const double fraction = std::clamp(fraction_done, 0.0, 1.0);
  if (stage != stage_) {
    if (line_open_ && interactive_) out_ << '\n';
    line_open_ = false;
    if (!stage_.empty()) {
      stages_[stage_].spent_s += std::chrono::duration<double>(now - stage_start_).count();
    }
    stage_ = stage;
    stage_start_ = now;
    last_draw_ = Clock::time_point{};
  }
  StageClock& clock = stages_[stage_];
  const double elapsed_s =
      clock.spent_s + std::chrono::duration<double>(now - stage_start_).count();
  const std::string left =
      fraction > 0.02 ? fixed(elapsed_s * (1.0 - fraction) / fraction, 1) + " s left" : "";
  if (interactive_) {
    if (now - last_draw_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
    last_draw_ = now;
    const int filled = static_cast<int>(std::lround(fraction * kBarWidth));
    out_ << '\r' << stage_ << " [" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kBarWidth - filled), '.') << "] "
         << static_cast<int>(fraction * 100.0) << "% " << left << "   " << std::flush;
    line_open_ = true;
    return;
  }
  const int quarter = static_cast<int>(fraction * 4.0);
  if (quarter == clock.last_quarter) return;
  clock.last_quarter = quarter;
  out_ << stage_ << ": " << quarter * 25 << "%" << (left.empty() ? "" : ", " + left) << '\n'
       << std::flush;
}

void ProgressBar::finish() {
  if (line_open_ && interactive_) out_ << '\n' << std::flush;
  line_open_ = false;
}

}  // namespace safecell
