// tests/host/store/token_store_test.cpp: tokens are stored hashed, checked by secret, scoped, and
// revoked at once.
#include "host/store/token_store.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

TEST(TokenStore, AddCheckRevoke) {
  const auto db = tp::test::scratch_dir("tokens") / "jobs.db";
  auto s = TokenStore::open(db);
  ASSERT_TRUE(s) << s.error().message;
  auto admin = s->add("mis", TokenScope::kAdmin);
  ASSERT_TRUE(admin) << admin.error().message;
  auto dash = s->add("dashboard", TokenScope::kRead);
  ASSERT_TRUE(dash);
  EXPECT_EQ(admin->secret.rfind("tp_", 0), 0u);
  EXPECT_EQ(admin->secret.size(), 67u);
  EXPECT_NE(admin->secret, dash->secret);
  EXPECT_FALSE(s->add("mis", TokenScope::kRead)) << "a second live token of one name";
  EXPECT_FALSE(s->add("has space", TokenScope::kRead));

  auto c = s->check(dash->secret);
  ASSERT_TRUE(c && *c);
  EXPECT_EQ((*c)->name, "dashboard");
  EXPECT_EQ((*c)->scope, TokenScope::kRead);
  EXPECT_FALSE(*s->check("tp_wrong"));

  // Only the hash is on disk.
  std::ifstream in(db, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes.find(admin->secret), std::string::npos);

  ASSERT_TRUE(s->revoke("mis"));
  EXPECT_FALSE(*s->check(admin->secret));
  EXPECT_FALSE(s->revoke("mis"));
  ASSERT_TRUE(s->revoke(std::to_string(dash->record.id)));
  EXPECT_FALSE(*s->any_live());
  auto l = s->list();
  ASSERT_TRUE(l);
  ASSERT_EQ(l->size(), 2u);
  EXPECT_TRUE((*l)[0].revoked);
}

}  // namespace
}  // namespace tp::host
