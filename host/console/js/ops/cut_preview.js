// host/console/js/ops/cut_preview.js: draws a DXF R12 cut file (blocks placed by INSERT; POLYLINE,
// LWPOLYLINE, LINE, CIRCLE, POINT) as an SVG element, for jobs whose outputs have no cut.svg.

const SVG = "http://www.w3.org/2000/svg";

/** Group-code/value pairs of a DXF text. */
function pairs(text) {
  const lines = text.split(/\r?\n/);
  const out = [];
  for (let i = 0; i + 1 < lines.length; i += 2) out.push([parseInt(lines[i], 10), lines[i + 1].trim()]);
  return out;
}

/** Entities in order: {type, layer, pts: [[x, y]...], closed, r, block, at, scale, rot}. */
function entities(list, start, stop) {
  const ents = [];
  let cur = null, poly = null;
  for (let i = start; i < stop; ++i) {
    const [code, v] = list[i];
    if (code === 0) {
      if (v === "VERTEX" && poly) { cur = { type: "VERTEX", pts: [[0, 0]] }; poly.vertices.push(cur); continue; }
      if (v === "SEQEND") { poly = null; cur = null; continue; }
      cur = { type: v, layer: "0", pts: [], closed: false, scale: [1, 1], rot: 0, vertices: [] };
      ents.push(cur);
      if (v === "POLYLINE") poly = cur;
      continue;
    }
    if (!cur) continue;
    const n = parseFloat(v);
    if (code === 8) cur.layer = v;
    else if (code === 2) cur.block = v;
    else if (code === 10) cur.pts.push([n, 0]);
    else if (code === 20 && cur.pts.length) cur.pts[cur.pts.length - 1][1] = n;
    else if (code === 11) cur.pts.push([n, 0]);
    else if (code === 21 && cur.pts.length) cur.pts[cur.pts.length - 1][1] = n;
    else if (code === 40) cur.r = n;
    else if (code === 41) cur.scale[0] = n;
    else if (code === 42) cur.scale[1] = n;
    else if (code === 50) cur.rot = n;
    else if (code === 70) cur.closed = (parseInt(v, 10) & 1) === 1;
  }
  for (const e of ents) if (e.type === "POLYLINE") e.pts = e.vertices.map((q) => q.pts[0]);
  return ents;
}

/** The SVG drawing of `text`, a DXF file; throws naming what is missing when it holds no geometry. */
export function dxfToSvg(text) {
  const list = pairs(text);
  const blocks = {};
  let entStart = -1, entStop = -1;
  for (let i = 0; i < list.length; ++i) {
    if (list[i][0] === 0 && list[i][1] === "BLOCK") {
      let name = "", j = i + 1;
      while (j < list.length && list[j][0] !== 0) { if (list[j][0] === 2) name = list[j][1]; ++j; }
      let end = j;
      while (end < list.length && !(list[end][0] === 0 && list[end][1] === "ENDBLK")) ++end;
      blocks[name] = entities(list, j, end);
      i = end;
    } else if (list[i][0] === 2 && list[i][1] === "ENTITIES") {
      entStart = i + 1;
      entStop = entStart;
      while (entStop < list.length && !(list[entStop][0] === 0 && list[entStop][1] === "ENDSEC")) ++entStop;
    }
  }
  if (entStart < 0) throw new Error("cut.dxf: no ENTITIES section");
  const paths = [];  // {layer, d, pts}
  const draw = (ents, tf) => {
    for (const e of ents) {
      if (e.type === "INSERT") {
        const at = e.pts[0] || [0, 0], a = e.rot * Math.PI / 180, [sx, sy] = e.scale;
        const inner = (p) => tf([at[0] + Math.cos(a) * sx * p[0] - Math.sin(a) * sy * p[1],
                                 at[1] + Math.sin(a) * sx * p[0] + Math.cos(a) * sy * p[1]]);
        if (blocks[e.block]) draw(blocks[e.block], inner);
      } else if ((e.type === "POLYLINE" || e.type === "LWPOLYLINE" || e.type === "LINE") && e.pts.length >= 2) {
        paths.push({ layer: e.layer, pts: e.pts.map(tf), closed: e.closed });
      } else if (e.type === "CIRCLE" && e.pts.length) {
        const c = tf(e.pts[0]);
        paths.push({ layer: e.layer, circle: c, r: e.r || 1, pts: [c] });
      } else if (e.type === "POINT" && e.pts.length) {
        const c = tf(e.pts[0]);
        paths.push({ layer: e.layer, circle: c, r: 1.5, pts: [c] });
      }
    }
  };
  draw(entities(list, entStart, entStop), (p) => p);
  if (!paths.length) throw new Error("cut.dxf: no lines, polylines or points to draw");
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const p of paths) for (const [x, y] of p.pts) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
  const pad = 0.02 * Math.max(x1 - x0, y1 - y0, 1);
  const svg = document.createElementNS(SVG, "svg");
  // DXF's y grows up, SVG's down: flip about the drawing's box.
  svg.setAttribute("viewBox", `${x0 - pad} ${-(y1 + pad)} ${x1 - x0 + 2 * pad} ${y1 - y0 + 2 * pad}`);
  svg.setAttribute("role", "img");
  svg.setAttribute("aria-label", `cut file: ${paths.length} contours`);
  const stroke = Math.max(x1 - x0, y1 - y0) / 600;
  for (const p of paths) {
    let node;
    if (p.circle) {
      node = document.createElementNS(SVG, "circle");
      node.setAttribute("cx", p.circle[0]);
      node.setAttribute("cy", -p.circle[1]);
      node.setAttribute("r", p.r);
    } else {
      node = document.createElementNS(SVG, "path");
      node.setAttribute("d", "M" + p.pts.map(([x, y]) => `${x.toFixed(2)} ${(-y).toFixed(2)}`).join(" L") + (p.closed ? " Z" : ""));
    }
    node.setAttribute("class", "dxf-layer-" + String(p.layer).replace(/[^A-Za-z0-9_-]/g, "_"));
    node.setAttribute("fill", "none");
    node.setAttribute("stroke", "currentColor");
    node.setAttribute("stroke-width", stroke.toFixed(3));
    svg.appendChild(node);
  }
  return svg;
}
