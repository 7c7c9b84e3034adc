// host/app/printctl/cmd_pattern.cpp: `printctl pattern suggest`: stitches proposed for a pattern, as an editable stitches file.
#include <cstdio>
#include <filesystem>
#include <string>

#include "geometry/pattern/import/load_pattern.h"
#include "geometry/pattern/stitches_json.h"
#include "geometry/pattern/suggest_stitches.h"
#include "geometry/pattern/validate.h"
#include "host/app/printctl/commands.h"
#include "host/pipeline/garment_files.h"

namespace tp::host::cli {
namespace {

struct SuggestArgs {
  std::string file;
  std::string out;
  double min_score = geometry::SuggestOptions{}.min_score;
};

[[noreturn]] void die(const std::string& msg, int code) {
  std::fprintf(stderr, "printctl pattern suggest: %s\n", msg.c_str());
  throw CLI::RuntimeError(code);
}

void run_suggest(const SuggestArgs& a) {
  auto pattern = geometry::load_pattern(a.file);
  if (!pattern) die(pattern.error().what(), 2);
  if (auto st = geometry::validate_pattern(*pattern); !st) die(st.error().what(), 2);
  geometry::SuggestOptions opt;
  opt.min_score = a.min_score;
  auto suggestions = geometry::suggest_stitches(*pattern, opt);
  const std::string text = geometry::write_stitches_json(*pattern, suggestions);
  if (a.out.empty()) {
    std::fputs(text.c_str(), stdout);
  } else if (auto st = write_text_file(a.out, text); !st) {
    die(st.error().message, 1);
  }
  // A summary on stderr keeps standard output a clean stitches file.
  int stitches = 0;
  for (const auto& s : suggestions) stitches += static_cast<int>(s.stitches.size());
  std::fprintf(stderr, "pattern=%s pieces=%zu own_stitches=%zu suggestions=%zu stitches=%d min_score=%.2f%s%s\n",
               pattern->name.c_str(), pattern->pieces.size(), pattern->stitches.size(), suggestions.size(), stitches,
               a.min_score, a.out.empty() ? "" : " out=", a.out.c_str());
}

}  // namespace

void register_pattern_commands(CLI::App& app) {
  CLI::App* pattern = app.add_subcommand("pattern", "Pattern tools");
  pattern->require_subcommand(1);
  auto args = std::make_shared<SuggestArgs>();
  CLI::App* cmd = pattern->add_subcommand("suggest", "Suggest stitches for a pattern; write them as a stitches file "
                                                     "(edit it, then give it to a job as garment.stitches_file)");
  cmd->add_option("file", args->file, "pattern file (native JSON, GarmentCode, FreeSewing SVG, DXF-AAMA)")->required();
  cmd->add_option("--out", args->out, "stitches file to write (default: standard output)");
  cmd->add_option("--min-score", args->min_score, "drop suggestions scoring below this (0..1)")->check(CLI::Range(0.0, 1.0));
  cmd->callback([args] { run_suggest(*args); });
}

}  // namespace tp::host::cli
