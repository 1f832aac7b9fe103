// The lathe's half-profile as SVG: Z along (to the right), X as the program gives it (a diameter) upwards,
// from POST /api/simulate's "drawing". The blank, the finished part, the chuck and tailstock, the path
// (rapids dashed) and where the simulator found something. Each move is an element with its G-code line,
// so the page can light the block under the cursor and move the cursor to a clicked move.
const NS = "http://www.w3.org/2000/svg";
const W = 600, H = 300, PAD = 16;

function el(name, attrs, parent) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

/** The box around the path and the blank (chuck and tailstock reach far: they are only clipped). */
function bounds(d) {
  let zMin = Infinity, zMax = -Infinity, xMin = Infinity, xMax = -Infinity;
  const take = (zs, xs) => zs.forEach((z, i) => {
    zMin = Math.min(zMin, z); zMax = Math.max(zMax, z); xMin = Math.min(xMin, xs[i]); xMax = Math.max(xMax, xs[i]);
  });
  d.moves.forEach((m) => take(m.z, m.x));
  if (d.stock) take([d.stock.zBack, d.stock.zFace], [d.stock.xAxis, d.stock.x]);
  if (!isFinite(zMin)) return null;
  xMin = Math.min(xMin, 0);
  return { zMin, zMax, xMin, xMax };
}

/**
 * Draws `drawing` into `svg`; `onPick(line)` when a move is clicked. Returns a function that lights the
 * moves of one G-code line (and returns how many it lit).
 */
export function drawProfile(svg, drawing, onPick) {
  svg.replaceChildren();
  const b = drawing && bounds(drawing);
  if (!b) return () => 0;
  // one scale for both axes: a diameter looks as large as the same length along Z
  const s = Math.min((W - 2 * PAD) / Math.max(b.zMax - b.zMin, 1e-6), (H - 2 * PAD) / Math.max(b.xMax - b.xMin, 1e-6));
  const px = (z) => PAD + (z - b.zMin) * s;
  const py = (x) => H - PAD - (x - b.xMin) * s;
  const pts = (zs, xs) => zs.map((z, i) => `${px(z).toFixed(2)},${py(xs[i]).toFixed(2)}`).join(" ");
  el("line", { x1: 0, x2: W, y1: py(0), y2: py(0), class: "centreline" }, svg);
  for (const c of drawing.chuck) el("polygon", { points: pts(c.z, c.x), class: "chuck" }, svg);
  for (const c of drawing.tailstock) el("polygon", { points: pts(c.z, c.x), class: "tailstock" }, svg);
  if (drawing.stock) {
    const st = drawing.stock;
    el("rect", { x: px(Math.min(st.zBack, st.zFace)), y: py(Math.max(st.x, st.xAxis)),
      width: Math.abs(st.zFace - st.zBack) * s, height: Math.abs(st.x - st.xAxis) * s, class: "blank" }, svg);
    if (st.final.z.length > 1) {
      const zs = [st.final.z[0], ...st.final.z, st.final.z[st.final.z.length - 1]];
      const xs = [st.xAxis, ...st.final.x, st.xAxis];
      el("polygon", { points: pts(zs, xs), class: "part" }, svg);
    }
  }
  const byLine = new Map();
  drawing.moves.forEach((m) => {
    const g = el("g", { class: "move" + (m.rapid ? " rapid" : " feed"), "data-line": m.line }, svg);
    const title = el("title", {}, g);
    title.textContent = `line ${m.line}`;
    // a wide transparent stroke under the visible one: a thin move is easy to click
    el("polyline", { points: pts(m.z, m.x), class: "hit" }, g);
    el("polyline", { points: pts(m.z, m.x), class: "stroke" }, g);
    g.addEventListener("click", () => onPick(m.line));
    if (!byLine.has(m.line)) byLine.set(m.line, []);
    byLine.get(m.line).push(g);
  });
  for (const k of drawing.marks) {
    const c = el("circle", { cx: px(k.z), cy: py(k.x), r: 5, class: "mark" }, svg);
    el("title", {}, c).textContent = `${k.code} ${k.block}`;
  }
  let lit = [];
  return (line) => {
    lit.forEach((g) => g.classList.remove("current"));
    lit = byLine.get(line) || [];
    lit.forEach((g) => { g.classList.add("current"); svg.appendChild(g); }); // drawn last: on top
    return lit.length;
  };
}
