// rip/render/image_file_source.cpp: decoder thread, ring of rows, and the copy-out that frees them.
#include "rip/render/image_file_source.h"

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <spdlog/fmt/fmt.h>

#include "rip/image/image_io.h"
#include "rip/image/internal/scanline_reader.h"
#include "rip/render/image_source.h"

namespace tp::rip {

using geometry::Rgba8;

namespace {
/// Rows decoded per step of the decoder thread.
constexpr int kDecodeRows = 32;
}  // namespace

struct ImageFileSource::Impl {
  std::string name;
  int width = 0;
  std::int64_t height = 0;
  geometry::ImageRgba8 whole;                 ///< oriented images only, served by `in_memory`
  std::unique_ptr<ImageSource> in_memory;

  std::unique_ptr<ScanlineReader> reader;
  int window = 0;               ///< ring capacity in rows
  std::vector<Rgba8> ring;      ///< row y lives in slot y % window

  std::mutex mu;
  std::condition_variable cv;
  std::int64_t decoded = 0;                    ///< rows [0, decoded) have been decoded
  std::int64_t released = 0;           ///< rows [0, released) were copied out; their slots are free
  std::map<std::int64_t, int> copied;         ///< copied ranges above `released` (start -> rows)
  std::optional<Error> error;
  bool stop = false;
  std::thread decoder;

  Rgba8* slot(std::int64_t y) { return ring.data() + static_cast<std::size_t>(y % window) * width; }

  void decode_loop() {
    while (true) {
      std::int64_t y = 0;
      int n = 0;
      {
        std::unique_lock lock(mu);
        cv.wait(lock, [&] { return stop || error || decoded >= height || decoded - released < window; });
        if (stop || error || decoded >= height) return;
        y = decoded;
        n = static_cast<int>(std::min<std::int64_t>({kDecodeRows, height - decoded, window - (decoded - released)}));
      }
      // Slots [y, y + n) are not visible to readers until `decoded` moves past them.
      Status s;
      for (int done = 0; done < n && s;) {
        const int run = static_cast<int>(std::min<std::int64_t>(n - done, window - (y + done) % window));
        s = reader->read_rows(run, slot(y + done), width);
        done += run;
      }
      {
        std::lock_guard lock(mu);
        if (!s) error = s.error();
        else decoded = y + n;
      }
      cv.notify_all();
    }
  }
};

ImageFileSource::ImageFileSource(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

ImageFileSource::~ImageFileSource() {
  if (!impl_ || !impl_->decoder.joinable()) return;
  {
    std::lock_guard lock(impl_->mu);
    impl_->stop = true;
  }
  impl_->cv.notify_all();
  impl_->decoder.join();
}

Result<std::unique_ptr<ImageFileSource>> ImageFileSource::open(const std::filesystem::path& path, int window_rows) {
  if (window_rows < 2 * kRenderTileRows)
    return fail(ErrorCode::kInvalidArgument,
                fmt::format("{}: window of {} rows (at least {})", path.string(), window_rows, 2 * kRenderTileRows));
  auto m = std::make_unique<Impl>();
  m->name = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return fail(ErrorCode::kImage, m->name + ": no such image file");
  auto reader = ScanlineReader::open(m->name);
  if (!reader) return std::unexpected(reader.error());
  if ((*reader)->orientation() != 1) {
    reader->reset();
    auto img = read_image(path);
    if (!img) return std::unexpected(img.error());
    m->width = img->width_px;
    m->height = img->height_px;
    m->whole = std::move(*img);
    m->in_memory = std::make_unique<ImageSource>(m->whole);
    return std::unique_ptr<ImageFileSource>(new ImageFileSource(std::move(m)));
  }
  m->reader = std::move(*reader);
  m->width = m->reader->width_px();
  m->height = m->reader->height_px();
  m->window = static_cast<int>(std::min<std::int64_t>(window_rows + kDecodeRows, m->height + kDecodeRows));
  m->ring.resize(static_cast<std::size_t>(m->window) * m->width);
  Impl* raw = m.get();
  m->decoder = std::thread([raw] { raw->decode_loop(); });
  return std::unique_ptr<ImageFileSource>(new ImageFileSource(std::move(m)));
}

int ImageFileSource::width_px() const { return impl_->width; }
std::int64_t ImageFileSource::height_px() const { return impl_->height; }

void ImageFileSource::render_rows(std::int64_t y0, int rows, Rgba8* out, std::ptrdiff_t stride_px) const {
  Impl& m = *impl_;
  if (m.in_memory) return m.in_memory->render_rows(y0, rows, out, stride_px);
  rows = static_cast<int>(std::clamp<std::int64_t>(m.height - y0, 0, rows));
  if (rows == 0) return;
  {
    std::unique_lock lock(m.mu);
    if (y0 < m.released || y0 + rows - m.released > m.window) {
      if (!m.error)
        m.error = Error{ErrorCode::kInvalidArgument,
                        fmt::format("{}: rows {}..{} asked outside the decoded window ({} rows from row {})", m.name, y0,
                                    y0 + rows - 1, m.window, m.released)};
      m.cv.notify_all();
      return;
    }
    m.cv.wait(lock, [&] { return m.error || m.decoded >= y0 + rows; });
    if (m.error) return;
  }
  // Rows [y0, y0 + rows) stay put until released below.
  for (int r = 0; r < rows; ++r)
    std::memcpy(static_cast<void*>(out + r * stride_px), m.slot(y0 + r), sizeof(Rgba8) * static_cast<std::size_t>(m.width));
  {
    std::lock_guard lock(m.mu);
    m.copied[y0] = rows;
    for (auto it = m.copied.begin(); it != m.copied.end() && it->first == m.released; it = m.copied.erase(it))
      m.released += it->second;
  }
  m.cv.notify_all();
}

Status ImageFileSource::status() const {
  std::lock_guard lock(impl_->mu);
  if (impl_->error) return std::unexpected(*impl_->error);
  return {};
}

}  // namespace tp::rip
