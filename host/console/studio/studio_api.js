// host/console/studio/studio_api.js: the design studio's calls to printd (docs/studio.md): garments,
// uploads, preview atlases and job packages, with the console's bearer token when there is one.

/** An API refusal: the daemon's message, status and (422) its problem list. */
export class StudioError extends Error {
  constructor(status, message, problems) {
    super(message);
    this.status = status;
    this.problems = problems || [];
  }
}

function authHeaders(extra) {
  const h = Object.assign({}, extra || {});
  const token = sessionStorage.getItem("printd.token");
  if (token) h.Authorization = "Bearer " + token;
  return h;
}

async function call(method, path, body, contentType, as, signal) {
  const init = { method, headers: authHeaders(contentType ? { "Content-Type": contentType } : {}), signal };
  if (body !== undefined) init.body = body;
  let res;
  try {
    res = await fetch(path, init);
  } catch (e) {
    if (e.name === "AbortError") throw e;
    throw new StudioError(0, `${method} ${path}: printd did not answer (${e.message})`);
  }
  if (!res.ok) {
    let json = null;
    try { json = await res.json(); } catch (e) { json = null; }
    throw new StudioError(res.status, (json && json.error) || `${method} ${path}: HTTP ${res.status}`, json && json.problems);
  }
  if (as === "blob") return { blob: await res.blob(), headers: res.headers };
  if (as === "text") return res.text();
  return res.status === 204 ? null : res.json();
}

/** Sews a sample garment: {sample, size}. */
export const sewSample = (sample, size) =>
  call("POST", "/api/v1/studio/garments", JSON.stringify({ sample, size }), "application/json");

/** Sews an uploaded pattern on an uploaded body mesh (or a dress form of the size). */
export function sewUpload(patternFile, bodyFile, bodyUnits, size) {
  const form = new FormData();
  form.append("pattern", patternFile, patternFile.name);
  if (bodyFile) {
    form.append("body", bodyFile, bodyFile.name);
    form.append("body_units", bodyUnits || "mm");
  } else {
    form.append("dress_form", "{}");
  }
  if (size) form.append("size", size);
  return call("POST", "/api/v1/studio/garments", form);
}

export const garmentMesh = (g) => call("GET", g.urls.mesh, undefined, undefined, "text");

/** Stores a file among the garment's assets; resolves to its package path ("assets/x.png"). */
export async function uploadAsset(g, file) {
  const name = file.name.replace(/[^A-Za-z0-9._-]/g, "_").replace(/^\.+/, "") || "asset";
  const reply = await call("POST", `${g.urls.assets}?name=${encodeURIComponent(name)}`, file, "application/octet-stream");
  return reply.paths[0];
}

/** The design rendered by the daemon: {blob, headers} of the atlas PNG. */
export const preview = (g, design, signal) =>
  call("POST", g.urls.preview, JSON.stringify({ design }), "application/json", "blob", signal);

/** The job package (zip blob) for design and settings. */
export const jobPackage = (g, settings) =>
  call("POST", g.urls.job, JSON.stringify(settings), "application/json", "blob");

/** Submits zip bytes as a job; resolves to the daemon's reply ({id, ...}). */
export const submit = (blob) => call("POST", "/api/v1/jobs", blob, "application/zip");
