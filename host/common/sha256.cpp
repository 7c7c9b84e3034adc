// host/common/sha256.cpp: SHA-256 over libmd, and the content hash of a job package.
#include "host/common/sha256.h"

#include <sha2.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

namespace tp::host {

namespace fs = std::filesystem;

namespace {

Status hash_file(Sha256& h, const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail(ErrorCode::kIo, path.string() + ": cannot read");
  std::vector<char> buf(1 << 16);
  while (in) {
    in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
    h.update(std::string_view(buf.data(), static_cast<size_t>(in.gcount())));
  }
  if (in.bad()) return fail(ErrorCode::kIo, path.string() + ": read failed");
  return {};
}

}  // namespace

struct Sha256::Context {
  SHA2_CTX ctx;
};

Sha256::Sha256() : ctx_(std::make_unique<Context>()) { SHA256Init(&ctx_->ctx); }
Sha256::~Sha256() = default;
Sha256::Sha256(const Sha256& other) : ctx_(std::make_unique<Context>(*other.ctx_)) {}
Sha256& Sha256::operator=(const Sha256& other) {
  *ctx_ = *other.ctx_;
  return *this;
}

void Sha256::update(std::string_view bytes) {
  SHA256Update(&ctx_->ctx, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

std::string Sha256::hex_digest() const {
  SHA2_CTX copy = ctx_->ctx;  // SHA256End finishes its context; the object hashes on
  char hex[SHA256_DIGEST_STRING_LENGTH];
  SHA256End(&copy, hex);
  return std::string(hex, SHA256_DIGEST_STRING_LENGTH - 1);
}

Result<std::string> package_hash(const fs::path& package) {
  Sha256 h;
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(package, ec))) {
    if (auto st = hash_file(h, package); !st) return std::unexpected(st.error());
    return h.hex_digest();
  }
  std::vector<fs::path> entries;
  for (auto it = fs::recursive_directory_iterator(package, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    entries.push_back(it->path());
  if (ec) return fail(ErrorCode::kIo, package.string() + ": " + ec.message());
  std::sort(entries.begin(), entries.end());
  for (const fs::path& p : entries) {
    const std::string rel = p.lexically_relative(package).generic_string();
    auto st = fs::symlink_status(p, ec);
    h.update(rel);
    if (fs::is_symlink(st)) {
      h.update(std::string_view("\0L", 2));
      h.update(fs::read_symlink(p, ec).string());
    } else if (fs::is_regular_file(st)) {
      h.update(std::string_view("\0F", 2));
      if (auto r = hash_file(h, p); !r) return std::unexpected(r.error());
    } else {
      h.update(std::string_view("\0D", 2));
    }
    h.update(std::string_view("\0", 1));
  }
  return h.hex_digest();
}

}  // namespace tp::host
