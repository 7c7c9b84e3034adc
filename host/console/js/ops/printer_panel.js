// host/console/js/ops/printer_panel.js: the printer panel: state and faults as they happen, the
// swath buffer, the device's counters and the cutter's cue log (GET /api/v1/printer, printer events).
import * as api from "../api.js";
import { el, fixed } from "../util.js";

export class PrinterPanel {
  constructor(body) {
    this.body = body;
    this.status = null;
    this.live = null;  // the newest printer event, shown before the next full status arrives
    this.timer = null;
  }

  async refresh() {
    try {
      this.status = await api.printer();
      this.live = null;
      this.render();
    } catch (e) {
      this.body.replaceChildren(el("p", { class: "error" }, e.message));
    }
  }

  /** A `printer` event: state and faults show at once; the counters follow from a status fetch. */
  event(data) {
    this.live = data;
    this.render();
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.refresh(), 300);
  }

  render() {
    const s = this.status || {};
    const d = s.device || null;
    const state = (this.live && this.live.state) || (d && d.state) || s.state || "unknown";
    const faults = (this.live && this.live.faults) || (d && d.faults) || [];
    const parts = [];
    parts.push(el("dl", { class: "kv" },
      el("dt", {}, "State"), el("dd", { id: "printer-state", "data-state": state }, el("span", { class: `state p-${state}` }, state)),
      el("dt", {}, "Printer"), el("dd", {}, `${s.printer || "–"}${s.model ? " · " + s.model : ""}`),
      el("dt", {}, "Job"), el("dd", {}, s.job_id ? `#${s.job_id} ${s.stage || ""}` : "none")));
    parts.push(el("div", { id: "printer-faults", class: "faults", role: "alert", "aria-live": "assertive" },
      faults.length ? faults.map((f) => el("p", { class: f.stops_job ? "fault stop" : "fault pause", "data-condition": f.condition },
                                           el("strong", {}, f.condition.replace(/_/g, " ")), ": ", f.text))
                    : el("p", { class: "muted" }, "no faults")));
    if (d && d.swath_buffer) {
      const b = d.swath_buffer, pct = Math.round(100 * (b.fill || 0));
      parts.push(el("div", { class: "buffer" }, el("span", {}, `Swath buffer ${b.slots_used}/${b.slots} slots, `,
                                                  `${fixed(b.bytes_used / 1048576, 1)} of ${fixed(b.bytes / 1048576, 1)} MiB`),
        el("div", { class: "bar", role: "progressbar", "aria-valuenow": pct, "aria-valuemin": 0, "aria-valuemax": 100,
                    "aria-label": "swath buffer fill" }, el("span", { class: "fill", style: `width:${pct}%` }))));
    }
    const c = Object.assign({}, (s.counters || {}), (d && d.counters) || {});
    const names = { jobs_run: "jobs run", swaths_acked: "swaths acknowledged", swaths_committed: "swaths committed",
                    swaths_printed: "swaths printed", fabric_pos_um: "fabric fed", cues_registered: "cues registered",
                    rx_crc_errors: "CRC errors", rx_gaps: "gaps", naks: "NAKs", fault_changes: "faults since start" };
    parts.push(el("table", { class: "counters", id: "printer-counters" },
      el("tbody", {}, Object.keys(names).filter((k) => k in c).map((k) =>
        el("tr", { "data-counter": k }, el("th", { scope: "row" }, names[k]),
           el("td", {}, k === "fabric_pos_um" ? fixed(c[k] / 1000, 1, "mm") : String(c[k])))))));
    const cues = (d && d.cutter_lines) || [];
    parts.push(el("details", { class: "cues", open: cues.length > 0 },
      el("summary", {}, `Cutter cue log (${cues.length})`),
      cues.length ? el("table", { class: "cue-log" },
        el("thead", {}, el("tr", {}, el("th", {}, "#"), el("th", {}, "kind"), el("th", {}, "line"),
                                     el("th", {}, "planned mm"), el("th", {}, "fired at mm"))),
        el("tbody", {}, cues.slice().reverse().map((q) => el("tr", {}, el("td", {}, String(q.id)), el("td", {}, q.kind),
          el("td", {}, q.line), el("td", {}, fixed(q.position_um / 1000, 1)), el("td", {}, fixed(q.fired_at_um / 1000, 1))))))
        : el("p", { class: "muted" }, "no cues fired yet")));
    this.body.replaceChildren(...parts);
  }
}
