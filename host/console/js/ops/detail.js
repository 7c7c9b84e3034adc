// host/console/js/ops/detail.js: one job in detail: state, error, cancel and reprint, the report's
// figures (seams, garment distortion, estimate), marker and piece previews, 3D garment and cut file.
import * as api from "../api.js";
import { el, duration, fixed, clock } from "../util.js";
import { STAGES } from "./queue.js";
import { dxfToSvg } from "./cut_preview.js";

const ENDED = new Set(["done", "failed", "cancelled"]);

/** An <img> of a job file, fetched with the token (an <img src> could not send it). */
function fileImage(id, name, alt) {
  const img = el("img", { alt, loading: "lazy" });
  api.fetchFile(id, name, "blob").then((b) => { img.src = URL.createObjectURL(b); })
    .catch((e) => img.replaceWith(el("p", { class: "error" }, e.message)));
  return img;
}

function figureRows(rows) {
  return el("table", { class: "figures" }, el("tbody", {}, rows.filter(Boolean).map(([k, v, id]) =>
    el("tr", id ? { "data-figure": id } : {}, el("th", { scope: "row" }, k), el("td", {}, v)))));
}

export class Detail {
  constructor(section, body, queue) {
    this.section = section;
    this.body = body;
    this.queue = queue;
    this.id = null;
    this.disposeGarment = null;
  }

  /** A job event for the job shown: reload it when it ends, so its outputs appear. */
  jobEvent(ev) {
    if (ev.job_id === this.id && ENDED.has(ev.state)) this.open(this.id, { keepFocus: true });
  }

  /** A `progress` event: when a stage of the job shown begins or ends, its stage table follows. */
  progress(ev) {
    if (ev.job_id !== this.id || (ev.state === "running" && ev.fraction !== 0)) return;
    clearTimeout(this.reload);
    this.reload = setTimeout(() => this.open(this.id, { keepFocus: true }), 200);
  }

  async open(id, opts) {
    this.id = id;
    const serial = this.serial = (this.serial || 0) + 1;  // a later open wins over one still loading
    if (this.disposeGarment) { this.disposeGarment(); this.disposeGarment = null; }
    this.body.replaceChildren(el("p", { class: "muted" }, `loading job #${id}…`));
    let job, files = [];
    try {
      job = (await api.getJob(id)).job;
      files = (await api.jobFiles(id)).files.map((f) => f.name);
    } catch (e) {
      if (!job) return this.body.replaceChildren(el("p", { class: "error" }, e.message));
    }
    if (this.serial !== serial) return;
    this.section.dataset.jobId = id;
    this.section.dataset.state = job.state;
    this.render(job, new Set(files));
    if (!(opts && opts.keepFocus)) this.section.focus();
  }

  render(job, files) {
    const id = job.id, r = job.report || {};
    const head = el("div", { class: "detail-head" },
      el("h3", {}, `#${id} ${job.name} `, el("span", { class: `state s-${job.state}` }, job.state)),
      el("div", { class: "actions" },
        !ENDED.has(job.state) ? el("button", { type: "button", id: "detail-cancel", onclick: () => this.act(() => api.cancelJob(id), id) }, "Cancel") : null,
        ENDED.has(job.state) ? el("button", { type: "button", id: "detail-reprint", onclick: () => this.act(() => api.reprintJob(id), null) }, "Reprint") : null,
        el("button", { type: "button", onclick: () => this.open(id) }, "Reload")));
    const parts = [head, el("p", { class: "muted small" }, `submitted ${clock(job.submitted_ms)} · ${job.origin || ""} · outputs ${job.out_dir}`)];
    const error = job.error || r.error;
    if (error) parts.push(el("div", { class: "job-error", role: "alert" }, el("strong", {}, "Error: "), el("code", { id: "detail-error" }, error)));
    for (const w of r.warnings || []) parts.push(el("p", { class: "warning small" }, w));

    // The stages with their state and wall time.
    const stages = new Map((job.stages || []).map((s) => [s.stage, s]));
    parts.push(el("table", { class: "stage-table" }, el("tbody", {}, STAGES.map((s) => {
      const st = stages.get(s) || { state: "fresh" };
      return el("tr", {}, el("th", { scope: "row" }, s), el("td", {}, el("span", { class: `state st-${st.state}` }, st.state)),
                el("td", {}, st.seconds ? duration(st.seconds) : ""));
    }))));

    // The report's figures: what an operator checks before cutting.
    const seams = r.seams || {}, allow = r.allowance || {}, g = r.garment || {}, chk = g.checks || {};
    const est = r.estimate || {}, meas = r.measured || {}, marker = r.marker || {};
    parts.push(el("h4", {}, "Figures"), figureRows([
      ["pieces", r.piece_count ?? "–"],
      ["fabric length", fixed(r.fabric_length_mm, 0, "mm")],
      ["marker utilisation", marker.utilisation !== undefined ? fixed(100 * marker.utilisation, 1, "%") : "–"],
      ["print time est. / measured", `${duration(est.print_time_s)} / ${duration(meas.print_time_s)}`],
      ["seam continuity ΔE00 mean / p95 / max", `${fixed(seams.de00_mean, 2)} / ${fixed(seams.de00_p95, 2)} / ${fixed(seams.de00_max, 2)}` +
        (seams.count !== undefined ? ` (${seams.count} seams)` : ""), "seams"],
      ["allowance ΔE00 mean / p95", `${fixed(allow.de00_mean, 2)} / ${fixed(allow.de00_p95, 2)}`],
      g.mode ? ["garment", `${g.mode}${g.vertices ? ", " + g.vertices + " vertices" : ""}`] : null,
      ["distortion: strain mean / p95 / max", `${fixed(g.strain_mean, 4)} / ${fixed(g.strain_p95, 4)} / ${fixed(g.strain_max, 4)}`, "strain"],
      ["area change", g.area_change !== undefined ? fixed(100 * g.area_change, 3, "%") : "–"],
      ["seam length difference max", fixed(g.seam_len_diff_max, 4)],
      ["clearance to body (min)", fixed(g.min_clearance_mm, 1, "mm")],
      chk.stitch_gap_max_mm !== undefined ? ["stitch gap max", fixed(chk.stitch_gap_max_mm, 2, "mm")] : null,
      ["job wall time", duration(r.wall_s)],
    ]));

    // Previews once the job has ended: while it runs its outputs are still being written.
    if (!ENDED.has(job.state)) {
      parts.push(el("p", { class: "muted" }, "The marker, pieces, 3D garment and cut file show here when the job ends."));
      this.body.replaceChildren(...parts);
      return;
    }
    if (files.has("marker.png")) parts.push(el("h4", {}, "Marker"), el("div", { class: "preview marker" }, fileImage(id, "marker.png", "marker as printed")));
    const pieces = [...files].filter((f) => /^pieces\/[^/]+\.png$/.test(f)).sort();
    if (pieces.length) parts.push(el("h4", {}, `Pieces (${pieces.length})`), el("div", { class: "pieces" }, pieces.map((p) =>
      el("figure", {}, fileImage(id, p, p), el("figcaption", {}, p.slice(7, -4))))));
    const objs = ["garment.obj", "garment-draped.obj"].filter((f) => files.has(f));
    if (objs.length) parts.push(this.garmentSection(id, objs));
    if (files.has("cut.svg")) parts.push(el("h4", {}, "Cut file (cut.svg)"), el("div", { class: "preview cut" }, fileImage(id, "cut.svg", "cut contours")));
    else if (files.has("cut.dxf")) {
      const box = el("div", { class: "preview cut", id: "detail-cut" }, el("p", { class: "muted" }, "reading cut.dxf…"));
      api.fetchFile(id, "cut.dxf").then((t) => box.replaceChildren(dxfToSvg(t)))
        .catch((e) => box.replaceChildren(el("p", { class: "error" }, e.message)));
      parts.push(el("h4", {}, "Cut file (cut.dxf)"), box);
    }
    if (files.size) parts.push(el("details", {}, el("summary", {}, `All output files (${files.size})`),
      el("ul", { class: "files" }, [...files].sort().map((f) => el("li", {}, el("a", { href: api.fileUrl(id, f), target: "_blank", rel: "noopener" }, f))))));
    this.body.replaceChildren(...parts);
  }

  garmentSection(id, objs) {
    const view = el("div", { class: "garment-view", id: "detail-garment" });
    const load = async (name) => {
      if (this.disposeGarment) this.disposeGarment();
      const serial = this.serial;
      const { showGarment } = await import("./garment_view.js");
      if (serial !== this.serial) return;
      const dispose = await showGarment(view, id, name);
      // Opened again meanwhile: this viewer's canvas is no longer on the page.
      if (serial !== this.serial) dispose();
      else this.disposeGarment = dispose;
    };
    const choose = objs.length > 1 ? el("label", {}, "shape ", el("select", { onchange: (e) => load(e.target.value) },
      objs.map((o) => el("option", { value: o }, o === "garment.obj" ? "sewn on the body" : "draped")))) : null;
    requestAnimationFrame(() => load(objs[0]));
    return el("section", { class: "garment" }, el("h4", {}, "3D garment ", choose), view);
  }

  async act(fn, id) {
    try {
      const r = await fn();
      this.queue.refresh();
      this.open(id || r.id);
    } catch (e) {
      this.body.prepend(el("p", { class: "error", role: "alert" }, e.message));
    }
  }
}
