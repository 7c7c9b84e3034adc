// host/console/studio/studio.js: the design studio (docs/studio.md): choose and sew a garment, build
// the design's layers on it in 3D, see the daemon's own render of it on the garment and on the
// flat pieces after each change, and save or print it as a job package. Exports mount(container,
// context) for the console's Studio tab; /studio/index.html mounts it on its own.
import * as api from "./studio_api.js";
import { createScene, loadThree } from "./studio_scene.js";
import { designJson, layerForm, newLayer, planarUp } from "./studio_layers.js";

const SAMPLES = ["simple_top", "blouse", "dress", "skirt8"];
const DEBOUNCE_MS = 80;

function h(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") e.className = v;
    else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children) if (c !== null && c !== undefined) e.append(c);
  return e;
}

function labelled(text, control) { return h("label", { class: "st-field" }, text, control); }

const state = {
  garment: null, layers: [], selected: null, tool: "orbit", box: null,
  pendingSince: null, seq: 0, applied: 0, timings: [], inflight: null, context: null,
};

/** Mounts the studio into `container`. `context` (optional) is the console's. */
export async function mount(container, context) {
  state.context = context || null;
  container.classList.add("st-root");
  // Inside the console the page shell has only its own stylesheet: bring the studio's.
  const css = new URL("./studio.css", import.meta.url).href;
  if (![...document.styleSheets].some((sheet) => sheet.href === css))
    document.head.append(Object.assign(document.createElement("link"), { rel: "stylesheet", href: css }));
  const base = container.dataset.threeBase || "/vendor/three/";
  const lib = await loadThree(base);
  const status = h("p", { class: "st-status", role: "status", "aria-live": "polite" }, "Choose a garment and sew it.");
  const problems = h("ul", { class: "st-problems", "aria-live": "polite" });

  // Garment chooser: a sample and size, or an uploaded pattern with a body.
  const sample = h("select", { id: "st-sample" }, ...SAMPLES.map((s) => new Option(s, s)));
  const size = h("select", { id: "st-size" }, ...["S", "M", "L"].map((s) => new Option(s, s)));
  size.value = "M";
  const patternFile = h("input", { type: "file", id: "st-pattern", accept: ".json,.svg,.dxf" });
  const bodyFile = h("input", { type: "file", id: "st-body", accept: ".obj" });
  const bodyUnits = h("select", { id: "st-body-units" }, ...["mm", "cm", "m", "in"].map((s) => new Option(s, s)));
  const sewButton = h("button", { type: "button", id: "st-sew", onclick: () => sew(false) }, "Sew sample");
  const sewUpload = h("button", { type: "button", id: "st-sew-upload", onclick: () => sew(true) }, "Sew uploaded pattern");
  const garmentBox = h("fieldset", { class: "st-box" }, h("legend", {}, "Garment"),
    labelled("Sample", sample), labelled("Size", size), sewButton,
    h("details", {}, h("summary", {}, "Upload a pattern"), labelled("Pattern (JSON, GarmentCode, SVG, DXF)", patternFile),
      labelled("Body mesh (OBJ; none: dress form of the size)", bodyFile), labelled("Body units", bodyUnits), sewUpload));

  // Layers: list with order, visibility and delete; the selected layer's form below.
  const list = h("ol", { class: "st-layers", id: "st-layers", "aria-label": "Layers, bottom first" });
  const form = h("div", { class: "st-form", id: "st-form" });
  const addButtons = ["cylindrical", "planar", "stroke", "texture"].map((t) =>
    h("button", { type: "button", "data-add": t, onclick: () => addLayer(t) }, `+ ${t}`));
  const layersBox = h("fieldset", { class: "st-box" }, h("legend", {}, "Layers"), h("div", { class: "st-row" }, ...addButtons), list, form);

  // Tools over the 3D view.
  const tools = ["orbit", "place", "paint"].map((t) =>
    h("button", { type: "button", "data-tool": t, "aria-pressed": String(t === "orbit"), onclick: () => setTool(t),
                  title: { orbit: "Turn the garment (O)", place: "Place the selected planar image by a click (P)", paint: "Paint a stroke (B)" }[t] },
      { orbit: "Orbit", place: "Place", paint: "Paint" }[t]));
  const viewHost = h("div", { class: "st-view", id: "st-view" });
  const centre = h("div", { class: "st-centre" }, h("div", { class: "st-row st-tools", role: "toolbar", "aria-label": "Tools" }, ...tools), viewHost, status);

  // The flat pieces (the same atlas as on the garment) and the job settings.
  const pieces = h("canvas", { class: "st-pieces", id: "st-pieces", role: "img",
                               "aria-label": "The printed pieces, flat, as the daemon renders them, seam lines drawn" });
  const settings = {
    seam_allowance: h("input", { type: "number", min: 0, max: 100, step: 1, value: 10, id: "st-seam" }),
    hem_allowance: h("input", { type: "number", min: 0, max: 200, step: 1, value: 20, id: "st-hem" }),
    corner_style: h("select", { id: "st-corner" }, ...["mitre", "square", "mirror"].map((s) => new Option(s, s))),
    labels: h("select", { id: "st-labels" }, ...["inside", "separate", "none"].map((s) => new Option(s, s))),
    fabric_width: h("input", { type: "number", min: 300, max: 5000, step: 10, value: 1600, id: "st-fabric" }),
    gap: h("input", { type: "number", min: 0, max: 100, step: 1, value: 4, id: "st-gap" }),
    time_limit_s: h("input", { type: "number", min: 1, max: 600, step: 1, value: 5, id: "st-time" }),
    dpi: h("select", { id: "st-dpi" }, ...["150", "300", "600"].map((s) => new Option(s, s))),
    passes: h("select", { id: "st-passes" }, ...["1", "2", "4", "8"].map((s) => new Option(s, s))),
    name: h("input", { type: "text", value: "studio-design", id: "st-name", maxlength: 100 }),
  };
  settings.dpi.value = "300";
  const saveButton = h("button", { type: "button", id: "st-save", onclick: () => save(false) }, "Save job.zip");
  const printButton = h("button", { type: "button", id: "st-print", onclick: () => save(true) }, "Print");
  const download = h("a", { id: "st-download", hidden: "" }, "job.zip");
  const settingsBox = h("fieldset", { class: "st-box" }, h("legend", {}, "Job"),
    labelled("Name", settings.name), labelled("Seam allowance, mm", settings.seam_allowance),
    labelled("Hem allowance, mm", settings.hem_allowance), labelled("Corners", settings.corner_style),
    labelled("Labels", settings.labels), labelled("Fabric width, mm", settings.fabric_width),
    labelled("Gap, mm", settings.gap), labelled("Nesting time, s", settings.time_limit_s),
    labelled("Print dpi", settings.dpi), labelled("Passes", settings.passes),
    h("div", { class: "st-row" }, saveButton, printButton), download);

  container.replaceChildren(h("div", { class: "st-grid" },
    h("aside", { class: "st-side" }, garmentBox, layersBox),
    centre,
    h("aside", { class: "st-side" }, h("fieldset", { class: "st-box" }, h("legend", {}, "Pieces"), pieces), settingsBox, problems)));

  const view = createScene(lib, viewHost, { onPlace, onPaint, onHandle });
  window.studio = { state, view, project: (p) => view.screenOf(p), pick: (x, y) => view.pick(x, y), design: () => designJson(state.layers) };
  container.addEventListener("keydown", (e) => {
    if (e.target.matches("input, select, textarea")) return;
    const t = { o: "orbit", p: "place", b: "paint" }[e.key.toLowerCase()];
    if (t) { setTool(t); e.preventDefault(); }
  });

  function say(text, problemList) {
    status.textContent = text;
    problems.replaceChildren(...(problemList || []).map((p) => h("li", {}, `${p.pointer ? p.pointer + ": " : ""}${p.message}`)));
  }

  async function sew(upload) {
    sewButton.disabled = sewUpload.disabled = true;
    say("Sewing the garment...");
    try {
      const g = upload ? await api.sewUpload(patternFile.files[0], bodyFile.files[0], bodyUnits.value, size.value)
                       : await api.sewSample(sample.value, size.value);
      state.garment = g;
      const objText = await api.garmentMesh(g);
      state.box = view.load(objText);
      state.seams = seamLines(objText);
      say(`${g.garment.sample || "pattern"}: ${g.pieces.length} pieces, ${g.vertices} vertices, sewn in ${g.sew_s.toFixed(1)} s.`);
      viewHost.dataset.garment = g.id;
      changed();
    } catch (e) {
      say(`Sewing failed: ${e.message}`, e.problems);
    } finally {
      sewButton.disabled = sewUpload.disabled = false;
    }
  }

  function selectedLayer() { return state.layers.find((l) => l.id === state.selected) || null; }

  function addLayer(type) {
    const layer = newLayer(type);
    state.layers.push(layer);
    state.selected = layer.id;
    if (type === "planar") setTool("place");
    else if (type === "stroke") setTool("paint");
    renderList();
    changed();
  }

  function renderList() {
    list.replaceChildren(...state.layers.map((l, i) => {
      const move = (d) => () => {
        const j = i + d;
        if (j < 0 || j >= state.layers.length) return;
        [state.layers[i], state.layers[j]] = [state.layers[j], state.layers[i]];
        renderList();
        changed();
      };
      return h("li", { class: l.id === state.selected ? "st-selected" : "", "data-layer": l.id },
        h("button", { type: "button", class: "st-name", "aria-pressed": String(l.id === state.selected),
                      onclick: () => { state.selected = l.id; renderList(); updateGuides(); } }, `${l.name}${l.hidden ? " (hidden)" : ""}`),
        h("button", { type: "button", title: "Down (earlier)", "aria-label": `Move ${l.name} down`, onclick: move(-1) }, "\u2193"),
        h("button", { type: "button", title: "Up (later)", "aria-label": `Move ${l.name} up`, onclick: move(1) }, "\u2191"),
        h("button", { type: "button", "aria-label": `${l.hidden ? "Show" : "Hide"} ${l.name}`,
                      onclick: () => { l.hidden = !l.hidden; renderList(); changed(); } }, l.hidden ? "Show" : "Hide"),
        h("button", { type: "button", "aria-label": `Delete ${l.name}`, onclick: () => {
          state.layers.splice(i, 1);
          if (state.selected === l.id) state.selected = null;
          renderList();
          changed();
        } }, "Delete"));
    }));
    const layer = selectedLayer();
    if (layer) layerForm(form, layer, { onChange: () => changed(), upload: uploadAsset, onRebuild: () => renderList() });
    else form.replaceChildren(h("p", { class: "st-note" }, "Add a layer, or select one to edit it."));
  }

  async function uploadAsset(file) {
    if (!state.garment) throw new Error("sew a garment first");
    try {
      return await api.uploadAsset(state.garment, file);
    } catch (e) {
      say(`Upload failed: ${e.message}`, e.problems);
      throw e;
    }
  }

  function setTool(t) {
    state.tool = t;
    view.setTool(t);
    for (const b of tools) b.setAttribute("aria-pressed", String(b.dataset.tool === t));
  }

  function onPlace(hit, phase) {
    let layer = selectedLayer();
    if (!hit || phase === "up") return;
    if (!layer || layer.type !== "planar") {
      layer = newLayer("planar");
      state.layers.push(layer);
      state.selected = layer.id;
    }
    layer.centre = hit.point;
    if (phase === "down") layer.normal = hit.normal;
    renderList();
    changed(phase === "move");
  }

  // Size and rotation handles of the selected planar image: the wheel (shift: rotation) in the
  // Place tool, or the keys [ ] (size) and , . (rotation) on the canvas.
  function onHandle(kind, steps) {
    const layer = selectedLayer();
    if (!layer || layer.type !== "planar") return;
    if (kind === "size") layer.width = Math.max(5, Math.round(Number(layer.width) * Math.pow(1.05, steps)));
    else layer.rotation_deg = ((Number(layer.rotation_deg) + 5 * steps + 540) % 360) - 180;
    renderList();
    changed();
  }

  let painting = null;
  function onPaint(hit, phase) {
    if (phase === "down") {
      const current = selectedLayer();
      painting = current && current.type === "stroke" && current.points.length === 0 ? current : newLayer("stroke");
      if (painting !== current) {
        if (current && current.type === "stroke") Object.assign(painting, { radius: current.radius, colour: current.colour, alpha: current.alpha, hardness: current.hardness });
        state.layers.push(painting);
      }
      state.selected = painting.id;
      painting.points = [hit.point];
      painting.pieces = new Set([hit.piece]);
      renderList();
    } else if (painting && hit && phase === "move") {
      const last = painting.points[painting.points.length - 1];
      const step = Math.max(1, Number(painting.radius) / 4);
      if (Math.hypot(hit.point[0] - last[0], hit.point[1] - last[1], hit.point[2] - last[2]) >= step) {
        painting.points.push(hit.point);
        painting.pieces.add(hit.piece);
        updateGuides();
      }
    } else if (phase === "up" && painting) {
      say(`Stroke of ${painting.points.length} points over ${[...painting.pieces].join(", ")}.`);
      painting = null;
      renderList();
      changed();
    }
  }

  function updateGuides() {
    for (const l of state.layers) if (l.type === "planar") l.up = planarUp(l);
    view.setGuides(state.layers, state.selected, state.box);
  }

  // A change: guides now, the daemon's render after a short quiet time; the time from the first
  // change of a burst to the texture on the garment is what the studio reports.
  let timer = 0;
  function changed() {
    updateGuides();
    if (!state.garment) return;
    if (state.pendingSince === null) state.pendingSince = performance.now();
    clearTimeout(timer);
    timer = setTimeout(refresh, DEBOUNCE_MS);
  }

  async function refresh() {
    const seq = ++state.seq;
    const since = state.pendingSince;
    if (state.inflight) state.inflight.abort();
    const ctl = new AbortController();
    state.inflight = ctl;
    viewHost.dataset.previewSeq = String(seq);
    try {
      const { blob, headers } = await api.preview(state.garment, designJson(state.layers), ctl.signal);
      if (seq !== state.seq) return;
      await view.setAtlas(blob);
      if (seq !== state.seq) return;
      await drawPieces(pieces, blob, state.seams);
      const ms = performance.now() - since;
      state.pendingSince = null;
      state.applied = seq;
      const part = (h) => Number(headers.get(h)) || 0;
      const t = { ms, parse_ms: part("X-Parse-Ms"), build_ms: part("X-Build-Ms"), render_ms: part("X-Render-Ms"),
                  encode_ms: part("X-Encode-Ms") };
      state.timings.push(t);
      viewHost.dataset.applied = String(seq);
      say(`Preview updated in ${ms.toFixed(0)} ms (daemon ${(t.parse_ms + t.build_ms + t.render_ms + t.encode_ms).toFixed(0)} ms).`);
    } catch (e) {
      if (e.name === "AbortError") return;
      // 409: a newer design superseded this one in the daemon; its own answer follows.
      if (e.status === 409 || seq !== state.seq) return;
      state.pendingSince = null;
      viewHost.dataset.applied = String(seq);
      say(`Preview refused: ${e.message}`, e.problems);
    }
  }

  function jobSettings() {
    const n = (el) => Number(el.value);
    return {
      name: settings.name.value,
      design: designJson(state.layers),
      finishing: { seam_allowance: n(settings.seam_allowance), hem_allowance: n(settings.hem_allowance),
                   corner_style: settings.corner_style.value, labels: settings.labels.value },
      marker: { fabric_width: n(settings.fabric_width), gap: n(settings.gap), time_limit_s: n(settings.time_limit_s) },
      print: { dpi: n(settings.dpi), passes: n(settings.passes) },
    };
  }

  async function save(andPrint) {
    if (!state.garment) return say("Sew a garment first.");
    saveButton.disabled = printButton.disabled = true;
    try {
      const { blob } = await api.jobPackage(state.garment, jobSettings());
      if (download.href) URL.revokeObjectURL(download.href);
      download.href = URL.createObjectURL(blob);
      download.download = `${settings.name.value || "studio-design"}.zip`;
      download.textContent = `${download.download} (${(blob.size / 1024).toFixed(0)} KiB)`;
      download.hidden = false;
      if (!andPrint) {
        download.click();
        say(`Saved ${download.download}.`);
      } else {
        const reply = await api.submit(blob);
        say(`Submitted as job ${reply.id}.`);
        if (state.context && state.context.onSubmitted) state.context.onSubmitted(reply.id);
      }
    } catch (e) {
      say(`${andPrint ? "Print" : "Save"} refused: ${e.message}`, e.problems);
    } finally {
      saveButton.disabled = printButton.disabled = false;
    }
  }

  renderList();
  setTool("orbit");
}

// The seam line of every piece in atlas coordinates (0..1, v up): the UV edges that only one
// triangle of its group uses.
function seamLines(objText) {
  const vt = [], lines = [];
  let count = new Map();
  const flush = () => {
    for (const [key, n] of count) if (n === 1) lines.push(key.split(",").map(Number));
    count = new Map();
  };
  for (const line of objText.split("\n")) {
    if (line.startsWith("vt ")) vt.push(line.split(/\s+/).slice(1, 3).map(Number));
    else if (line.startsWith("g ")) flush();
    else if (line.startsWith("f ")) {
      const idx = line.trim().split(/\s+/).slice(1).map((c) => Number(c.split("/")[1]) - 1);
      for (let i = 0; i < idx.length; ++i) {
        const a = Math.min(idx[i], idx[(i + 1) % idx.length]), b = Math.max(idx[i], idx[(i + 1) % idx.length]);
        const key = `${a},${b}`;
        count.set(key, (count.get(key) || 0) + 1);
      }
    }
  }
  flush();
  return lines.map(([a, b]) => [vt[a], vt[b]]).filter(([p, q]) => p && q);
}

// The atlas on the flat-pieces canvas (fitted to the panel) with the seam lines over it.
async function drawPieces(canvas, blob, seams) {
  const bitmap = await createImageBitmap(blob);
  const width = Math.max(200, canvas.parentElement.clientWidth - 16);
  const scale = Math.min(width / bitmap.width, 320 / bitmap.height);
  canvas.width = Math.round(bitmap.width * scale);
  canvas.height = Math.round(bitmap.height * scale);
  const ctx = canvas.getContext("2d");
  ctx.drawImage(bitmap, 0, 0, canvas.width, canvas.height);
  bitmap.close();
  ctx.strokeStyle = "rgba(60, 80, 110, 0.8)";
  ctx.lineWidth = 1;
  ctx.beginPath();
  for (const [p, q] of seams || []) {
    ctx.moveTo(p[0] * canvas.width, (1 - p[1]) * canvas.height);
    ctx.lineTo(q[0] * canvas.width, (1 - q[1]) * canvas.height);
  }
  ctx.stroke();
}

/** Called by the console each later time the Studio tab opens. */
export function shown() {
  if (window.studio && window.studio.view) window.studio.view.draw();
}
