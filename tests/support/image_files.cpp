// tests/support/image_files.cpp: see image_files.h.
#include "tests/support/image_files.h"

#include <cstdint>

#include <gtest/gtest.h>

namespace tp::test {

void write_raw_image(const std::filesystem::path& path, const OIIO_NAMESPACE::ImageSpec& spec, const void* data) {
  auto out = OIIO_NAMESPACE::ImageOutput::create(path.string());
  ASSERT_TRUE(out) << path;
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(spec.format, data)) << out->geterror();
  ASSERT_TRUE(out->close());
}

void write_oriented_tiff(const std::filesystem::path& path) {
  std::uint8_t px[6 * 3];
  for (int i = 0; i < 6; ++i) px[3 * i] = px[3 * i + 1] = px[3 * i + 2] = static_cast<std::uint8_t>(10 * i);
  OIIO_NAMESPACE::ImageSpec spec(3, 2, 3, OIIO_NAMESPACE::TypeDesc::UINT8);
  spec.attribute("Orientation", 6);
  write_raw_image(path, spec, px);
}

}  // namespace tp::test
