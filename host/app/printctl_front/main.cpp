// host/app/printctl_front/main.cpp: printctl's front. The daemon client (submit, status, cancel)
// and the token commands run here, in a binary that does not load the imaging libraries:
// OpenImageIO brings some 260 shared libraries, about 0.2 s of CPU at every start, which a cell
// polling `printctl status` paid on each call. Every other command line (run, bench, garment,
// --help, ...) is handed unchanged to printctl-full, which has every command.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "host/app/printctl/commands.h"

namespace {

namespace fs = std::filesystem;

// printctl-full beside this binary (the build tree), else in <prefix>/libexec/printd (installed).
fs::path full_binary() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const fs::path& p : {self.parent_path() / "printctl-full",
                            self.parent_path().parent_path() / "libexec" / "printd" / "printctl-full"})
    if (::access(p.c_str(), X_OK) == 0) return p;
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"printctl: garment print controller command line"};
  app.require_subcommand(1);
  app.fallthrough();
  tp::host::cli::register_daemon_commands(app);
  tp::host::cli::register_token_commands(app);
  // A command line whose command the front registered runs here; any other goes to printctl-full.
  const std::string_view command = argc >= 2 ? argv[1] : "";
  const auto registered = [&](const CLI::App* sub) { return sub->check_name(std::string(command)); };
  if (app.get_subcommands(registered).empty()) {
    const fs::path full = full_binary();
    if (full.empty()) {
      std::fprintf(stderr,
                   "printctl: printctl-full is neither beside this binary nor in ../libexec/printd/; "
                   "only submit, status, cancel and token run without it\n");
      return 127;
    }
    ::execv(full.c_str(), argv);
    std::fprintf(stderr, "printctl: %s: %s\n", full.c_str(), std::strerror(errno));
    return 127;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return 0;
}
