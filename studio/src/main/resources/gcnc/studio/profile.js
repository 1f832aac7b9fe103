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

/**
 * The box the view shows: where the tool cuts (the feed moves) and the centreline, with a margin. Rapids
 * to and from home, the rest of the bar, the chuck and the tailstock reach further and are clipped: at
 * the scale of the whole machine the passes of a part would lie a pixel apart.
 */
function bounds(d) {
  let zMin = Infinity, zMax = -Infinity, xMin = 0, xMax = 0;
  const take = (m) => m.z.forEach((z, i) => {
    zMin = Math.min(zMin, z); zMax = Math.max(zMax, z); xMin = Math.min(xMin, m.x[i]); xMax = Math.max(xMax, m.x[i]);
  });
  const feeds = d.moves.filter((m) => !m.rapid);
  (feeds.length ? feeds : d.moves).forEach(take);
  if (!isFinite(zMin)) return null;
  const mz = Math.max((zMax - zMin) * 0.06, 1e-3), mx = Math.max((xMax - xMin) * 0.08, 1e-3);
  return { zMin: zMin - mz, zMax: zMax + mz, xMin: xMin - mx, xMax: xMax + mx };
}

/**
 * Draws `drawing` into `svg`; `onPick(line, file, elsewhere)` when a move is clicked (`file`: the called program
 * the line is in, when not this one; `elsewhere`: in a file outside the studio's folder). Returns a function that lights the
 * moves of one G-code line (and returns how many it lit); its `scrub(answer)` draws an answer of
 * POST /api/stock over the drawing (null takes it away): the stock as it stood after the block, what the
 * block removed (between the outline before it and after it) and the insert and holder where it ended;
 * its `running(line)` lights the moves of the block a run executes and `tool(x, z)` marks where the tool is
 * (program coordinates, as the run's status gives them); its `finding(code, line)` marks the place of a
 * simulator's finding (the error list's row) and says whether the drawing has it.
 */
export function drawProfile(svg, drawing, onPick) {
  svg.replaceChildren();
  el("rect", { x: 0, y: 0, width: W, height: H, class: "background" }, svg);
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
  // rapids first, feeds over them: a click where a rapid crosses a cut picks the cut
  const ordered = [...drawing.moves.filter((m) => m.rapid), ...drawing.moves.filter((m) => !m.rapid)];
  ordered.forEach((m) => {
    const g = el("g", { class: "move" + (m.rapid ? " rapid" : " feed"), "data-line": m.line }, svg);
    if (m.file) g.dataset.file = m.file;
    const title = el("title", {}, g);
    title.textContent = m.file ? `${m.file}: line ${m.line}` : `line ${m.line}`;
    // a wide transparent stroke under the visible one: a thin move is easy to click
    el("polyline", { points: pts(m.z, m.x), class: "hit" }, g);
    el("polyline", { points: pts(m.z, m.x), class: "stroke" }, g);
    g.addEventListener("click", () => onPick(m.line, m.file, m.elsewhere));
    if (m.file || m.elsewhere) return; // a line of another file: not lit by this file's cursor
    if (!byLine.has(m.line)) byLine.set(m.line, []);
    byLine.get(m.line).push(g);
  });
  for (const k of drawing.marks) {
    const c = el("circle", { cx: px(k.z), cy: py(k.x), r: 5, class: "mark", "data-code": k.code, "data-line": k.line }, svg);
    el("title", {}, c).textContent = `${k.code} ${k.block}`;
  }
  // the scale: the program's Z at the left and right edges, its X (diameter) at the top and the centreline
  const label = (x, y, text, anchor) => {
    const e = el("text", { x, y, class: "scale", "text-anchor": anchor }, svg);
    e.textContent = text;
  };
  const fmt = (v) => (Math.abs(v) >= 100 ? v.toFixed(0) : v.toFixed(2));
  label(4, H - 4, `Z ${fmt(b.zMin)}`, "start");
  label(W - 4, H - 4, `Z ${fmt(b.zMax)}`, "end");
  label(4, 12, `X ${fmt(b.xMax)}`, "start");
  label(4, py(0) - 3, "X 0", "start");
  let lit = [];
  const light = (line) => {
    lit.forEach((g) => g.classList.remove("current"));
    lit = byLine.get(line) || [];
    lit.forEach((g) => { g.classList.add("current"); svg.appendChild(g); }); // drawn last: on top
    return lit.length;
  };
  // a finding of the simulator picked in the error list: its place marked (larger, on top); none: none
  light.finding = (code, line) => {
    let picked = null;
    for (const c of svg.querySelectorAll("circle.mark")) {
      const it = c.dataset.code === code && Number(c.dataset.line) === line;
      c.classList.toggle("picked", it && picked === null);
      if (it && picked === null) picked = c;
    }
    if (picked) { picked.setAttribute("r", 9); svg.appendChild(picked); }
    for (const c of svg.querySelectorAll("circle.mark:not(.picked)")) c.setAttribute("r", 5);
    return picked !== null;
  };
  // Run: the block executing, lit apart from the cursor's, and the tool where the controller says it is
  let running = [];
  light.running = (line) => {
    running.forEach((g) => g.classList.remove("running"));
    running = line === null ? [] : byLine.get(line) || [];
    running.forEach((g) => { g.classList.add("running"); svg.appendChild(g); });
    const t = svg.querySelector("circle.tool");
    if (t) svg.appendChild(t);
  };
  light.tool = (x, z) => {
    let t = svg.querySelector("circle.tool");
    if (!t) t = el("circle", { r: 5, class: "tool" }, svg);
    t.setAttribute("cx", px(z).toFixed(2));
    t.setAttribute("cy", py(x).toFixed(2));
    t.dataset.x = x;
    t.dataset.z = z;
    svg.appendChild(t);
  };
  const axis = drawing.stock ? drawing.stock.xAxis : 0;
  /** A stock outline (x for each z) closed down to the centreline. */
  const solid = (o) => {
    const n = o.z.length;
    return pts([o.z[0], ...o.z, o.z[n - 1]], [axis, ...o.x, axis]);
  };
  light.scrub = (s) => {
    const old = svg.querySelector("g.scrub");
    if (old) old.remove();
    svg.classList.toggle("scrubbing", !!(s && s.found));
    if (!s || !s.found) return;
    const g = el("g", { class: "scrub", "data-line": s.line }, svg);
    // the outline before the block, then the one after it over it: what shows of the first is what the block took
    if (s.before.z.length > 1) el("polygon", { points: solid(s.before), class: "removed" }, g);
    if (s.after.z.length > 1) el("polygon", { points: solid(s.after), class: "left" }, g);
    if (s.holder) el("polygon", { points: pts(s.holder.z, s.holder.x), class: "holder" }, g);
    if (s.insert) el("polygon", { points: pts(s.insert.z, s.insert.x), class: "insert" }, g);
    // the moves stay on top, so that the path can still be clicked
    for (const m of svg.querySelectorAll("g.move")) svg.appendChild(m);
    for (const m of svg.querySelectorAll("circle.mark")) svg.appendChild(m);
  };
  return light;
}
