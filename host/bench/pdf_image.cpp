// host/bench/pdf_image.cpp: minimal PDF 1.4 writer (catalog, pages, page, content stream, image XObject).
#include "host/bench/pdf_image.h"

#include <cstdio>
#include <fstream>
#include <string>

#include <spdlog/fmt/fmt.h>

namespace tp::rip {

Status write_jpeg_pdf(const std::filesystem::path& path, const std::vector<std::uint8_t>& jpeg, int width_px,
                      int height_px, double dpi) {
  const double w_pt = width_px * 72.0 / dpi, h_pt = height_px * 72.0 / dpi;
  std::string out = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";
  std::vector<size_t> offsets;
  auto object = [&](const std::string& body) {
    offsets.push_back(out.size());
    out += fmt::format("{} 0 obj\n{}\nendobj\n", offsets.size(), body);
  };
  object("<< /Type /Catalog /Pages 2 0 R >>");
  object("<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
  object(fmt::format("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 {:.4f} {:.4f}] /Resources << /XObject << /Im0 5 0 R >> >> "
                     "/Contents 4 0 R >>", w_pt, h_pt));
  const std::string content = fmt::format("q {:.4f} 0 0 {:.4f} 0 0 cm /Im0 Do Q", w_pt, h_pt);
  object(fmt::format("<< /Length {} >>\nstream\n{}\nendstream", content.size(), content));
  offsets.push_back(out.size());
  out += fmt::format("5 0 obj\n<< /Type /XObject /Subtype /Image /Width {} /Height {} /ColorSpace /DeviceRGB "
                     "/BitsPerComponent 8 /Filter /DCTDecode /Length {} >>\nstream\n", width_px, height_px, jpeg.size());
  out.append(reinterpret_cast<const char*>(jpeg.data()), jpeg.size());
  out += "\nendstream\nendobj\n";
  const size_t xref = out.size();
  out += fmt::format("xref\n0 {}\n0000000000 65535 f \n", offsets.size() + 1);
  for (size_t off : offsets) out += fmt::format("{:010d} 00000 n \n", off);
  out += fmt::format("trailer\n<< /Size {} /Root 1 0 R >>\nstartxref\n{}\n%%EOF\n", offsets.size() + 1, xref);
  std::ofstream f(path, std::ios::binary);
  if (!f) return fail(ErrorCode::kIo, path.string() + ": cannot create PDF");
  f.write(out.data(), static_cast<std::streamsize>(out.size()));
  if (!f) return fail(ErrorCode::kIo, path.string() + ": cannot write PDF");
  return {};
}

}  // namespace tp::rip
