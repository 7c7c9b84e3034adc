// tests/scenarios/http/http_api_test.cpp: printd's HTTP API against a real printd (--printer none):
// every route of docs/api.yaml, uploads as zip and multipart, the 422 validation list, paging,
// files without escapes, events with Last-Event-ID replay, tokens, TLS and the upload caps.
#include <gtest/gtest.h>
#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zip.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "tests/scenarios/jobs/run_command.h"
#include "tests/support/files.h"
#include "tests/support/paths.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace std::chrono_literals;

// A job folder as zip bytes (libzip), the way a client would send it.
std::string zip_folder(const fs::path& dir, const fs::path& zip_path) {
  int err = 0;
  zip_t* z = zip_open(zip_path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
  EXPECT_TRUE(z);
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = fs::relative(e.path(), dir).generic_string();
    zip_source_t* src = zip_source_file(z, e.path().c_str(), 0, -1);
    zip_file_add(z, rel.c_str(), src, ZIP_FL_OVERWRITE);
  }
  zip_close(z);
  return read_text(zip_path);
}

// One printd with its own state, outputs and an ephemeral HTTP port read from its log.
class Printd {
 public:
  explicit Printd(fs::path root) : root_(std::move(root)) {}
  ~Printd() { stop(); }

  bool start(std::vector<std::string> extra = {}) {
    fs::create_directories(root_);
    std::ofstream(root_ / "none.conf") << "# no settings: the test gives them all\n";
    pid_ = ::fork();
    if (pid_ == 0) {
      const std::string log = (root_ / "printd.log").string();
      std::FILE* f = std::freopen(log.c_str(), "a", stdout);
      if (f) ::dup2(::fileno(stdout), 2);
      std::vector<std::string> args = {(bin_dir() / "printd").string(), "--state-dir", (root_ / "state").string(),
                                        "--out", (root_ / "out").string(), "--printer", "none",
                                        "--config", (root_ / "none.conf").string()};
      bool listen_given = false;
      for (const auto& e : extra) listen_given = listen_given || e == "--listen";
      if (!listen_given) args.insert(args.end(), {"--listen", "127.0.0.1:0"});
      args.insert(args.end(), extra.begin(), extra.end());
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    const std::regex port_re(R"(HTTP API on https?://[^ ]+:(\d+))");
    for (int i = 0; i < 200; ++i) {
      std::smatch m;
      const std::string log = read_text(root_ / "printd.log");
      if (std::regex_search(log, m, port_re)) {
        port_ = std::stoi(m[1]);
        return true;
      }
      int st = 0;
      if (::waitpid(pid_, &st, WNOHANG) == pid_) {
        pid_ = -1;
        exit_code_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128;
        return false;
      }
      std::this_thread::sleep_for(50ms);
    }
    return false;
  }

  void stop() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    int st = 0;
    ::waitpid(pid_, &st, 0);
    pid_ = -1;
  }

  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port_);
    c.set_read_timeout(30, 0);
    return c;
  }
  std::string log() const { return read_text(root_ / "printd.log"); }
  const fs::path& root() const { return root_; }
  int port() const { return port_; }
  int exit_code() const { return exit_code_; }

  /// Polls GET /api/v1/jobs/{id} until the job has ended.
  json wait_end(std::int64_t id, std::chrono::seconds limit = 240s) const {
    auto c = client();
    const auto until = std::chrono::steady_clock::now() + limit;
    json job;
    while (std::chrono::steady_clock::now() < until) {
      auto r = c.Get("/api/v1/jobs/" + std::to_string(id));
      if (r && r->status == 200) {
        job = json::parse(r->body)["job"];
        const std::string s = job["state"];
        if (s == "done" || s == "failed" || s == "cancelled") return job;
      }
      std::this_thread::sleep_for(100ms);
    }
    return job;
  }

 private:
  fs::path root_;
  pid_t pid_ = -1;
  int port_ = 0;
  int exit_code_ = -1;
};

fs::path example(const std::string& name) { return source_dir() / "examples" / name; }

TEST(HttpApi, JobsFilesAndEventsEndToEnd) {
  Printd d(scratch_dir("http-api"));
  ASSERT_TRUE(d.start()) << d.log();
  auto c = d.client();

  // The printer, idle.
  auto pr = c.Get("/api/v1/printer");
  ASSERT_TRUE(pr);
  ASSERT_EQ(pr->status, 200) << pr->body;
  EXPECT_EQ(json::parse(pr->body)["state"], "idle");

  // A zip upload queues the job; the same bytes again are the same job.
  const std::string zip = zip_folder(example("shirt-front-flat"), d.root() / "shirt.zip");
  auto up = c.Post("/api/v1/jobs", zip, "application/zip");
  ASSERT_TRUE(up);
  ASSERT_EQ(up->status, 201) << up->body;
  const std::int64_t id = json::parse(up->body)["id"];
  auto again = c.Post("/api/v1/jobs", zip, "application/zip");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 200) << again->body;
  EXPECT_EQ(json::parse(again->body)["id"], id);
  EXPECT_TRUE(json::parse(again->body)["duplicate"].get<bool>());

  // Events from the start of the log: the job's queued, running, stage progress and done, in
  // increasing sequence order.
  std::vector<json> seen;
  std::string buffer;
  auto ev = d.client();
  ev.set_read_timeout(240, 0);
  ev.Get("/api/v1/events?after=0", [&](const char* data, size_t n) {
    buffer.append(data, n);
    size_t end;
    while ((end = buffer.find("\n\n")) != std::string::npos) {
      const std::string frame = buffer.substr(0, end);
      buffer.erase(0, end + 2);
      const size_t d0 = frame.find("data: ");
      if (d0 == std::string::npos || frame.find("event: gap") != std::string::npos) continue;
      seen.push_back(json::parse(frame.substr(d0 + 6)));
      const json& e = seen.back();
      if (e["type"] == "job" && e["job_id"] == id && e["state"] != "queued" && e["state"] != "running") return false;
    }
    return true;
  });
  ASSERT_GE(seen.size(), 4u);
  for (size_t k = 1; k < seen.size(); ++k) EXPECT_EQ(seen[k]["seq"], seen[k - 1]["seq"].get<std::uint64_t>() + 1);
  EXPECT_EQ(seen.back()["state"], "done") << seen.back().dump();
  bool print_progress = false;
  for (const auto& e : seen) print_progress = print_progress || (e["type"] == "progress" && e["stage"] == "print");
  EXPECT_TRUE(print_progress);
  // Within a stage: the RIP's bands (no printer: the print stage's work) and the nester's
  // iterations (the default budget) give fractions between 0 and 1, rising.
  for (const std::string stage : {"print", "marker"}) {
    std::vector<double> inner;
    for (const auto& e : seen)
      if (e["type"] == "progress" && e["stage"] == stage && e.contains("detail")) inner.push_back(e["fraction"]);
    ASSERT_FALSE(inner.empty()) << stage;
    EXPECT_TRUE(std::any_of(inner.begin(), inner.end(), [](double f) { return f > 0 && f < 1; })) << stage;
    EXPECT_TRUE(std::is_sorted(inner.begin(), inner.end())) << stage;
  }

  // Reconnecting with Last-Event-ID replays exactly what came after it.
  const std::uint64_t mid = seen[seen.size() / 2]["seq"];
  std::string replay;
  auto ev2 = d.client();
  ev2.Get("/api/v1/events", httplib::Headers{{"Last-Event-ID", std::to_string(mid)}},
          [&](const char* data, size_t n) {
            replay.append(data, n);
            return replay.find("id: " + std::to_string(mid + 1) + "\n") == std::string::npos;
          });
  EXPECT_NE(replay.find("id: " + std::to_string(mid + 1) + "\n"), std::string::npos) << replay;
  EXPECT_EQ(replay.find("id: " + std::to_string(mid) + "\n"), std::string::npos) << replay;

  // The job with its stages and figures.
  json job = d.wait_end(id);
  ASSERT_EQ(job["state"], "done") << job.dump();
  ASSERT_TRUE(job["stages"].is_array());
  EXPECT_EQ(job["stages"].size(), 8u);
  EXPECT_TRUE(job["report"].contains("estimate")) << job.dump();

  // The printer now names the model the job ran on and its IEEE 1284 ID.
  json printer = json::parse(c.Get("/api/v1/printer")->body);
  EXPECT_NE(printer.value("ieee1284_id", "").find("CMD:TPWP;"), std::string::npos) << printer.dump();
  EXPECT_EQ(printer["counters"]["jobs_run"], 1);

  // Its files, and nothing but them.
  auto list = c.Get("/api/v1/jobs/" + std::to_string(id) + "/files");
  ASSERT_TRUE(list);
  ASSERT_EQ(list->status, 200);
  EXPECT_FALSE(json::parse(list->body)["files"].empty());
  auto rep = c.Get("/api/v1/jobs/" + std::to_string(id) + "/files/report.json");
  ASSERT_TRUE(rep);
  ASSERT_EQ(rep->status, 200);
  EXPECT_EQ(json::parse(rep->body)["job_id"], id);
  const fs::path out_dir = std::string(job["out_dir"]);
  fs::create_symlink(d.root() / "state" / "jobs.db", out_dir / "db-link");
  for (const std::string bad : {"../../state/jobs.db", "..%2F..%2Fstate%2Fjobs.db", "%2e%2e/%2e%2e/state/jobs.db",
                                "db-link", "%2Fetc%2Fpasswd"}) {
    auto r = c.Get("/api/v1/jobs/" + std::to_string(id) + "/files/" + bad);
    ASSERT_TRUE(r) << bad;
    EXPECT_TRUE(r->status == 400 || r->status == 404) << bad << ": " << r->status;
    EXPECT_EQ(r->body.find("SQLite"), std::string::npos) << bad;
  }
  EXPECT_EQ(c.Get("/api/v1/jobs/" + std::to_string(id) + "/files/nope.png")->status, 404);

  // Paging and the state filter.
  auto done = c.Get("/api/v1/jobs?state=done&limit=1&offset=0");
  ASSERT_TRUE(done);
  ASSERT_EQ(done->status, 200) << done->body;
  EXPECT_EQ(json::parse(done->body)["total"], 1);
  EXPECT_EQ(json::parse(done->body)["jobs"][0]["id"], id);
  EXPECT_EQ(json::parse(c.Get("/api/v1/jobs?state=queued")->body)["total"], 0);
  EXPECT_EQ(c.Get("/api/v1/jobs?state=nonsense")->status, 400);
  EXPECT_EQ(c.Get("/api/v1/jobs?limit=x")->status, 400);
  EXPECT_TRUE(json::parse(c.Get("/api/v1/jobs?offset=5")->body)["jobs"].empty());

  // Cancel: a finished job cannot be, an unknown one is not found.
  EXPECT_EQ(c.Delete("/api/v1/jobs/" + std::to_string(id))->status, 409);
  EXPECT_EQ(c.Delete("/api/v1/jobs/99999")->status, 404);
  EXPECT_EQ(c.Get("/api/v1/jobs/99999")->status, 404);

  // Reprint queues the kept package again as a new job, which can be cancelled.
  auto re = c.Post("/api/v1/jobs/" + std::to_string(id) + "/reprint");
  ASSERT_TRUE(re);
  ASSERT_EQ(re->status, 201) << re->body;
  const std::int64_t id2 = json::parse(re->body)["id"];
  EXPECT_NE(id2, id);
  auto del = c.Delete("/api/v1/jobs/" + std::to_string(id2));
  ASSERT_TRUE(del);
  EXPECT_EQ(del->status, 200) << del->body;
  EXPECT_EQ(d.wait_end(id2)["state"], "cancelled");
}

TEST(HttpApi, UploadsAreCheckedAsPackages) {
  std::signal(SIGPIPE, SIG_IGN);  // a refused upload closes the connection under the client's write
  Printd d(scratch_dir("http-upload"));
  ASSERT_TRUE(d.start({"--http-max-upload-mb", "1"})) << d.log();
  auto c = d.client();

  // A job.json with a wrong field: 422 with file and pointer.
  const fs::path bad = d.root() / "bad-job";
  fs::create_directories(bad);
  fs::copy(example("shirt-front-flat"), bad, fs::copy_options::recursive);
  json manifest = read_json(bad / "job.json");
  manifest["print"]["dpi"] = "lots";
  std::ofstream(bad / "job.json") << manifest.dump();
  auto r = c.Post("/api/v1/jobs", zip_folder(bad, d.root() / "bad.zip"), "application/zip");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 422) << r->body;
  json problems = json::parse(r->body)["problems"];
  ASSERT_FALSE(problems.empty()) << r->body;
  EXPECT_EQ(problems[0]["file"], "job.json");
  EXPECT_EQ(problems[0]["pointer"], "/print/dpi") << r->body;

  // A folder as multipart files (the browser's folder upload).
  httplib::MultipartFormDataItems items;
  for (const auto& e : fs::directory_iterator(example("shirt-front-flat")))
    items.push_back({"files", read_text(e.path()), e.path().filename().string(), "application/json"});
  auto mp = c.Post("/api/v1/jobs", items);
  ASSERT_TRUE(mp);
  EXPECT_EQ(mp->status, 201) << mp->body;
  // A part that climbs out of the upload folder.
  httplib::MultipartFormDataItems evil = {{"files", "x", "../../escape.json", "application/json"}};
  auto ev = c.Post("/api/v1/jobs", evil);
  ASSERT_TRUE(ev);
  EXPECT_EQ(ev->status, 400) << ev->body;
  EXPECT_FALSE(fs::exists(d.root() / "state" / "escape.json"));

  // Not a zip, too large, wrong type.
  EXPECT_EQ(c.Post("/api/v1/jobs", "not a zip", "application/zip")->status, 422);
  // Too large: answered 413 from the Content-Length before the body is read, and the connection
  // closed, so the client may see its write fail instead of the answer.
  auto big = c.Post("/api/v1/jobs", std::string(2u << 20, 'x'), "application/zip");
  EXPECT_TRUE(!big || big->status == 413) << (big ? big->body : httplib::to_string(big.error()));
  EXPECT_EQ(c.Post("/api/v1/jobs", "{}", "application/json")->status, 415);
  // Nothing of the uploads is left behind.
  std::error_code ec;
  EXPECT_TRUE(fs::is_empty(d.root() / "state" / "uploads", ec));
}

// printctl submit --wait draws the same progress the events carry: plain lines when its output is
// not a terminal, one per stage change.
TEST(HttpApi, SubmitWaitShowsTheStagesFromTheEvents) {
  Printd d(scratch_dir("http-wait"));
  ASSERT_TRUE(d.start()) << d.log();
  auto r = run_command({(bin_dir() / "printctl").string(), "submit", example("shirt-front-flat").string(), "--wait",
                        "--state-dir", (d.root() / "state").string()});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* line : {"queued job 1", "design: running", "marker: done", "print: running", "job 1 done"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << " not in:\n" << r.output;
}

// Slow clients hold only their own threads: 20 connections that send half a request line and an
// event stream nobody reads do not stop others being answered, and the half-sent ones are dropped
// at --http-timeout-ms.
TEST(HttpApi, SlowClientsStallNobody) {
  std::signal(SIGPIPE, SIG_IGN);
  Printd d(scratch_dir("http-slow"));
  // A request stalled behind the slow clients would wait for their timeout (5 s): one answered in
  // well under half of it was not, however loaded the machine is.
  ASSERT_TRUE(d.start({"--http-timeout-ms", "5000"})) << d.log();
  std::vector<int> slow;
  for (int i = 0; i < 20; ++i) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<std::uint16_t>(d.port()));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
    const std::string half = i % 2 ? "GET /api/v1/jo" : "GET /api/v1/events HTTP/1.1\r\nHost: x\r\n\r\n";
    ASSERT_EQ(::send(fd, half.data(), half.size(), 0), static_cast<ssize_t>(half.size()));
    slow.push_back(fd);  // never read from
  }
  auto c = d.client();
  for (int i = 0; i < 20; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    auto r = c.Get("/api/v1/jobs");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, 2500ms) << "a request waited behind the slow clients";
  }
  // The half-sent requests are closed by the daemon after the timeout.
  std::this_thread::sleep_for(6500ms);
  int closed = 0;
  for (size_t i = 1; i < slow.size(); i += 2) {
    char buf[256];
    timeval tv{0, 200000};
    ::setsockopt(slow[i], SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    ssize_t n;
    while ((n = ::recv(slow[i], buf, sizeof buf, 0)) > 0) {}
    if (n == 0) ++closed;
  }
  EXPECT_EQ(closed, 10);
  for (int fd : slow) ::close(fd);
}

TEST(HttpApi, TokensGuardTheApiWithAReadOnlyScope) {
  Printd d(scratch_dir("http-tokens"));
  ASSERT_TRUE(d.start({"--require-token"})) << d.log();
  auto ctl = [&](std::vector<std::string> args) {
    args.insert(args.begin(), {(bin_dir() / "printctl").string(), "token"});
    args.insert(args.begin() + 2, {"--state-dir", (d.root() / "state").string()});
    return run_command(args);
  };
  auto admin = ctl({"add", "mis"});
  ASSERT_EQ(admin.exit_code, 0) << admin.output;
  auto read = ctl({"add", "wall", "--read-only"});
  ASSERT_EQ(read.exit_code, 0) << read.output;
  const std::regex tok("tp_[0-9a-f]{64}");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(admin.output, m, tok));
  const std::string admin_secret = m[0];
  ASSERT_TRUE(std::regex_search(read.output, m, tok));
  const std::string read_secret = m[0];

  auto c = d.client();
  EXPECT_EQ(c.Get("/api/v1/jobs")->status, 401);
  c.set_bearer_token_auth("tp_" + std::string(64, '0'));
  EXPECT_EQ(c.Get("/api/v1/jobs")->status, 401);
  c.set_bearer_token_auth(read_secret);
  EXPECT_EQ(c.Get("/api/v1/jobs")->status, 200);
  EXPECT_EQ(c.Delete("/api/v1/jobs/1")->status, 403);
  c.set_bearer_token_auth(admin_secret);
  EXPECT_EQ(c.Delete("/api/v1/jobs/1")->status, 404);
  auto list = ctl({"list"});
  EXPECT_NE(list.output.find("wall"), std::string::npos);
  EXPECT_EQ(list.output.find(admin_secret), std::string::npos);
  ASSERT_EQ(ctl({"revoke", "mis"}).exit_code, 0);
  EXPECT_EQ(c.Get("/api/v1/jobs")->status, 401);
}

TEST(HttpApi, BeyondLoopbackNeedsTlsAndServesHttps) {
  Printd plain(scratch_dir("http-any"));
  EXPECT_FALSE(plain.start({"--listen", "0.0.0.0:0"}));
  EXPECT_NE(plain.log().find("TLS"), std::string::npos) << plain.log();

  const fs::path root = scratch_dir("http-tls");
  const std::string cert = (root / "cert.pem").string(), key = (root / "key.pem").string();
  auto gen = run_command({"openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1", "-subj",
                          "/CN=localhost", "-keyout", key, "-out", cert});
  ASSERT_EQ(gen.exit_code, 0) << gen.output;
  Printd d(root / "d");
  ASSERT_TRUE(d.start({"--tls-cert", cert, "--tls-key", key})) << d.log();
  httplib::SSLClient c("127.0.0.1", d.port());
  c.enable_server_certificate_verification(false);
  auto r = c.Get("/api/v1/printer");
  ASSERT_TRUE(r) << httplib::to_string(r.error());
  EXPECT_EQ(r->status, 200);
  // Plain HTTP to the HTTPS port gets nothing useful.
  httplib::Client p("127.0.0.1", d.port());
  p.set_read_timeout(2, 0);
  auto pr = p.Get("/api/v1/printer");
  EXPECT_TRUE(!pr || pr->status != 200);
}

}  // namespace
}  // namespace tp::test
