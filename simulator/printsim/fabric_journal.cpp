// simulator/printsim/fabric_journal.cpp: appending printed swaths and replaying them.
#include "simulator/printsim/fabric_journal.h"

#include <unistd.h>

#include <cstring>
#include <vector>

#include "device/protocol/messages.h"
#include "device/swath/packbits.h"

namespace tp::sim {

namespace {

constexpr char kMagic[4] = {'T', 'P', 'F', 'J'};
// Bound on one record, so a damaged length cannot ask for gigabytes.
constexpr std::uint32_t kMaxRecordBytes = 1u << 30;

bool read_exact(std::FILE* f, void* p, std::size_t n) { return std::fread(p, 1, n, f) == n; }

}  // namespace

Result<FabricJournal> FabricJournal::create(const std::filesystem::path& path, std::uint64_t job_id) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return fail(ErrorCode::kOutput, path.string() + ": cannot create the fabric journal");
  if (std::fwrite(kMagic, 1, 4, f) != 4 || std::fwrite(&job_id, sizeof job_id, 1, f) != 1 || std::fflush(f) != 0) {
    std::fclose(f);
    return fail(ErrorCode::kOutput, path.string() + ": cannot write the fabric journal");
  }
  return FabricJournal(f, path);
}

Result<FabricJournal> FabricJournal::reopen(
    const std::filesystem::path& path, std::uint64_t job_id, std::uint32_t before_swath,
    const std::function<void(const device::SwathHeader&, std::span<const std::uint8_t>)>& laid) {
  std::FILE* f = std::fopen(path.c_str(), "r+b");
  if (!f) return fail(ErrorCode::kInvalidArgument, path.string() + ": no fabric journal to resume from");
  const std::string where = path.string() + ": ";
  auto bad = [&](const std::string& why) -> std::unexpected<Error> {
    std::fclose(f);
    return fail(ErrorCode::kInvalidArgument, where + why);
  };
  char magic[4];
  std::uint64_t id = 0;
  if (!read_exact(f, magic, 4) || std::memcmp(magic, kMagic, 4) != 0 || !read_exact(f, &id, sizeof id))
    return bad("not a fabric journal");
  if (id != job_id) return bad("journal of job " + std::to_string(id) + ", not " + std::to_string(job_id));
  std::vector<std::uint8_t> rec, raw;
  long keep = std::ftell(f);
  for (;;) {
    std::uint32_t len = 0;
    if (!read_exact(f, &len, sizeof len)) break;  // the end, or a record cut short by the power loss
    if (len > kMaxRecordBytes) break;
    rec.resize(len);
    if (!read_exact(f, rec.data(), len)) break;
    std::uint32_t header_len = 0;
    if (len < sizeof header_len) break;
    std::memcpy(&header_len, rec.data(), sizeof header_len);
    if (header_len > len - sizeof header_len) break;
    auto h = device::decode_swath_header(std::span(rec).subspan(sizeof header_len, header_len));
    if (!h) break;
    if (h->header.index >= before_swath) break;
    raw.clear();
    const auto packed = std::span(rec).subspan(sizeof header_len + header_len);
    if (!device::packbits_decode(packed, h->header.raw_bytes, raw)) break;
    laid(h->header, raw);
    keep = std::ftell(f);
  }
  // Whatever follows the last swath kept was not on the fabric: cut it off.
  if (std::fflush(f) != 0 || ftruncate(fileno(f), keep) != 0 || std::fseek(f, keep, SEEK_SET) != 0)
    return bad("cannot trim the fabric journal");
  return FabricJournal(f, path);
}

FabricJournal::FabricJournal(FabricJournal&& o) noexcept : f_(o.f_), path_(std::move(o.path_)) { o.f_ = nullptr; }

FabricJournal& FabricJournal::operator=(FabricJournal&& o) noexcept {
  if (this != &o) {
    if (f_) std::fclose(f_);
    f_ = o.f_;
    path_ = std::move(o.path_);
    o.f_ = nullptr;
  }
  return *this;
}

FabricJournal::~FabricJournal() {
  if (f_) std::fclose(f_);
}

Status FabricJournal::append(const device::SwathHeader& header, std::span<const std::uint8_t> raw) {
  if (!f_) return fail(ErrorCode::kOutput, path_.string() + ": fabric journal closed");
  device::SwathHeaderMsg m;
  m.header = header;
  m.header.compression = device::SwathCompression::kPackBits;
  std::vector<std::uint8_t> packed;
  device::packbits_encode(raw, packed);
  m.data_bytes = static_cast<std::uint32_t>(packed.size());
  std::vector<std::uint8_t> head;
  device::encode(m, head);
  const std::uint32_t header_len = static_cast<std::uint32_t>(head.size());
  const std::uint32_t len = static_cast<std::uint32_t>(sizeof header_len + head.size() + packed.size());
  const bool ok = std::fwrite(&len, sizeof len, 1, f_) == 1 && std::fwrite(&header_len, sizeof header_len, 1, f_) == 1 &&
                  std::fwrite(head.data(), 1, head.size(), f_) == head.size() &&
                  std::fwrite(packed.data(), 1, packed.size(), f_) == packed.size() && std::fflush(f_) == 0;
  if (!ok) return fail(ErrorCode::kOutput, path_.string() + ": cannot append to the fabric journal");
  return {};
}

void FabricJournal::discard() {
  if (f_) std::fclose(f_);
  f_ = nullptr;
  std::error_code ec;
  if (!path_.empty()) std::filesystem::remove(path_, ec);
}

}  // namespace tp::sim
