// host/app/printctl/cmd_token.cpp: printctl token add | list | revoke: the HTTP API's bearer
// tokens, kept hashed in printd's job store (<state-dir>/jobs.db).
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "host/app/printctl/commands.h"
#include "host/store/token_store.h"

namespace tp::host::cli {

namespace {

namespace fs = std::filesystem;

TokenStore open_tokens(const std::string& state_dir) {
  const fs::path db = fs::path(state_dir) / "jobs.db";
  std::error_code ec;
  if (!fs::exists(db, ec)) {
    std::fprintf(stderr, "printctl: %s: no job store (start printd with --state-dir %s first)\n", db.c_str(),
                 state_dir.c_str());
    throw CLI::RuntimeError(3);
  }
  auto s = TokenStore::open(db);
  if (!s) {
    std::fprintf(stderr, "printctl: %s\n", s.error().message.c_str());
    throw CLI::RuntimeError(3);
  }
  return std::move(*s);
}

}  // namespace

void register_token_commands(CLI::App& app) {
  static std::string state_dir = "/var/lib/printd";
  CLI::App* token = app.add_subcommand("token", "Bearer tokens of printd's HTTP API");
  token->require_subcommand(1);
  token->add_option("--state-dir", state_dir, "printd's state directory")->capture_default_str();

  static std::string add_name;
  static bool read_only = false;
  CLI::App* add = token->add_subcommand("add", "Make a token; its secret is printed once");
  add->add_option("name", add_name, "A name for whoever uses it (unique among live tokens)")->required();
  add->add_flag("--read-only", read_only, "GET routes only (dashboards)");
  add->callback([] {
    TokenStore s = open_tokens(state_dir);
    auto t = s.add(add_name, read_only ? TokenScope::kRead : TokenScope::kAdmin);
    if (!t) {
      std::fprintf(stderr, "printctl: %s\n", t.error().message.c_str());
      throw CLI::RuntimeError(1);
    }
    std::fprintf(stderr, "token %lld '%s' (%s); keep the secret, it is not stored:\n",
                 static_cast<long long>(t->record.id), t->record.name.c_str(),
                 std::string(to_string(t->record.scope)).c_str());
    std::printf("%s\n", t->secret.c_str());
  });

  CLI::App* list = token->add_subcommand("list", "List tokens (never their secrets)");
  list->callback([] {
    TokenStore s = open_tokens(state_dir);
    auto l = s.list();
    if (!l) {
      std::fprintf(stderr, "printctl: %s\n", l.error().message.c_str());
      throw CLI::RuntimeError(1);
    }
    std::printf("%-5s %-24s %-6s %-20s %s\n", "ID", "NAME", "SCOPE", "CREATED (UTC)", "STATE");
    for (const auto& t : *l) {
      std::time_t secs = static_cast<std::time_t>(t.created_ms / 1000);
      char when[32];
      std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::gmtime(&secs));
      std::printf("%-5lld %-24s %-6s %-20s %s\n", static_cast<long long>(t.id), t.name.c_str(),
                  std::string(to_string(t.scope)).c_str(), when, t.revoked ? "revoked" : "live");
    }
  });

  static std::string revoke_what;
  CLI::App* revoke = token->add_subcommand("revoke", "Revoke a token by name or id (at once: no restart)");
  revoke->add_option("token", revoke_what, "Name or id")->required();
  revoke->callback([] {
    TokenStore s = open_tokens(state_dir);
    if (auto st = s.revoke(revoke_what); !st) {
      std::fprintf(stderr, "printctl: %s\n", st.error().message.c_str());
      throw CLI::RuntimeError(1);
    }
    std::printf("token '%s' revoked\n", revoke_what.c_str());
  });
}

}  // namespace tp::host::cli
