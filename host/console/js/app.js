// host/console/js/app.js: boots the console: the two views (Operator, Studio), the token prompt,
// the event stream, and the studio hook that loads studio/studio.js when its view first opens.
import * as api from "./api.js";
import { el } from "./util.js";
import { Queue } from "./ops/queue.js";
import { PrinterPanel } from "./ops/printer_panel.js";
import { Detail } from "./ops/detail.js";
import { installSubmit } from "./ops/submit.js";

const linkState = document.getElementById("link-state");
const queue = new Queue(document.getElementById("queue"), document.getElementById("history"),
                        document.getElementById("history-more"), (id) => detail.open(id));
const printerPanel = new PrinterPanel(document.getElementById("printer-body"));
const detail = new Detail(document.getElementById("detail"), document.getElementById("detail-body"), queue);

// The token prompt appears when the daemon asks for one (printd --require-token, or beyond loopback).
const tokenForm = document.getElementById("token-form");
api.onUnauthorised(() => { tokenForm.hidden = false; });
tokenForm.addEventListener("submit", (e) => {
  e.preventDefault();
  api.setToken(document.getElementById("token-input").value.trim());
  tokenForm.hidden = true;
  refreshAll();
});

// Views: tabs with arrow-key movement (WAI-ARIA tabs), the studio mounted on first open.
const tabs = [document.getElementById("tab-ops"), document.getElementById("tab-studio")];
let studio = null;
async function show(tab) {
  for (const t of tabs) {
    const on = t === tab;
    t.setAttribute("aria-selected", String(on));
    t.tabIndex = on ? 0 : -1;
    document.getElementById(t.getAttribute("aria-controls")).hidden = !on;
  }
  if (tab.id === "tab-studio") await openStudio();
}
tabs.forEach((t, i) => {
  t.addEventListener("click", () => show(t));
  t.addEventListener("keydown", (e) => {
    if (e.key !== "ArrowRight" && e.key !== "ArrowLeft") return;
    const next = tabs[(i + (e.key === "ArrowRight" ? 1 : tabs.length - 1)) % tabs.length];
    next.focus();
    show(next);
  });
});

// The studio hook (docs/console.md): studio/studio.js exports mount(container, context) and,
// optionally, shown() called each time the view opens again.
async function openStudio() {
  const container = document.getElementById("view-studio");
  if (studio) { if (studio.shown) studio.shown(); return; }
  try {
    const module = await import("../studio/studio.js");
    studio = module;
    await module.mount(container, {
      api,
      onSubmitted: (id) => { queue.refresh(); detail.open(id); },
      showOperator: () => show(tabs[0]),
    });
  } catch (e) {
    container.replaceChildren(el("p", { class: "error" }, `The design studio could not be loaded: ${e.message}`));
  }
}

function refreshAll() {
  queue.refresh();
  printerPanel.refresh();
}

// Live updates: job states and stage progress go to the queue (and the open job), printer
// changes to the printer panel.
api.followEvents((type, data) => {
  if (type === "progress") { queue.progress(data); detail.progress(data); }
  else if (type === "job") { queue.jobEvent(data); detail.jobEvent(data); printerPanel.refresh(); }
  else if (type === "printer") printerPanel.event(data);
  else if (type === "gap") refreshAll();
}, (state) => {
  linkState.textContent = state === "live" ? "live" : "reconnecting…";
  linkState.dataset.state = state;
  if (state === "live") refreshAll();
});

installSubmit(document.getElementById("submit-file"), document.getElementById("drop-overlay"),
              document.getElementById("submit-log"), (id) => { queue.refresh(); detail.open(id); });
setInterval(() => queue.tick(), 1000);
refreshAll();
