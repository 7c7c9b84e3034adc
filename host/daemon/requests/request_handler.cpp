// host/daemon/requests/request_handler.cpp: typed, checked access to control-socket requests.
#include "host/daemon/requests/request_handler.h"

#include <optional>

#include "host/common/text.h"

namespace tp::host {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string err(const std::string& m) { return dump_json(json{{"ok", false}, {"error", printable_utf8(m)}}); }

// An optional integer field: absent -> fallback; present but not an integer in range -> error.
Result<std::int64_t> int_field(const json& req, const char* op, const char* key, std::int64_t fallback,
                               std::int64_t min, std::int64_t max) {
  auto it = req.find(key);
  if (it == req.end()) return fallback;
  if (!it->is_number_integer())
    return fail(ErrorCode::kInvalidArgument, std::string(op) + ": \"" + key + "\" must be an integer");
  // Unsigned values above INT64_MAX read as negative through get<int64_t>: compare unsigned first.
  if (it->is_number_unsigned() && it->get<std::uint64_t>() > static_cast<std::uint64_t>(max))
    return fail(ErrorCode::kInvalidArgument, std::string(op) + ": \"" + key + "\" must be at most " + std::to_string(max));
  const std::int64_t v = it->get<std::int64_t>();
  if (v < min || v > max)
    return fail(ErrorCode::kInvalidArgument, std::string(op) + ": \"" + key + "\" must be " + std::to_string(min) +
                                                 ".." + std::to_string(max));
  return v;
}

std::string handle_status(JobStore& store, const json& req) {
  if (req.contains("id")) {
    auto id = int_field(req, "status", "id", 0, 1, INT64_MAX);
    if (!id) return err(id.error().message);
    auto rec = store.get(*id);
    if (!rec) return err(rec.error().message);
    if (!*rec) return err("no job " + std::to_string(*id));
    json j = job_record_json(**rec);
    if (auto st = store.stages((*rec)->id)) {
      j["stages"] = json::array();
      for (const auto& s : *st)
        j["stages"].push_back({{"stage", printable_utf8(s.stage)}, {"state", printable_utf8(s.state)}, {"seconds", s.seconds}});
    }
    return dump_json(json{{"ok", true}, {"job", j}});
  }
  auto limit = int_field(req, "status", "limit", 50, 1, kMaxStatusLimit);
  if (!limit) return err(limit.error().message);
  auto offset = int_field(req, "status", "offset", 0, 0, INT64_MAX);
  if (!offset) return err(offset.error().message);
  std::optional<JobState> state;
  if (auto it = req.find("state"); it != req.end()) {
    state = it->is_string() ? job_state_from_string(it->get<std::string>()) : std::nullopt;
    if (!state) return err("status: \"state\" must be one of queued, running, done, failed, cancelled");
  }
  auto list = store.list_page(static_cast<int>(*limit), *offset, state);
  if (!list) return err(list.error().message);
  auto total = store.count(state);
  if (!total) return err(total.error().message);
  json jobs = json::array();
  for (const auto& r : *list) jobs.push_back(job_record_json(r));
  return dump_json(json{{"ok", true}, {"jobs", jobs}, {"total", *total}, {"offset", *offset}});
}

std::string handle_reprint(const json& req, const RequestHooks& hooks) {
  if (!req.contains("id")) return err("reprint needs \"id\": an integer");
  auto id = int_field(req, "reprint", "id", 0, 1, INT64_MAX);
  if (!id) return err(id.error().message);
  if (!hooks.reprint) return err("reprint: this daemon takes no jobs");
  auto reply = hooks.reprint(*id);
  if (!reply) return err(reply.error().message);
  json out = *reply;
  out["ok"] = true;
  return dump_json(out);
}

std::string handle_submit(const json& req, const RequestHooks& hooks) {
  auto it = req.find("package");
  if (it == req.end() || !it->is_string()) return err("submit needs \"package\": a path");
  const std::string& text = it->get_ref<const std::string&>();
  if (text.empty() || text.find('\0') != std::string::npos) return err("submit: \"package\" is not a usable path");
  fs::path p = text;
  if (!p.is_absolute()) return err("submit: package path must be absolute");
  bool reprint = false;
  if (auto r = req.find("reprint"); r != req.end()) {
    if (!r->is_boolean()) return err("submit: \"reprint\" must be true or false");
    reprint = r->get<bool>();
  }
  if (!hooks.submit) return err("submit: this daemon takes no jobs");
  auto reply = hooks.submit(p, reprint);
  if (!reply) return err(reply.error().message);
  json out = *reply;
  out["ok"] = true;
  return dump_json(out);
}

std::string handle_cancel(JobStore& store, const json& req, const RequestHooks& hooks) {
  if (!req.contains("id")) return err("cancel needs \"id\": an integer");
  auto id = int_field(req, "cancel", "id", 0, 1, INT64_MAX);
  if (!id) return err(id.error().message);
  auto st = store.request_cancel(*id);
  if (!st) return err(st.error().message);
  if (*st == JobState::kRunning && hooks.cancel_running) hooks.cancel_running(*id);
  if (*st == JobState::kCancelled && hooks.cancelled_queued) hooks.cancelled_queued(*id);
  return dump_json(json{{"ok", true}, {"id", *id}, {"state", *st == JobState::kRunning ? "cancelling" : "cancelled"}});
}

std::string handle_events(const json& req, const RequestHooks& hooks) {
  auto after = int_field(req, "events", "after", 0, 0, INT64_MAX);
  if (!after) return err(after.error().message);
  auto job = int_field(req, "events", "job", 0, 0, INT64_MAX);
  if (!job) return err(job.error().message);
  auto wait = int_field(req, "events", "wait_ms", 0, 0, 1000);
  if (!wait) return err(wait.error().message);
  if (!hooks.events) return err("events: this daemon keeps no event log");
  json out = hooks.events(static_cast<std::uint64_t>(*after), *job, static_cast<int>(*wait));
  out["ok"] = true;
  return dump_json(out);
}

}  // namespace

json job_record_json(const JobRecord& r) {
  return {{"id", r.id},
          {"name", printable_utf8(r.name)},
          {"state", std::string(to_string(r.state))},
          {"stage", printable_utf8(r.stage)},
          {"error", printable_utf8(r.error)},
          {"out_dir", printable_utf8(r.out_dir)},
          {"origin", printable_utf8(r.origin)},
          {"submitted_ms", r.submitted_ms},
          {"updated_ms", r.updated_ms},
          {"last_acked_swath", r.last_acked_swath},
          {"cancel_requested", r.cancel_requested},
          {"crash_count", r.crash_count},
          {"unclean_exits", r.unclean_exits}};
}

std::string handle_request(JobStore& store, const std::string& request, const RequestHooks& hooks) noexcept {
  try {
    json req = json::parse(request, nullptr, false);
    if (req.is_discarded() || !req.is_object()) return err("request must be a JSON object with \"op\"");
    auto op_it = req.find("op");
    if (op_it == req.end() || !op_it->is_string()) return err("request must be a JSON object with \"op\"");
    const std::string op = op_it->get<std::string>();
    if (op == "ping") return dump_json(json{{"ok", true}});
    if (op == "submit") return handle_submit(req, hooks);
    if (op == "status") return handle_status(store, req);
    if (op == "cancel") return handle_cancel(store, req, hooks);
    if (op == "reprint") return handle_reprint(req, hooks);
    if (op == "events") return handle_events(req, hooks);
    return err("unknown op \"" + op + "\" (ping, submit, status, cancel, reprint, events)");
  } catch (const std::exception& e) {
    // A bug here must cost the client its request, never the daemon its life.
    try {
      return err(std::string("internal error handling the request: ") + e.what());
    } catch (...) {
    }
  } catch (...) {
  }
  return R"({"ok":false,"error":"internal error handling the request"})";
}

}  // namespace tp::host
