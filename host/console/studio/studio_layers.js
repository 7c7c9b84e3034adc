// host/console/studio/studio_layers.js: the studio's design layers: their defaults, their property
// forms, and the job.json "design" object they make (docs/job-format.md, design.layers[]).

let serial = 0;

/** A new layer of `type` with the studio's defaults (lengths in mm). */
export function newLayer(type) {
  const base = { id: ++serial, type, name: `${type}-${serial}`, hidden: false, opacity: 1 };
  if (type === "cylindrical")
    return Object.assign(base, { source: "procedural", kind: "stripes", seed: 1, size_px: 512, image: "",
                                 tile_width: 200, tile_height: 0, rotation_deg: 0, offset: [0, 0], repeat: true,
                                 custom_axis: false, axis_origin: [0, 1000, 0], axis_direction: [0, 1, 0] });
  if (type === "planar")
    return Object.assign(base, { source: "procedural", kind: "motif", seed: 1, size_px: 512, image: "",
                                 centre: null, normal: [0, 0, 1], rotation_deg: 0, width: 150, height: 0, repeat: false });
  if (type === "stroke")
    return Object.assign(base, { points: [], radius: 12, colour: "#d01818", alpha: 255, hardness: 0.8 });
  return Object.assign(base, { mesh: "", image: "", units: "mm", max_distance: 30 });
}

const r3 = (v) => v.map((x) => Math.round(x * 1000) / 1000);

// Up vector of a planar layer: world up projected off the normal, turned by rotation_deg about it.
export function planarUp(layer) {
  const n = layer.normal;
  const ref = Math.abs(n[1]) > 0.95 ? [0, 0, -1] : [0, 1, 0];
  const d = ref[0] * n[0] + ref[1] * n[1] + ref[2] * n[2];
  let u = [ref[0] - d * n[0], ref[1] - d * n[1], ref[2] - d * n[2]];
  const len = Math.hypot(...u) || 1;
  u = u.map((x) => x / len);
  const a = (layer.rotation_deg || 0) * Math.PI / 180;
  const c = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]];  // n x u
  return u.map((x, i) => Math.cos(a) * x + Math.sin(a) * c[i]);
}

function source(layer) {
  if (layer.source === "image" && layer.image) return { image: layer.image };
  return { procedural: { kind: layer.kind, seed: Number(layer.seed) || 1, size_px: Number(layer.size_px) || 512 } };
}

/** A layer as job.json writes it, or null while it is not complete (a planar layer not placed). */
export function layerJson(layer) {
  const out = { type: layer.type, name: layer.name, opacity: Number(layer.opacity) };
  if (layer.type === "cylindrical") {
    Object.assign(out, source(layer), { rotation_deg: Number(layer.rotation_deg) || 0,
                                        offset: layer.offset.map(Number), repeat: !!layer.repeat });
    if (Number(layer.tile_width) > 0) out.tile_width = Number(layer.tile_width);
    if (Number(layer.tile_height) > 0) out.tile_height = Number(layer.tile_height);
    if (layer.custom_axis) {
      out.axis_origin = layer.axis_origin.map(Number);
      out.axis_direction = layer.axis_direction.map(Number);
    }
  } else if (layer.type === "planar") {
    if (!layer.centre) return null;
    Object.assign(out, source(layer), { centre: r3(layer.centre), normal: r3(layer.normal), up: r3(planarUp(layer)),
                                        width: Number(layer.width), repeat: !!layer.repeat });
    if (Number(layer.height) > 0) out.height = Number(layer.height);
  } else if (layer.type === "stroke") {
    if (layer.points.length < 1) return null;
    const c = layer.colour.match(/[0-9a-f]{2}/gi).map((h) => parseInt(h, 16));
    Object.assign(out, { points: layer.points.map(r3), radius: Number(layer.radius),
                         colour: [c[0], c[1], c[2], Number(layer.alpha)], hardness: Number(layer.hardness) });
  } else {
    if (!layer.mesh || !layer.image) return null;
    Object.assign(out, { mesh: layer.mesh, image: layer.image, units: layer.units, max_distance: Number(layer.max_distance) });
  }
  return out;
}

/** job.json's design: the visible, complete layers, bottom first. */
export function designJson(layers) {
  return { layers: layers.filter((l) => !l.hidden).map(layerJson).filter((l) => l) };
}

// ---- property forms ----

function field(label, input) {
  const wrap = document.createElement("label");
  wrap.className = "st-field";
  wrap.append(label, input);
  return wrap;
}

function input(layer, key, attrs, onChange, index) {
  const el = document.createElement(attrs.tag || "input");
  for (const [k, v] of Object.entries(attrs)) if (k !== "tag" && k !== "options") el.setAttribute(k, v);
  if (attrs.options) for (const o of attrs.options) el.append(new Option(o, o));
  const get = () => (index === undefined ? layer[key] : layer[key][index]);
  const set = (v) => { if (index === undefined) layer[key] = v; else layer[key][index] = v; };
  if (el.type === "checkbox") el.checked = !!get();
  else el.value = get() === null || get() === undefined ? "" : get();
  el.dataset.key = index === undefined ? key : `${key}.${index}`;
  el.addEventListener(el.type === "checkbox" || el.tagName === "SELECT" ? "change" : "input", () => {
    const v = el.type === "checkbox" ? el.checked : el.type === "number" || el.type === "range" ? Number(el.value) : el.value;
    set(v);
    onChange(key);
  });
  return el;
}

const num = (min, max, step) => ({ type: "number", min, max, step });

/**
 * Fills `host` with the form of `layer`. `onChange(key)` after each edit; `upload(file)` resolves
 * to an asset path; `onRebuild()` when the form must be drawn again (source switched).
 */
export function layerForm(host, layer, { onChange, upload, onRebuild }) {
  host.replaceChildren();
  const add = (label, key, attrs, index) => host.append(field(label, input(layer, key, attrs, onChange, index)));
  add("Name", "name", { type: "text", maxlength: 60 });
  add("Opacity", "opacity", num(0, 1, 0.05));
  const fileButton = (label, accept, key) => {
    const f = document.createElement("input");
    f.type = "file";
    f.accept = accept;
    f.dataset.key = key + "-file";
    f.addEventListener("change", async () => {
      if (!f.files[0]) return;
      layer[key] = await upload(f.files[0]);
      if (key === "image") layer.source = "image";
      onChange(key);
      onRebuild();
    });
    host.append(field(label, f));
    if (layer[key]) host.append(Object.assign(document.createElement("p"), { className: "st-note", textContent: layer[key] }));
  };
  if (layer.type === "cylindrical" || layer.type === "planar") {
    add("Source", "source", { tag: "select", options: ["procedural", "image"] });
    host.lastChild.querySelector("select").addEventListener("change", onRebuild);
    if (layer.source === "image") fileButton("Image (PNG, JPEG, TIFF, EXR)", "image/*,.tif,.tiff,.exr", "image");
    else {
      add("Pattern", "kind", { tag: "select", options: ["marbling", "stripes", "motif"] });
      add("Seed", "seed", num(1, 1e6, 1));
      add("Tile pixels", "size_px", num(64, 4096, 64));
    }
  }
  if (layer.type === "cylindrical") {
    add("Tile width, mm (0: once around)", "tile_width", num(0, 5000, 10));
    add("Tile height, mm (0: keep aspect)", "tile_height", num(0, 5000, 10));
    add("Rotation, degrees", "rotation_deg", num(-360, 360, 5));
    add("Offset around, mm", "offset", num(-5000, 5000, 5), 0);
    add("Offset along, mm", "offset", num(-5000, 5000, 5), 1);
    add("Repeat", "repeat", { type: "checkbox" });
    add("Own axis", "custom_axis", { type: "checkbox" });
    if (layer.custom_axis)
      for (const [label, key] of [["Axis origin", "axis_origin"], ["Axis direction", "axis_direction"]])
        for (let i = 0; i < 3; ++i) add(`${label} ${"xyz"[i]}`, key, num(-5000, 5000, key === "axis_origin" ? 10 : 0.1), i);
  } else if (layer.type === "planar") {
    host.append(Object.assign(document.createElement("p"), { className: "st-note",
      textContent: layer.centre ? `Centre ${layer.centre.map((x) => x.toFixed(0)).join(", ")} mm: click or drag on the garment (Place tool) to move it.`
                                : "Choose the Place tool and click the garment to put the image there." }));
    add("Width, mm", "width", num(5, 3000, 5));
    add("Height, mm (0: keep aspect)", "height", num(0, 3000, 5));
    add("Rotation, degrees", "rotation_deg", num(-360, 360, 5));
    add("Repeat", "repeat", { type: "checkbox" });
  } else if (layer.type === "stroke") {
    host.append(Object.assign(document.createElement("p"), { className: "st-note",
      textContent: `${layer.points.length} points painted on the surface.` }));
    add("Radius, mm", "radius", num(1, 200, 1));
    add("Colour", "colour", { type: "color" });
    add("Alpha (0-255)", "alpha", num(0, 255, 5));
    add("Hardness", "hardness", num(0, 1, 0.05));
  } else {
    fileButton("Textured OBJ (garment coordinates)", ".obj", "mesh");
    fileButton("Its texture image", "image/*,.tif,.tiff,.exr", "image");
    add("OBJ units", "units", { tag: "select", options: ["mm", "cm", "m", "in"] });
    add("Max distance, mm", "max_distance", num(1, 500, 1));
  }
}
