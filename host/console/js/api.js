// host/console/js/api.js: printd's HTTP API (docs/api.yaml) for the console: JSON requests with the
// optional bearer token, job file URLs, and the Server-Sent Events stream read through fetch.

const TOKEN_KEY = "printd.token";

/** An API error: the daemon's own message, its HTTP status and (for a 422) the problem list. */
export class ApiError extends Error {
  constructor(status, message, problems) {
    super(message);
    this.status = status;
    this.problems = problems || [];
  }
}

export function token() { return sessionStorage.getItem(TOKEN_KEY) || ""; }
export function setToken(value) {
  if (value) sessionStorage.setItem(TOKEN_KEY, value);
  else sessionStorage.removeItem(TOKEN_KEY);
}

function headers(extra) {
  const h = Object.assign({}, extra || {});
  if (token()) h.Authorization = "Bearer " + token();
  return h;
}

/** Listeners told when the daemon answers 401 (the page then asks for a token). */
const unauthorised = new Set();
export function onUnauthorised(fn) { unauthorised.add(fn); }

/** One API request; resolves to the JSON body, rejects with an ApiError naming what was refused. */
export async function request(method, path, body, contentType) {
  const init = { method, headers: headers(contentType ? { "Content-Type": contentType } : {}) };
  if (body !== undefined) init.body = body;
  let res;
  try {
    res = await fetch(path, init);
  } catch (e) {
    throw new ApiError(0, `${method} ${path}: printd did not answer (${e.message})`);
  }
  let json = null;
  try { json = await res.json(); } catch (e) { json = null; }
  if (res.status === 401) unauthorised.forEach((fn) => fn());
  if (!res.ok) {
    const msg = (json && json.error) || `${method} ${path}: HTTP ${res.status}`;
    throw new ApiError(res.status, msg, json && json.problems);
  }
  return json;
}

export const listJobs = (limit, offset) => request("GET", `/api/v1/jobs?limit=${limit}&offset=${offset || 0}`);
export const getJob = (id) => request("GET", `/api/v1/jobs/${id}`);
export const jobFiles = (id) => request("GET", `/api/v1/jobs/${id}/files`);
export const cancelJob = (id) => request("DELETE", `/api/v1/jobs/${id}`);
export const reprintJob = (id) => request("POST", `/api/v1/jobs/${id}/reprint`);
export const printer = () => request("GET", "/api/v1/printer");
/** Submits job .zip bytes (a Blob or ArrayBuffer) as application/zip. */
export const submitZip = (bytes) => request("POST", "/api/v1/jobs", bytes, "application/zip");

/** The URL of one of a job's output files ("pieces/front.png" keeps its slash). */
export function fileUrl(id, name) {
  return `/api/v1/jobs/${id}/files/` + name.split("/").map(encodeURIComponent).join("/");
}

/** Fetches a job file as text or a Blob with the token (an <img> cannot send one). */
export async function fetchFile(id, name, as) {
  const res = await fetch(fileUrl(id, name), { headers: headers() });
  if (!res.ok) throw new ApiError(res.status, `${name}: HTTP ${res.status}`);
  return as === "blob" ? res.blob() : res.text();
}

/**
 * Follows GET /api/v1/events for as long as the page lives: each event goes to onEvent(type, data),
 * the link state to onLink("live" | "lost"). Read with fetch rather than EventSource so a bearer
 * token can be sent; reconnects with Last-Event-ID, so nothing the log still holds is missed.
 */
export function followEvents(onEvent, onLink) {
  let last = null;
  const run = async () => {
    for (;;) {
      try {
        const h = headers({ Accept: "text/event-stream" });
        if (last !== null) h["Last-Event-ID"] = String(last);
        const res = await fetch("/api/v1/events", { headers: h, cache: "no-store" });
        if (!res.ok || !res.body) throw new Error(`HTTP ${res.status}`);
        onLink("live");
        const reader = res.body.getReader();
        const decoder = new TextDecoder();
        let buffer = "";
        for (;;) {
          const { value, done } = await reader.read();
          if (done) break;
          buffer += decoder.decode(value, { stream: true });
          let cut;
          while ((cut = buffer.indexOf("\n\n")) >= 0) {
            const block = buffer.slice(0, cut);
            buffer = buffer.slice(cut + 2);
            let type = "message", data = "", id = null;
            for (const line of block.split("\n")) {
              if (line.startsWith("event:")) type = line.slice(6).trim();
              else if (line.startsWith("data:")) data += line.slice(5).trim();
              else if (line.startsWith("id:")) id = line.slice(3).trim();
            }
            if (id !== null) last = id;
            if (!data) continue;
            let parsed = null;
            try { parsed = JSON.parse(data); } catch (e) { continue; }
            onEvent(type, parsed);
          }
        }
      } catch (e) {
        /* fall through to the retry below */
      }
      onLink("lost");
      await new Promise((r) => setTimeout(r, 2000));
    }
  };
  run();
}
