// host/app/printctl/cmd_bench_nest.cpp: `printctl bench nest`: nests an ESICUP strip-packing
// instance, or the markers of the sample garments at several sizes, and prints the density
// reached in the time given (figures for docs/nesting.md).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/allowance/allowance_widths.h"
#include "geometry/allowance/cut_outline.h"
#include "geometry/nesting/esicup.h"
#include "geometry/nesting/nest_pieces.h"
#include "geometry/nesting/placement_json.h"
#include "geometry/nesting/strip_nester.h"
#include "geometry/samples/garments.h"
#include "geometry/samples/sizes.h"
#include "host/app/printctl/commands.h"

namespace tp::host::cli {
namespace {

struct BenchNestArgs {
  std::string instance;
  std::string garments;             // "all" or comma-separated names
  std::string sizes = "S,M,L";
  double fabric_width_mm = 1500;
  double gap_mm = 0;
  double seconds = 60;
  std::uint64_t seed = 0;
  int threads = 2;
  int workers = 2;
  std::uint64_t work = 0;
  std::string out;
  bool progress = false;
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

[[noreturn]] void bench_fail(const std::string& message, int code) {
  std::fprintf(stderr, "printctl bench nest: %s\n", message.c_str());
  throw CLI::RuntimeError(code);
}

// Cut outlines (default finishing) of a drafted sample garment, one item per piece: the
// pattern already holds left and right pieces separately.
std::vector<geometry::NestItem> garment_items(const geometry::Pattern& pattern) {
  const geometry::Finishing finishing;
  std::vector<geometry::NestItem> items;
  for (size_t i = 0; i < pattern.pieces.size(); ++i) {
    const geometry::Piece& piece = pattern.pieces[i];
    auto allowance = geometry::resolve_allowance(pattern, static_cast<int>(i), finishing);
    if (!allowance) bench_fail(allowance.error().what(), 1);
    auto outline = geometry::cut_outline(piece, *allowance, finishing.mitre_limit);
    if (!outline) bench_fail(outline.error().what(), 1);
    geometry::NestItem it;
    it.piece = static_cast<int>(i);
    it.name = piece.name;
    it.outline_mm = *outline;
    if (piece.grain) it.grain = piece.grain->to_mm - piece.grain->from_mm;
    items.push_back(std::move(it));
  }
  return items;
}

void run_bench_garments(const BenchNestArgs& a) {
  std::vector<std::string> names = a.garments == "all" ? geometry::samples::garment_names() : split_list(a.garments);
  for (const std::string& name : names) {
    for (const std::string& size : split_list(a.sizes)) {
      auto m = geometry::samples::standard_size(size);
      if (!m) bench_fail(m.error().what(), 2);
      auto pattern = geometry::samples::draft_garment(name, *m, size);
      if (!pattern) bench_fail(pattern.error().what(), 2);
      const auto items = garment_items(*pattern);
      geometry::NestOptions o;
      o.fabric_width_mm = a.fabric_width_mm;
      o.gap_mm = a.gap_mm;
      o.time_limit_s = a.seconds;
      o.seed = a.seed;
      o.threads = a.threads;
      o.workers = a.workers;
      o.work_limit = a.work;
      auto markers = geometry::nest_pieces(items, o);
      if (!markers) bench_fail(markers.error().what(), 1);
      double length = 0, area = 0;
      for (const geometry::Marker& mk : *markers) {
        length += mk.length_mm;
        area += mk.utilisation * mk.width_mm * mk.length_mm;
      }
      std::printf("garment=%s size=%s pieces=%zu width_mm=%.0f length_mm=%.1f utilisation=%.4f\n", name.c_str(),
                  size.c_str(), items.size(), a.fabric_width_mm, length, area / (a.fabric_width_mm * length));
    }
  }
}

void run_bench_nest(const BenchNestArgs& a) {
  if (!a.garments.empty()) {
    run_bench_garments(a);
    return;
  }
  if (a.instance.empty()) bench_fail("give --instance <file> or --garments <names|all>", 2);
  auto problem = geometry::load_esicup(a.instance);
  if (!problem) {
    std::fprintf(stderr, "printctl bench nest: %s\n", problem.error().what().c_str());
    throw CLI::RuntimeError(2);
  }
  geometry::StripOptions o;
  o.time_limit_s = a.seconds;
  o.seed = a.seed;
  o.threads = a.threads;
  o.workers = a.workers;
  o.work_limit = a.work;
  o.improve = a.seconds > 0;
  if (a.progress)
    o.on_improvement = [](double length, double density, double s) {
      std::fprintf(stderr, "  t=%.2fs length=%.4f density=%.4f\n", s, length, density);
    };
  auto sol = geometry::nest_strip(*problem, o);
  if (!sol) {
    std::fprintf(stderr, "printctl bench nest: %s\n", sol.error().what().c_str());
    throw CLI::RuntimeError(1);
  }
  std::printf("instance=%s seconds=%.2f density=%.4f length=%.4f\n", problem->name.c_str(), sol->seconds, sol->density,
              sol->length);
  std::printf("constructive_length=%.4f iterations=%llu evaluations=%llu\n", sol->constructive_length,
              static_cast<unsigned long long>(sol->iterations), static_cast<unsigned long long>(sol->evaluations));
  if (!a.out.empty()) {
    std::ofstream f(a.out, std::ios::binary);
    f << geometry::placement_json(*problem, *sol);
    if (!f) {
      std::fprintf(stderr, "printctl bench nest: %s: cannot write\n", a.out.c_str());
      throw CLI::RuntimeError(1);
    }
  }
}

}  // namespace

void register_bench_nest(CLI::App& bench) {
  auto args = std::make_shared<BenchNestArgs>();
  CLI::App* cmd = bench.add_subcommand("nest", "Nest an ESICUP strip-packing instance and print its density");
  cmd->add_option("--instance", args->instance, "ESICUP instance (JSON)")->check(CLI::ExistingFile);
  cmd->add_option("--garments", args->garments, "sample garments to nest instead: names (comma-separated) or all");
  cmd->add_option("--sizes", args->sizes, "sizes of the sample garments (comma-separated)");
  cmd->add_option("--fabric-width", args->fabric_width_mm, "fabric width in mm for the garments")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--gap", args->gap_mm, "gap between garment pieces in mm")->check(CLI::NonNegativeNumber);
  cmd->add_option("--seconds", args->seconds, "time limit in seconds (0: constructive placement only)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", args->seed, "random seed");
  cmd->add_option("--threads", args->threads, "threads running the search workers")->check(CLI::PositiveNumber);
  cmd->add_option("--workers", args->workers, "parallel search workers (changes the result; threads do not)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--work", args->work, "work budget in separator iterations (0: none; reproducible runs)");
  cmd->add_option("--out", args->out, "write the placement JSON here");
  cmd->add_flag("--progress", args->progress, "print each improvement to stderr");
  cmd->callback([args] { run_bench_nest(*args); });
}

}  // namespace tp::host::cli
