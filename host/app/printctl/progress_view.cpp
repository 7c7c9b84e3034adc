// host/app/printctl/progress_view.cpp: drawing the progress bar or its plain-line form.
#include "host/app/printctl/progress_view.h"

#include <algorithm>
#include <cmath>

namespace tp::host::cli {

void ProgressView::end_line() {
  if (open_line_) std::fputc('\n', out_);
  open_line_ = false;
  std::fflush(out_);
}

void ProgressView::draw(const std::string& stage, double fraction, const std::string& detail) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(std::lround(fraction * kWidth));
  std::string bar(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(kWidth - filled), '.');
  std::fprintf(out_, "\r%-8s [%s] %3d%% %-28s", stage.c_str(), bar.c_str(), static_cast<int>(fraction * 100),
               detail.c_str());
  open_line_ = true;
  std::fflush(out_);
}

void ProgressView::stage(const std::string& stage, const std::string& state, double seconds) {
  if (state == "running") {
    if (stage != stage_) end_line();
    stage_ = stage;
    last_tenth_ = -1;
    if (tty_) draw(stage, 0, "");
    else std::fprintf(out_, "%s: running\n", stage.c_str());
    std::fflush(out_);
    return;
  }
  if (tty_ && stage == stage_ && (state == "done" || state == "reused")) {
    draw(stage, 1.0, state + " in " + std::to_string(static_cast<int>(seconds * 10) / 10.0).substr(0, 5) + " s");
    end_line();
    return;
  }
  end_line();
  std::fprintf(out_, "%s: %s (%.2f s)\n", stage.c_str(), state.c_str(), seconds);
  std::fflush(out_);
}

void ProgressView::progress(const std::string& stage, double fraction, const std::string& detail) {
  if (tty_) return draw(stage, fraction, detail);
  const int tenth = static_cast<int>(std::floor(std::clamp(fraction, 0.0, 1.0) * 10));
  if (stage == stage_ && tenth <= last_tenth_) return;
  stage_ = stage;
  last_tenth_ = tenth;
  std::fprintf(out_, "%s: %d%% %s\n", stage.c_str(), static_cast<int>(fraction * 100), detail.c_str());
  std::fflush(out_);
}

}  // namespace tp::host::cli
