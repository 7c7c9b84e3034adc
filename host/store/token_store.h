// host/store/token_store.h: the HTTP API's bearer tokens, kept as SHA-256 hashes in the job store
// (table api_tokens), each with a name and a scope: "admin" (everything) or "read" (GET only).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "host/common/error.h"

struct sqlite3;

namespace tp::host {

enum class TokenScope { kRead, kAdmin };
std::string_view to_string(TokenScope s);
std::optional<TokenScope> token_scope_from_string(std::string_view s);

/// A token as listed (never its secret: only the hash is stored).
struct TokenRecord {
  std::int64_t id = 0;
  std::string name;
  TokenScope scope = TokenScope::kRead;
  std::int64_t created_ms = 0;
  bool revoked = false;
};

/// A freshly made token: the secret is shown once, to whoever added it.
struct NewToken {
  TokenRecord record;
  std::string secret;  ///< "tp_" + 64 hex digits from /dev/urandom
};

/// Bearer tokens in `<state-dir>/jobs.db`. One instance per thread.
class TokenStore {
 public:
  TokenStore(TokenStore&&) noexcept;
  TokenStore& operator=(TokenStore&&) noexcept;
  ~TokenStore();

  [[nodiscard]] static Result<TokenStore> open(const std::filesystem::path& db_path);

  /// Makes a token named `name` (1..64 printable ASCII characters, unique among live tokens).
  [[nodiscard]] Result<NewToken> add(const std::string& name, TokenScope scope);
  [[nodiscard]] Result<std::vector<TokenRecord>> list();
  /// Revokes the live token named `name` or with that id; fails (kInvalidArgument) when none.
  [[nodiscard]] Status revoke(const std::string& name_or_id);
  /// The live token whose hash matches `secret`, or nullopt.
  [[nodiscard]] Result<std::optional<TokenRecord>> check(const std::string& secret);
  /// Whether any live token exists.
  [[nodiscard]] Result<bool> any_live();

 private:
  explicit TokenStore(sqlite3* db) : db_(db) {}
  sqlite3* db_ = nullptr;
};

}  // namespace tp::host
