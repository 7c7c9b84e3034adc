// tests/host/daemon/http/validation_list_test.cpp: a refused package's message becomes one entry
// per problem, with the file and JSON pointer printctl validate names.
#include "host/daemon/http/validation_list.h"

#include <gtest/gtest.h>

namespace tp::host {
namespace {

TEST(ValidationList, SplitsFilePointerAndMessage) {
  auto l = validation_list("job.json: /print/dpi: must be an integer\njob.json: /: expected a JSON object\n"
                           "pattern.json: /pieces/0/name: missing\nzip: entry 'a/../b' leaves the package");
  ASSERT_EQ(l.size(), 4u);
  EXPECT_EQ(l[0]["file"], "job.json");
  EXPECT_EQ(l[0]["pointer"], "/print/dpi");
  EXPECT_EQ(l[0]["message"], "must be an integer");
  EXPECT_EQ(l[1]["pointer"], "");
  EXPECT_EQ(l[2]["file"], "pattern.json");
  EXPECT_EQ(l[2]["pointer"], "/pieces/0/name");
  EXPECT_EQ(l[3]["file"], "zip");
  EXPECT_EQ(l[3]["pointer"], "");
  EXPECT_EQ(l[3]["message"], "entry 'a/../b' leaves the package");
}

TEST(ValidationList, KeepsAMessageWithoutAFileWhole) {
  auto l = validation_list("the package is not a folder or a .zip");
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(l[0]["file"], "");
  EXPECT_EQ(l[0]["message"], "the package is not a folder or a .zip");
}

}  // namespace
}  // namespace tp::host
