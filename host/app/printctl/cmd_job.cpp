// host/app/printctl/cmd_job.cpp: printctl validate | run: a job from the command line.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "device/model/printer_model_file.h"
#include "host/app/printctl/commands.h"
#include "host/app/printctl/progress_view.h"
#include "host/common/atomic_file.h"
#include "host/common/failure_report.h"
#include "host/job/manifest.h"
#include "host/job/package.h"
#include "host/pipeline/job_stitch_check.h"
#include "host/pipeline/printer_model.h"
#include "host/pipeline/run_job.h"
#include "host/session/sim_reexec.h"

namespace tp::host::cli {

namespace {

namespace fs = std::filesystem;

// Job limits given with --limit NAME=VALUE (shared by validate and run).
PackageLimits g_limits;
std::vector<std::string> g_limit_specs;

void add_limit_option(CLI::App* cmd) {
  cmd->add_option("--limit", g_limit_specs, "NAME=VALUE: a job limit, as printd's --limit (docs/daemon.md)");
}

// Opens and validates a package under the --limit values; a zip is unpacked into `scratch`.
// `sewable`: also refuse a job with a body whose pattern has no stitches (run leaves that to its
// pattern stage, which writes the refusal into report.json).
Result<Job> open_job(const fs::path& path, const fs::path& scratch, bool sewable = true) {
  for (const auto& l : g_limit_specs)
    if (auto st = set_limit(g_limits, l); !st) return fail(st.error());
  auto pkg = JobPackage::open(path, scratch, g_limits);
  if (!pkg) return fail(pkg.error());
  auto job = load_job(*pkg);
  if (!job) return job;
  // As printd's intake: a job to be sewn on a body needs stitches (read while the files are here).
  if (sewable)
    if (auto st = check_job_stitches(*job); !st) return fail(st.error());
  return job;
}

[[noreturn]] void die(const Error& e, int code) {
  std::fprintf(stderr, "%s\n", e.message.c_str());
  throw CLI::RuntimeError(code);
}

}  // namespace

void register_job_commands(CLI::App& app) {
  static std::string validate_path;
  CLI::App* validate = app.add_subcommand("validate", "Check a job package; exit 0 if it is valid");
  validate->add_option("job", validate_path, "Job folder or .zip")->required();
  add_limit_option(validate);
  validate->callback([] {
    fs::path scratch = fs::temp_directory_path() / ("printctl-validate-" + std::to_string(::getpid()));
    auto job = open_job(validate_path, scratch);
    std::error_code ec;
    fs::remove_all(scratch, ec);
    if (!job) die(job.error(), 1);
    std::printf("%s: valid job '%s'\n", validate_path.c_str(), job->name.c_str());
  });

  static std::string model_job, model_out;
  CLI::App* model = app.add_subcommand("printer-model", "Write the printer model a job plans its swaths for "
                                                        "(for printsim --printer)");
  model->add_option("job", model_job, "Job folder or .zip")->required();
  model->add_option("--out", model_out, "File to write (default: standard output)");
  model->callback([] {
    fs::path scratch = fs::temp_directory_path() / ("printctl-model-" + std::to_string(::getpid()));
    auto job = open_job(model_job, scratch);
    std::error_code ec;
    fs::remove_all(scratch, ec);
    if (!job) die(job.error(), 1);
    auto m = job_printer_model(*job);
    if (!m) die(m.error(), 1);
    const std::string text = device::format_printer_model(*m);
    if (model_out.empty()) {
      std::fputs(text.c_str(), stdout);
      return;
    }
    if (auto st = write_file_atomic(model_out, text); !st) die(st.error(), 1);
  });

  static std::string run_path, run_out, run_printer, run_plan;
  static long long resume_after = -1;
  CLI::App* run = app.add_subcommand("run", "Run a job end to end and print it");
  run->add_option("job", run_path, "Job folder or .zip")->required();
  run->add_option("--out", run_out, "Output folder (report.json, marker.png, pieces, fabric.png)")->required();
  run->add_option("--printer", run_printer, "Override the job's printer: sim, usb or none")
      ->check(CLI::IsMember(printer_choice_names()));
  run->add_option("--resume-after-swath", resume_after, "Swaths up to this index were already printed");
  add_limit_option(run);
  static std::string run_misplace;
  run->add_option("--debug-misplace", run_misplace,
                  "Debug and test hook: print piece P moved DX, DY mm and turned DEG degrees off its planned place "
                  "(P:DX:DY:DEG), the cut file unchanged, to check the printed-seam figures (docs/colour.md)");
  run->add_option("--plan-dir", run_plan,
                  "The job's plan directory: garment, marker and swath plan are stored there when made and "
                  "loaded while their inputs are unchanged (docs/plan-storage.md)");
  run->callback([] {
    fs::path out = fs::absolute(run_out);
    // A zip job is unpacked inside the output folder, afresh on every run.
    std::error_code ec;
    fs::remove_all(out / ".package", ec);
    auto job = open_job(run_path, out / ".package", false);
    if (!job) die(job.error(), 1);
    // The simulated printer is printsim: run this very command again under it, so the job goes
    // through the real USB and GPIO drivers to the emulated devices.
    const std::optional<PrinterChoice> printer_override =
        run_printer.empty() ? std::nullopt : parse_printer_choice(run_printer);
    if (needs_printsim(effective_printer(job->print.printer, printer_override))) {
      // printsim emulates the printer the job is planned for, in the job's print mode.
      auto model = job_printer_model(*job);
      if (!model) die(model.error(), 1);
      fs::create_directories(out, ec);
      const fs::path model_file = out / "printer-model.txt";
      if (auto st = write_file_atomic(model_file, device::format_printer_model(*model)); !st) die(st.error(), 1);
      SimReexec sim;
      sim.out_dir = out;
      sim.printer_model = model_file;
      fs::remove_all(out / ".package", ec);
      if (auto st = reexec_under_printsim(sim); !st) die(st.error(), 2);
    }
    RunOptions opt;
    opt.out_dir = out;
    opt.printer_override = printer_override;
    opt.resume_after_swath = resume_after;
    if (!run_plan.empty()) opt.plan_dir = fs::absolute(run_plan);
    if (!run_misplace.empty()) {
      // P:DX:DY:DEG, the piece name itself may hold ':' (the last three fields are numbers).
      RunOptions::Misplacement m;
      std::string rest = run_misplace;
      double v[3] = {0, 0, 0};
      bool ok = true;
      for (int k = 2; k >= 0 && ok; --k) {
        const std::size_t at = rest.rfind(':');
        if (at == std::string::npos) {
          ok = false;
          break;
        }
        char* end = nullptr;
        const std::string field = rest.substr(at + 1);
        v[k] = std::strtod(field.c_str(), &end);
        ok = !field.empty() && end && *end == 0 && std::isfinite(v[k]);
        rest.resize(at);
      }
      if (!ok || rest.empty())
        die(Error{ErrorCode::kInvalidArgument,
                  "--debug-misplace '" + run_misplace + "': expected PIECE:DX_MM:DY_MM:DEG"},
            1);
      m.piece = rest;
      m.dx_mm = v[0];
      m.dy_mm = v[1];
      m.rotation_deg = v[2];
      opt.misplace_for_test = m;
    }
    // Printers report "no job" as id 0, so a command-line run takes a non-zero id of its own.
    opt.job_id = static_cast<std::int64_t>(std::time(nullptr));
    // The same progress the daemon's events carry, drawn on standard error.
    auto view = std::make_shared<ProgressView>(stderr, ::isatty(2) != 0);
    opt.on_stage = [view](Stage s, StageState st, double secs) {
      view->stage(std::string(to_string(s)), std::string(to_string(st)), secs);
    };
    opt.on_progress = [view](Stage s, double fraction, const std::string& detail) {
      view->progress(std::string(to_string(s)), fraction, detail);
    };
    geometry::CancelToken cancel;
    if (auto st = reserve_report(out, job->name, opt.job_id); !st) die(st.error(), 1);
    if (auto st = run_job(*job, opt, cancel); !st) {
      // report.json is left with the error even when the pipeline could not write its own.
      const std::string state = st.error().code == ErrorCode::kCancelled ? "cancelled" : "failed";
      if (auto r = ensure_failure_report(out, job->name, opt.job_id, state, st.error().message); !r)
        std::fprintf(stderr, "%s\n", r.error().message.c_str());
      die(st.error(), 1);
    }
    std::printf("job '%s' done: %s\n", job->name.c_str(), (out / "report.json").c_str());
  });
}

}  // namespace tp::host::cli
