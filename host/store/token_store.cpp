// host/store/token_store.cpp: SQLite table and statements behind the HTTP API's bearer tokens.
#include "host/store/token_store.h"

#include <sqlite3.h>

#include <chrono>
#include <cstdio>
#include <utility>

#include "host/common/sha256.h"

namespace tp::host {

namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS api_tokens (
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  name TEXT NOT NULL,
  hash TEXT NOT NULL UNIQUE,
  scope TEXT NOT NULL,
  created_ms INTEGER NOT NULL,
  revoked INTEGER NOT NULL DEFAULT 0
);
)sql";

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::string hash_of(const std::string& secret) {
  Sha256 h;
  h.update(secret);
  return h.hex_digest();
}

// A prepared statement that is finalised on every path.
struct Stmt {
  Stmt(sqlite3* db, const char* sql) { ok = sqlite3_prepare_v2(db, sql, -1, &st, nullptr) == SQLITE_OK; }
  ~Stmt() { sqlite3_finalize(st); }
  Stmt(const Stmt&) = delete;
  Stmt& operator=(const Stmt&) = delete;
  void bind(int i, const std::string& v) { sqlite3_bind_text(st, i, v.c_str(), -1, SQLITE_TRANSIENT); }
  void bind(int i, std::int64_t v) { sqlite3_bind_int64(st, i, v); }
  std::string text(int c) const {
    const unsigned char* t = sqlite3_column_text(st, c);
    return t ? reinterpret_cast<const char*>(t) : "";
  }
  sqlite3_stmt* st = nullptr;
  bool ok = false;
};

TokenRecord read_token(const Stmt& s) {
  TokenRecord r;
  r.id = sqlite3_column_int64(s.st, 0);
  r.name = s.text(1);
  r.scope = token_scope_from_string(s.text(2)).value_or(TokenScope::kRead);
  r.created_ms = sqlite3_column_int64(s.st, 3);
  r.revoked = sqlite3_column_int64(s.st, 4) != 0;
  return r;
}

Result<std::string> random_secret() {
  unsigned char bytes[32];
  std::FILE* f = std::fopen("/dev/urandom", "rb");
  if (!f) return fail(ErrorCode::kIo, "/dev/urandom: cannot open");
  const size_t n = std::fread(bytes, 1, sizeof bytes, f);
  std::fclose(f);
  if (n != sizeof bytes) return fail(ErrorCode::kIo, "/dev/urandom: short read");
  static const char* hex = "0123456789abcdef";
  std::string s = "tp_";
  for (unsigned char b : bytes) {
    s += hex[b >> 4];
    s += hex[b & 15];
  }
  return s;
}

}  // namespace

std::string_view to_string(TokenScope s) {
  switch (s) {
    case TokenScope::kRead: return "read";
    case TokenScope::kAdmin: return "admin";
  }
  return "read";
}

std::optional<TokenScope> token_scope_from_string(std::string_view s) {
  if (s == "read") return TokenScope::kRead;
  if (s == "admin") return TokenScope::kAdmin;
  return std::nullopt;
}

TokenStore::TokenStore(TokenStore&& o) noexcept : db_(std::exchange(o.db_, nullptr)) {}
TokenStore& TokenStore::operator=(TokenStore&& o) noexcept {
  if (this != &o) {
    sqlite3_close(db_);
    db_ = std::exchange(o.db_, nullptr);
  }
  return *this;
}
TokenStore::~TokenStore() { sqlite3_close(db_); }

Result<TokenStore> TokenStore::open(const std::filesystem::path& db_path) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    std::string msg = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    return fail(ErrorCode::kStore, db_path.string() + ": cannot open the token store: " + msg);
  }
  TokenStore store(db);
  sqlite3_busy_timeout(db, 5000);
  char* err = nullptr;
  if (sqlite3_exec(db, kSchema, nullptr, nullptr, &err) != SQLITE_OK) {
    std::string msg = err ? err : "?";
    sqlite3_free(err);
    return fail(ErrorCode::kStore, db_path.string() + ": api_tokens: " + msg);
  }
  return store;
}

Result<NewToken> TokenStore::add(const std::string& name, TokenScope scope) {
  if (name.empty() || name.size() > 64)
    return fail(ErrorCode::kInvalidArgument, "token name must be 1 to 64 characters");
  for (unsigned char c : name)
    if (c < 0x21 || c > 0x7e)
      return fail(ErrorCode::kInvalidArgument, "token name '" + name + "': printable ASCII without spaces only");
  {
    Stmt s(db_, "SELECT 1 FROM api_tokens WHERE name=? AND revoked=0");
    s.bind(1, name);
    if (!s.ok) return fail(ErrorCode::kStore, std::string("token add: ") + sqlite3_errmsg(db_));
    if (sqlite3_step(s.st) == SQLITE_ROW)
      return fail(ErrorCode::kInvalidArgument, "a live token named '" + name + "' exists; revoke it first");
  }
  auto secret = random_secret();
  if (!secret) return std::unexpected(secret.error());
  NewToken t;
  t.secret = *secret;
  t.record.name = name;
  t.record.scope = scope;
  t.record.created_ms = now_ms();
  Stmt s(db_, "INSERT INTO api_tokens(name, hash, scope, created_ms) VALUES(?,?,?,?)");
  s.bind(1, name);
  s.bind(2, hash_of(t.secret));
  s.bind(3, std::string(to_string(scope)));
  s.bind(4, t.record.created_ms);
  if (!s.ok || sqlite3_step(s.st) != SQLITE_DONE)
    return fail(ErrorCode::kStore, std::string("token add: ") + sqlite3_errmsg(db_));
  t.record.id = sqlite3_last_insert_rowid(db_);
  return t;
}

Result<std::vector<TokenRecord>> TokenStore::list() {
  Stmt s(db_, "SELECT id, name, scope, created_ms, revoked FROM api_tokens ORDER BY id");
  if (!s.ok) return fail(ErrorCode::kStore, std::string("token list: ") + sqlite3_errmsg(db_));
  std::vector<TokenRecord> out;
  int rc;
  while ((rc = sqlite3_step(s.st)) == SQLITE_ROW) out.push_back(read_token(s));
  if (rc != SQLITE_DONE) return fail(ErrorCode::kStore, std::string("token list: ") + sqlite3_errmsg(db_));
  return out;
}

Status TokenStore::revoke(const std::string& name_or_id) {
  Stmt s(db_, "UPDATE api_tokens SET revoked=1 WHERE revoked=0 AND (name=? OR CAST(id AS TEXT)=?)");
  s.bind(1, name_or_id);
  s.bind(2, name_or_id);
  if (!s.ok || sqlite3_step(s.st) != SQLITE_DONE)
    return fail(ErrorCode::kStore, std::string("token revoke: ") + sqlite3_errmsg(db_));
  if (sqlite3_changes(db_) == 0)
    return fail(ErrorCode::kInvalidArgument, "no live token named or numbered '" + name_or_id + "'");
  return {};
}

Result<std::optional<TokenRecord>> TokenStore::check(const std::string& secret) {
  Stmt s(db_, "SELECT id, name, scope, created_ms, revoked FROM api_tokens WHERE hash=? AND revoked=0");
  if (!s.ok) return fail(ErrorCode::kStore, std::string("token check: ") + sqlite3_errmsg(db_));
  s.bind(1, hash_of(secret));
  const int rc = sqlite3_step(s.st);
  if (rc == SQLITE_ROW) return std::optional<TokenRecord>(read_token(s));
  if (rc != SQLITE_DONE) return fail(ErrorCode::kStore, std::string("token check: ") + sqlite3_errmsg(db_));
  return std::optional<TokenRecord>{};
}

Result<bool> TokenStore::any_live() {
  Stmt s(db_, "SELECT 1 FROM api_tokens WHERE revoked=0 LIMIT 1");
  if (!s.ok) return fail(ErrorCode::kStore, std::string("token check: ") + sqlite3_errmsg(db_));
  return sqlite3_step(s.st) == SQLITE_ROW;
}

}  // namespace tp::host
