// host/session/sim_reexec.cpp: re-running a command under printsim.
#include "host/session/sim_reexec.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

namespace tp::host {

namespace {

std::filesystem::path self_exe() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return {};
  buf[n] = 0;
  return buf;
}

}  // namespace

bool under_printsim() { return printsim_out_dir().has_value(); }

std::optional<std::filesystem::path> printsim_out_dir() {
  const char* v = std::getenv("TP_PRINTSIM");
  if (!v || !*v) return std::nullopt;
  return std::filesystem::path(v);
}

std::vector<std::string> printsim_command(int argc, char** argv, const SimReexec& o) {
  const std::filesystem::path exe = self_exe();
  std::vector<std::string> cmd{(exe.parent_path() / "printsim").string(), "run", "--out", o.out_dir.string()};
  if (o.scenario) cmd.insert(cmd.end(), {"--scenario", o.scenario->string()});
  if (o.printer_model) cmd.insert(cmd.end(), {"--printer", o.printer_model->string()});
  if (o.job_dirs) cmd.push_back("--job-dirs");
  if (!o.fabric) cmd.push_back("--no-fabric");
  if (o.speed > 0) cmd.insert(cmd.end(), {"--speed", std::to_string(o.speed)});
  cmd.push_back("--");
  // The same program by its real path, so a relative argv[0] still resolves.
  cmd.push_back(exe.empty() ? std::string(argv[0]) : exe.string());
  for (int i = 1; i < argc; ++i) cmd.emplace_back(argv[i]);
  return cmd;
}

Status reexec_under_printsim(int argc, char** argv, const SimReexec& options) {
  if (under_printsim()) return {};
  const auto cmd = printsim_command(argc, argv, options);
  if (access(cmd[0].c_str(), X_OK) != 0)
    return fail(ErrorCode::kPrinter, cmd[0] + ": printsim not found next to this program (build the 'printsim' target)");
  std::vector<char*> args;
  for (const auto& a : cmd) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  execv(args[0], args.data());
  return fail(ErrorCode::kPrinter, cmd[0] + ": cannot run: " + std::strerror(errno));
}

Status reexec_under_printsim(const SimReexec& options) {
  if (under_printsim()) return {};
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  for (std::size_t at = 0; at < all.size();) {
    const std::size_t end = all.find('\0', at);
    args.push_back(all.substr(at, end == std::string::npos ? std::string::npos : end - at));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  if (args.empty()) return fail(ErrorCode::kPrinter, "cannot read this process's arguments from /proc/self/cmdline");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return reexec_under_printsim(static_cast<int>(args.size()), argv.data(), options);
}

}  // namespace tp::host
