// tests/device/common/error_test.cpp: device errors carry context and name their code.
#include "device/common/error.h"

#include <gtest/gtest.h>

namespace tp::device {
namespace {

TEST(DeviceError, ContextIsPrepended) {
  Error e{ErrorCode::kCrcMismatch, "frame 7"};
  Error c = e.with_context("swath 12");
  EXPECT_EQ(c.message, "swath 12: frame 7");
  EXPECT_EQ(c.code, ErrorCode::kCrcMismatch);
  EXPECT_EQ(c.what(), "swath 12: frame 7 (crc_mismatch)");
}

TEST(DeviceError, ResultCarriesFailure) {
  auto f = [](bool ok) -> Result<int> {
    if (ok) return 3;
    return fail(ErrorCode::kTimeout, "no ack");
  };
  EXPECT_EQ(*f(true), 3);
  ASSERT_FALSE(f(false));
  EXPECT_EQ(f(false).error().code, ErrorCode::kTimeout);
}

}  // namespace
}  // namespace tp::device
