// The hover on a word of the program: what a G or M function does on this control (its row of g_codes.csv or
// m_codes.csv) and the modal state the checker holds after the block of that line (POST /api/hover).
// Everything is put in as text, never as HTML.
import { hoverTooltip } from "@codemirror/view";
import { t } from "/static/i18n.js";

/** The word (a letter and its number) at column `i` of a line's text, outside comments; null if none. */
export function wordAt(text, i) {
  let depth = 0;
  for (let k = 0; k < i && k < text.length; k++) {
    if (text[k] === ";") return null; // the rest of the line is a comment
    if (text[k] === "(") depth++;
    else if (text[k] === ")") depth = Math.max(0, depth - 1);
  }
  if (depth > 0) return null;
  const re = /[A-Za-z][+-]?(\d+\.?\d*|\.\d+)?/g;
  for (let m = re.exec(text); m; m = re.exec(text)) {
    if (m.index <= i && i < m.index + m[0].length) return { from: m.index, to: m.index + m[0].length, word: m[0] };
    if (m.index > i) break;
  }
  return null;
}

function row(box, label, value) {
  if (value === null || value === undefined || value === "") return;
  const div = document.createElement("div");
  const b = document.createElement("b");
  b.textContent = label + ": ";
  div.append(b, value);
  box.appendChild(div);
}

const num = (v) => (v === null || v === undefined ? null : String(Math.round(v * 1000) / 1000));

/** The tooltip's content for an answer of /api/hover. */
export function hoverContent(h) {
  const dom = document.createElement("div");
  dom.className = "gc-hover";
  if (h.function) {
    const f = document.createElement("div");
    f.className = "function";
    const b = document.createElement("b");
    b.textContent = h.function.code;
    f.append(b, " — ", h.function.unknown ? t.hoverUnknown(h.function.control) : h.function.text);
    if (!h.function.unknown && h.function.group !== undefined) {
      const g = document.createElement("span");
      g.className = "group";
      g.textContent = h.function.group === 0 ? ` (${t.oneShot})` : ` (${t.group} ${h.function.group})`;
      f.appendChild(g);
    }
    dom.appendChild(f);
  }
  const s = h.state;
  if (!s) {
    const n = document.createElement("div");
    n.className = "note";
    n.textContent = t.hoverNoBlock;
    dom.appendChild(n);
    return dom;
  }
  const head = document.createElement("div");
  head.className = "head";
  head.textContent = s.accepted ? t.hoverAfter : t.hoverRejected;
  dom.appendChild(head);
  const box = document.createElement("div");
  box.className = "state";
  dom.appendChild(box);
  row(box, t.units, `${s.unitsG || ""} ${s.units === "inch" ? t.inch : "mm"}`.trim());
  row(box, t.motion, [s.motion, s.incremental ? t.incremental : t.absolute].filter(Boolean).join(", "));
  row(box, t.feed, `${s.feedG || ""} ${s.feedPerRev ? t.perRev : t.perMin}` + (s.feed !== null ? `, F${num(s.feed)}` : ""));
  let spindle = s.spindleG ? s.spindleG + " " : "";
  if (s.css) {
    spindle += t.css(num(s.surfaceSpeed));
    if (s.blockRpm !== undefined) spindle += " → " + t.rpmAt(num(s.blockRpm), s.at ? num(s.at.x) : "?");
  } else if (s.rpm !== null) {
    spindle += `${num(s.rpm)} ${t.rpm}`;
  }
  if (s.rpmClamp !== null) spindle += ` (${t.clamp} ${num(s.rpmClamp)})`;
  row(box, t.spindle, spindle.trim());
  row(box, t.workOffset, s.workOffset + (s.workOffsetMm ? ` (${t.machineMm}: X${num(s.workOffsetMm.x)} Z${num(s.workOffsetMm.z)})` : ""));
  row(box, t.tool, `T${s.tool}, ${t.offset} ${s.toolOffset}` + (s.toolOffsetMm ? ` (X${num(s.toolOffsetMm.x)} Z${num(s.toolOffsetMm.z)} mm)` : ""));
  row(box, t.nose, s.nose);
  if (s.at) row(box, t.at, `X${num(s.at.x)} Z${num(s.at.z)}`);
  if (s.runs > 1) {
    const n = document.createElement("div");
    n.className = "note";
    n.textContent = t.hoverRuns(s.runs);
    dom.appendChild(n);
  }
  return dom;
}

/**
 * The CodeMirror extension: `ask(line, word)` calls the studio for the program as it is in the editor;
 * null when there is no program open.
 */
export function gcodeHover(ask) {
  return hoverTooltip(async (view, pos) => {
    const line = view.state.doc.lineAt(pos);
    const w = wordAt(line.text, pos - line.from);
    if (!w) return null;
    let h;
    try {
      h = await ask(line.number, w.word);
    } catch (e) {
      return null;
    }
    if (!h) return null;
    return { pos: line.from + w.from, end: line.from + w.to, above: true, create: () => ({ dom: hoverContent(h) }) };
  }, { hoverTime: 350 });
}
