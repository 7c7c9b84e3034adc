// host/app/printctl/cmd_bench_nest.cpp: `printctl bench nest`: nests an ESICUP strip-packing
// instance and prints the density reached in the time given (figures for docs/nesting.md).
#include <cstdio>
#include <fstream>
#include <string>

#include "geometry/nesting/esicup.h"
#include "geometry/nesting/placement_json.h"
#include "geometry/nesting/strip_nester.h"
#include "host/app/printctl/commands.h"

namespace tp::host::cli {
namespace {

struct BenchNestArgs {
  std::string instance;
  double seconds = 60;
  std::uint64_t seed = 0;
  int threads = 2;
  int workers = 2;
  std::uint64_t work = 0;
  std::string out;
  bool progress = false;
};

void run_bench_nest(const BenchNestArgs& a) {
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
  cmd->add_option("--instance", args->instance, "ESICUP instance (JSON)")->required()->check(CLI::ExistingFile);
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
