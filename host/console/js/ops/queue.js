// host/console/js/ops/queue.js: the queue (queued, running) and history (done, failed, cancelled)
// tables, with each job's per-stage and overall progress from the event stream, elapsed and left.
import * as api from "../api.js";
import { el, duration, clock } from "../util.js";

/** The pipeline's stages in order (docs/api.yaml) with rough shares of a job's time for the overall bar. */
export const STAGES = ["intake", "pattern", "mesh", "garment", "design", "marker", "print", "outputs"];
const WEIGHT = { intake: 1, pattern: 1, mesh: 1, garment: 4, design: 2, marker: 3, print: 6, outputs: 2 };
const ENDED = new Set(["done", "failed", "cancelled"]);
const FINISHED_STAGE = new Set(["done", "reused", "skipped"]);
const PAGE = 200;

/** Overall fraction 0..1 of a job from its stages' states and fractions. */
export function overall(stages) {
  let sum = 0, total = 0;
  for (const s of STAGES) {
    const st = stages[s];
    total += WEIGHT[s];
    if (!st) continue;
    if (FINISHED_STAGE.has(st.state)) sum += WEIGHT[s];
    else if (st.state === "running") sum += WEIGHT[s] * Math.min(1, Math.max(0, st.fraction || 0));
  }
  return total ? sum / total : 0;
}

export class Queue {
  constructor(queueTable, historyTable, moreButton, onOpen) {
    this.queueBody = queueTable.tBodies[0];
    this.historyBody = historyTable.tBodies[0];
    this.more = moreButton;
    this.onOpen = onOpen;
    this.limit = PAGE;
    this.jobs = new Map();     // id -> job object from the API
    this.stages = new Map();   // id -> { stage: {state, fraction, detail} }
    this.started = new Map();  // id -> ms the job began running, when seen
    this.dirty = new Set();
    this.pending = null;
    this.more.addEventListener("click", () => { this.limit += PAGE; this.refresh(); });
  }

  /** Reloads the job list (debounced: many events may ask at once). */
  refresh() {
    if (this.pending) return this.pending;
    this.pending = new Promise((r) => setTimeout(r, 50)).then(() => this.load()).finally(() => { this.pending = null; });
    return this.pending;
  }

  async load() {
    let page;
    try {
      page = await api.listJobs(this.limit, 0);
    } catch (e) {
      this.queueBody.replaceChildren(el("tr", {}, el("td", { colspan: 5, class: "error" }, e.message)));
      return;
    }
    this.jobs.clear();
    for (const j of page.jobs) this.jobs.set(j.id, j);
    this.total = page.total;
    // A running or queued job's stages come from its own record; later events keep them current.
    await Promise.all(page.jobs.filter((j) => !ENDED.has(j.state) && !this.stages.has(j.id)).map(async (j) => {
      try {
        const full = await api.getJob(j.id);
        const m = {};
        for (const s of full.job.stages || []) m[s.stage] = { state: s.state, fraction: FINISHED_STAGE.has(s.state) ? 1 : 0 };
        this.stages.set(j.id, Object.assign(m, this.stages.get(j.id) || {}));
      } catch (e) { /* the row still shows its state */ }
    }));
    this.render();
  }

  /** A `progress` event: one stage of one job moved. */
  progress(ev) {
    const m = this.stages.get(ev.job_id) || {};
    const prev = m[ev.stage] || {};
    m[ev.stage] = {
      state: ev.state,
      fraction: ev.fraction !== undefined ? ev.fraction : (FINISHED_STAGE.has(ev.state) ? 1 : prev.fraction || 0),
      detail: ev.detail || (ev.state === "running" ? prev.detail : ""),
    };
    this.stages.set(ev.job_id, m);
    if (!this.started.has(ev.job_id)) this.started.set(ev.job_id, ev.time_ms);
    const j = this.jobs.get(ev.job_id);
    if (!j) return this.refresh();
    if (j.state === "queued") j.state = "running";
    j.stage = ev.stage;
    this.mark(ev.job_id);
  }

  /** A `job` event: a job was queued, began, or ended. */
  jobEvent(ev) {
    const j = this.jobs.get(ev.job_id);
    if (ev.state === "running" && !this.started.has(ev.job_id)) this.started.set(ev.job_id, ev.time_ms);
    if (j) {
      j.state = ev.state;
      if (ev.error !== undefined) j.error = ev.error;
      j.updated_ms = ev.time_ms;
    }
    this.refresh();
  }

  /** Once a second: running jobs' elapsed and left move on. */
  tick() {
    for (const [id, j] of this.jobs) if (j.state === "running") this.mark(id);
  }

  mark(id) {
    this.dirty.add(id);
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = null;
      for (const d of this.dirty) {
        const row = document.querySelector(`tr[data-job-id="${d}"]`);
        const j = this.jobs.get(d);
        if (!row || !j) continue;
        const running = !ENDED.has(j.state);
        if (running !== (row.parentNode === this.queueBody)) { this.render(); break; }
        this.keepingFocus(() => row.replaceWith(running ? this.queueRow(j) : this.historyRow(j)));
      }
      this.dirty.clear();
    });
  }

  render() {
    const all = [...this.jobs.values()];
    // The queue runs oldest first, the history shows the newest first.
    const active = all.filter((j) => !ENDED.has(j.state)).sort((a, b) => a.id - b.id);
    const ended = all.filter((j) => ENDED.has(j.state));
    this.keepingFocus(() => {
      this.queueBody.replaceChildren(...(active.length ? active.map((j) => this.queueRow(j))
        : [el("tr", {}, el("td", { colspan: 5, class: "muted" }, "nothing queued"))]));
      this.historyBody.replaceChildren(...ended.map((j) => this.historyRow(j)));
    });
    document.getElementById("queue-count").textContent = `(${active.length})`;
    document.getElementById("history-count").textContent = `(${ended.length}${this.total > all.length ? " of " + (this.total - active.length) : ""})`;
    this.more.hidden = !(this.total > all.length);
    // The first full list is a mark on the page's timeline (docs/console.md: first paint figures).
    if (!this.marked) { this.marked = true; performance.mark("tp-jobs-rendered"); }
  }

  /** Runs `rebuild`, which replaces rows; a job's button that had the keyboard focus keeps it on
   *  its new row (rows are rebuilt every second while a job runs and on every job event). */
  keepingFocus(rebuild) {
    const had = document.activeElement;
    const id = had && had.dataset ? had.dataset.open : undefined;
    rebuild();
    if (id === undefined || had.isConnected) return;
    const again = this.queueBody.querySelector(`button[data-open="${id}"]`) ||
                  this.historyBody.querySelector(`button[data-open="${id}"]`);
    if (again) again.focus({ preventScroll: true });
  }

  nameCell(j) {
    return el("td", {}, el("button", { type: "button", class: "link", "data-open": j.id, onclick: () => this.onOpen(j.id),
                                       "aria-label": `Open job ${j.id} ${j.name}` }, `#${j.id} ${j.name}`));
  }

  stageBars(id, j) {
    const m = this.stages.get(id) || {};
    const ended = j && j.state === "done";
    return el("div", { class: "stages", "aria-hidden": "true" }, STAGES.map((s) => {
      const st = m[s] || (ended ? { state: "done", fraction: 1 } : { state: "fresh", fraction: 0 });
      const f = FINISHED_STAGE.has(st.state) ? 1 : (st.fraction || 0);
      return el("span", { class: `seg st-${st.state}`, title: `${s}: ${st.state}${st.detail ? " – " + st.detail : ""}` },
                el("span", { class: "fill", style: `width:${(100 * f).toFixed(1)}%` }));
    }));
  }

  elapsed(j) {
    const now = Date.now();
    const from = this.started.get(j.id) || j.submitted_ms;
    return ENDED.has(j.state) ? (j.updated_ms - j.submitted_ms) / 1000 : (now - from) / 1000;
  }

  queueRow(j) {
    const m = this.stages.get(j.id) || {};
    const f = j.state === "running" ? overall(m) : 0;
    const running = STAGES.find((s) => m[s] && m[s].state === "running");
    const detail = running ? `${running}${m[running].detail ? ": " + m[running].detail : ""}` : (j.stage || "");
    const elapsed = j.state === "running" ? this.elapsed(j) : null;
    const left = elapsed !== null && f > 0.03 ? elapsed * (1 - f) / f : null;
    const pct = Math.round(100 * f);
    return el("tr", { "data-job-id": j.id, "data-state": j.state },
      this.nameCell(j),
      el("td", {}, el("span", { class: `state s-${j.state}` }, j.state), el("div", { class: "muted small" }, detail)),
      el("td", { class: "progress-cell" },
        this.stageBars(j.id, j),
        el("div", { class: "bar overall", role: "progressbar", "aria-valuemin": 0, "aria-valuemax": 100,
                    "aria-valuenow": pct, "aria-label": `job ${j.id} overall progress` },
           el("span", { class: "fill", style: `width:${pct}%` }), el("span", { class: "pct" }, `${pct}%`))),
      el("td", {}, duration(elapsed)),
      el("td", {}, j.state === "running" ? (left === null ? "estimating…" : "~" + duration(left)) : "–"));
  }

  historyRow(j) {
    return el("tr", { "data-job-id": j.id, "data-state": j.state },
      this.nameCell(j),
      el("td", {}, el("span", { class: `state s-${j.state}` }, j.state),
        j.error ? el("div", { class: "error small", title: j.error }, j.error.length > 90 ? j.error.slice(0, 90) + "…" : j.error) : null),
      el("td", { class: "progress-cell" }, this.stageBars(j.id, j)),
      el("td", {}, duration(this.elapsed(j))),
      el("td", {}, clock(j.updated_ms)));
  }
}
