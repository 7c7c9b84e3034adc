// tests/host/daemon/http/listen_address_test.cpp: --listen values, and which count as loopback.
#include <gtest/gtest.h>

#include "host/daemon/http/http_server.h"

namespace tp::host {
namespace {

TEST(ListenAddress, ParsesHostAndPort) {
  auto a = parse_listen("127.0.0.1:8631");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->host, "127.0.0.1");
  EXPECT_EQ(a->port, 8631);
  EXPECT_TRUE(a->loopback);
  auto v6 = parse_listen("[::1]:0");
  ASSERT_TRUE(v6);
  EXPECT_EQ(v6->host, "::1");
  EXPECT_TRUE(v6->loopback);
  auto any = parse_listen("0.0.0.0:443");
  ASSERT_TRUE(any);
  EXPECT_FALSE(any->loopback);
  EXPECT_FALSE(parse_listen("192.168.1.5:80")->loopback);
}

TEST(ListenAddress, RefusesMalformedValues) {
  for (const char* s : {"", "8631", ":8631", "host:", "host:x", "host:70000", "[::1]8631", "host:-1"})
    EXPECT_FALSE(parse_listen(s)) << s;
}

TEST(ListenAddress, BeyondLoopbackWithoutTlsIsRefused) {
  HttpConfig cfg;
  cfg.listen = "0.0.0.0:0";
  auto s = HttpServer::start(cfg, HttpBackend{});
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("TLS"), std::string::npos) << s.error().message;
}

}  // namespace
}  // namespace tp::host
