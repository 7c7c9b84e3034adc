// host/console/js/util.js: small DOM and formatting helpers shared by the console's views.

/** An element with attributes (on* keys become listeners) and children (strings become text). */
export function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith("on") && typeof v === "function") e.addEventListener(k.slice(2), v);
    else if (k === "class") e.className = v;
    else if (k === "text") e.textContent = v;
    else e.setAttribute(k, v === true ? "" : String(v));
  }
  for (const c of children.flat()) {
    if (c === undefined || c === null || c === false) continue;
    e.appendChild(typeof c === "string" || typeof c === "number" ? document.createTextNode(String(c)) : c);
  }
  return e;
}

/** Seconds as "12 s", "3 min 04 s" or "1 h 02 min"; "–" when unknown. */
export function duration(s) {
  if (s === null || s === undefined || !isFinite(s) || s < 0) return "–";
  if (s < 60) return `${s < 10 ? s.toFixed(1) : Math.round(s)} s`;
  const m = Math.floor(s / 60), sec = Math.round(s % 60);
  if (m < 60) return `${m} min ${String(sec).padStart(2, "0")} s`;
  return `${Math.floor(m / 60)} h ${String(m % 60).padStart(2, "0")} min`;
}

/** A number with `digits` decimals and its unit, or "–" for null (not measured). */
export function fixed(v, digits, unit) {
  if (v === null || v === undefined || typeof v !== "number" || !isFinite(v)) return "–";
  return v.toFixed(digits) + (unit ? " " + unit : "");
}

/** Local wall-clock time of a millisecond timestamp. */
export function clock(ms) {
  if (!ms) return "–";
  const d = new Date(ms);
  return d.toLocaleDateString(undefined, { month: "short", day: "numeric" }) + " " +
         d.toLocaleTimeString(undefined, { hour: "2-digit", minute: "2-digit", second: "2-digit" });
}
