// tests/host/daemon/http/plain_relative_name_test.cpp: the one name check of the file routes:
// plain parts pass, split at '/'; anything that could climb out or be read another way is refused.
#include "host/daemon/http/plain_relative_name.h"

#include <gtest/gtest.h>

namespace tp::host {
namespace {

TEST(PlainRelativeName, SplitsPlainNamesAtSlashes) {
  auto one = plain_relative_name("report.json", "the job's outputs");
  ASSERT_TRUE(one) << one.error().message;
  EXPECT_EQ(*one, std::vector<std::string>{"report.json"});
  auto two = plain_relative_name("build/three.module.js", "/usr/share/javascript/three");
  ASSERT_TRUE(two) << two.error().message;
  EXPECT_EQ(*two, (std::vector<std::string>{"build", "three.module.js"}));
  EXPECT_TRUE(plain_relative_name("..hidden/a..b", "x")) << "dots inside a name are plain";
}

TEST(PlainRelativeName, RefusesEveryPartThatIsNotAPlainName) {
  const std::string nul("a\0b", 3);
  for (const std::string& name : {std::string(""), std::string("/etc/passwd"), std::string("../secret"),
                                  std::string("a/../../b"), std::string("./a"), std::string("a//b"), std::string("a/"),
                                  std::string("a\\..\\b"), nul, std::string(1025, 'a')}) {
    auto r = plain_relative_name(name, "the job's outputs");
    ASSERT_FALSE(r) << name;
    EXPECT_EQ(r.error().code, ErrorCode::kUnsafePath) << name;
    EXPECT_NE(r.error().message.find("file '"), std::string::npos) << r.error().message;
  }
  auto r = plain_relative_name("pieces/../x", "the job's outputs");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("'..' is not a plain name inside the job's outputs"), std::string::npos)
      << r.error().message;
}

}  // namespace
}  // namespace tp::host
