// host/app/printctl/progress_view.h: one view of a job's progress for `printctl run` and
// `printctl submit --wait`: a bar per stage on a terminal, plain lines otherwise.
#pragma once

#include <cstdio>
#include <string>

namespace tp::host::cli {

class ProgressView {
 public:
  /// `tty`: redraw one bar line in place; else one line per stage change and per 10 % step.
  ProgressView(std::FILE* out, bool tty) : out_(out), tty_(tty) {}
  ~ProgressView() { end_line(); }
  ProgressView(const ProgressView&) = delete;
  ProgressView& operator=(const ProgressView&) = delete;

  /// A stage changed state ("running", "done", "reused", "failed"...), after `seconds`.
  void stage(const std::string& stage, const std::string& state, double seconds);
  /// Progress within the running stage: `fraction` 0..1, `detail` such as "swath 3 of 9".
  void progress(const std::string& stage, double fraction, const std::string& detail);

 private:
  void draw(const std::string& stage, double fraction, const std::string& detail);
  void end_line();

  std::FILE* out_;
  bool tty_;
  bool open_line_ = false;
  std::string stage_;
  int last_tenth_ = -1;
};

}  // namespace tp::host::cli
