// host/console/js/ops/submit.js: submitting a job .zip dropped anywhere on the page or chosen with
// the file input; refusals list each problem with its file and field (the daemon's 422 answer).
import * as api from "../api.js";
import { el } from "../util.js";

/** Sends one File (or Blob with a name) and logs the outcome; calls onSubmitted(id) when queued. */
export async function submitFile(file, log, onSubmitted) {
  const entry = el("li", { class: "pending" }, `${file.name}: sending…`);
  log.prepend(entry);
  if (!/\.zip$/i.test(file.name || "")) {
    entry.className = "error";
    entry.textContent = `${file.name}: not a .zip; a job package is a zip of the job folder (docs/job-format.md)`;
    return;
  }
  try {
    const r = await api.submitZip(file);
    entry.className = "ok";
    entry.dataset.jobId = r.id;
    entry.textContent = `${file.name}: ${r.duplicate ? "already " + r.state + " as" : "queued as"} job #${r.id} ${r.name}`;
    onSubmitted(r.id);
  } catch (e) {
    entry.className = "error";
    entry.replaceChildren(`${file.name}: refused: ${e.message}`);
    if (e.problems.length)
      entry.appendChild(el("ul", {}, e.problems.map((p) =>
        el("li", {}, el("code", {}, `${p.file}${p.pointer ? " " + p.pointer : ""}`), `: ${p.message}`))));
  }
}

/** Wires the file input and page-wide drag and drop (the overlay shows while a file is dragged over). */
export function installSubmit(input, overlay, log, onSubmitted) {
  input.addEventListener("change", () => {
    for (const f of input.files) submitFile(f, log, onSubmitted);
    input.value = "";
  });
  let depth = 0;
  const hasFiles = (e) => e.dataTransfer && Array.from(e.dataTransfer.types || []).includes("Files");
  document.addEventListener("dragenter", (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    ++depth;
    overlay.hidden = false;
  });
  document.addEventListener("dragover", (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    e.dataTransfer.dropEffect = "copy";
  });
  document.addEventListener("dragleave", () => {
    depth = Math.max(0, depth - 1);
    if (depth === 0) overlay.hidden = true;
  });
  document.addEventListener("drop", (e) => {
    if (!hasFiles(e)) return;
    // The studio may take drops of its own (images, patterns); only the operator view submits.
    if (document.getElementById("view-ops").hidden) return;
    e.preventDefault();
    depth = 0;
    overlay.hidden = true;
    for (const f of e.dataTransfer.files) submitFile(f, log, onSubmitted);
  });
}
