// tests/host/daemon/request_handler_test.cpp: no request line, however malformed, throws or is
// answered with anything but a JSON error naming the field.
#include "host/daemon/requests/request_handler.h"

#include <gtest/gtest.h>

#include "tests/support/paths.h"

namespace tp::host {
namespace {

nlohmann::json reply(JobStore& store, const std::string& line, const RequestHooks& hooks = {}) {
  std::string r = handle_request(store, line, hooks);
  auto j = nlohmann::json::parse(r, nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << r;
  return j;
}

TEST(RequestHandler, WrongTypesGetNamedErrors) {
  auto store = JobStore::open(tp::test::scratch_dir("req-types") / "jobs.db");
  ASSERT_TRUE(store);
  // The probe that aborted printd: "limit" as a string (nlohmann type_error.302).
  auto r = reply(*store, R"({"op":"status","limit":"x"})");
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["error"].get<std::string>().find("\"limit\""), std::string::npos);
  for (const char* line : {R"({"op":"status","limit":-5})", R"({"op":"status","limit":18446744073709551615})",
                           R"({"op":"status","id":"3"})", R"({"op":"status","id":1.5})", R"({"op":"cancel","id":null})",
                           R"({"op":"cancel"})", R"({"op":"submit","package":7})", R"({"op":"submit","package":"rel/x"})",
                           R"({"op":"submit","package":"/x","reprint":"yes"})", R"({"op":1})", "[1]", "", "\xff\xfe",
                           R"({"op":"nope"})"}) {
    auto j = reply(*store, line);
    EXPECT_FALSE(j.value("ok", true)) << line;
    EXPECT_TRUE(j["error"].is_string()) << line;
  }
  EXPECT_TRUE(reply(*store, R"({"op":"status","limit":3})")["ok"].get<bool>());
}

TEST(RequestHandler, JobNamesThatAreNotUtf8AreEscaped) {
  auto store = JobStore::open(tp::test::scratch_dir("req-utf8") / "jobs.db");
  ASSERT_TRUE(store);
  ASSERT_TRUE(store->enqueue("caf\xE9", "/spool/x", "/out/x", "hot-folder:caf\xE9-job"));
  auto r = reply(*store, R"({"op":"status"})");
  ASSERT_TRUE(r["ok"].get<bool>());
  EXPECT_EQ(r["jobs"][0]["name"], "caf\\xE9");
  EXPECT_EQ(r["jobs"][0]["origin"], "hot-folder:caf\\xE9-job");
}

TEST(RequestHandler, SubmitAndCancelGoThroughTheHooks) {
  auto store = JobStore::open(tp::test::scratch_dir("req-hooks") / "jobs.db");
  ASSERT_TRUE(store);
  RequestHooks hooks;
  bool reprint_seen = false;
  std::int64_t cancelled = 0;
  hooks.submit = [&](const std::filesystem::path& p, bool reprint) -> Result<nlohmann::json> {
    reprint_seen = reprint;
    auto id = store->enqueue("j", p.string(), "/out", "socket");
    return nlohmann::json{{"id", *id}, {"name", "j"}};
  };
  hooks.cancelled_queued = [&](std::int64_t id) { cancelled = id; };
  auto r = reply(*store, R"({"op":"submit","package":"/jobs/a","reprint":true})", hooks);
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  EXPECT_TRUE(reprint_seen);
  const std::int64_t id = r["id"];
  auto c = reply(*store, R"({"op":"cancel","id":)" + std::to_string(id) + "}", hooks);
  EXPECT_EQ(c["state"], "cancelled");
  EXPECT_EQ(cancelled, id);
  // A hook that throws costs the request, not the daemon.
  hooks.submit = [](const std::filesystem::path&, bool) -> Result<nlohmann::json> { throw std::runtime_error("boom"); };
  auto t = reply(*store, R"({"op":"submit","package":"/jobs/a"})", hooks);
  EXPECT_FALSE(t["ok"].get<bool>());
  EXPECT_NE(t["error"].get<std::string>().find("boom"), std::string::npos);
}

}  // namespace
}  // namespace tp::host
