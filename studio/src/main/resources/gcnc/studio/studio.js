// gcnc studio's page: the editor (CodeMirror 6), the error list, the tool path and the Galil DMC, all linked
// by G-code line. Everything it knows comes from the studio's JSON API (docs/studio.md), which runs the same
// gcnc.Session as the command line.
import { EditorView, Decoration, keymap, lineNumbers, highlightActiveLine, highlightActiveLineGutter, drawSelection } from "@codemirror/view";
import { EditorState, StateEffect, StateField } from "@codemirror/state";
import { syntaxHighlighting, defaultHighlightStyle } from "@codemirror/language";
import { history as undoHistory, defaultKeymap, historyKeymap } from "@codemirror/commands";
import { searchKeymap } from "@codemirror/search";
import { linter, lintGutter, lintKeymap, setDiagnostics } from "@codemirror/lint";
import { gcode } from "/static/gcode-mode.js";
import { drawProfile } from "/static/profile.js";
import { t, translatePage } from "/static/i18n.js";
import { gcodeHover } from "/static/hover.js";
import { configure } from "/static/configure.js";
import { runPanel } from "/static/run.js";

const params = new URLSearchParams(location.search);
const token = params.get("token") || "";
const $ = (id) => document.getElementById(id);

/** The open program: its name, the version the server gave (null for a new file) and the text saved. */
const current = { name: null, version: null, saved: "" };
let lightPath = () => 0;
let dmcBySource = new Map();
let simulateTimer = null;
let simulateSeq = 0;
/** The simulator's findings of the last simulation: kept in the error list while the next one runs. */
let simFindings = [];
/** The open program's units ("in", "mm") as its last simulation found them (its first move's), else null. */
let programUnits = null;

/** One API call; an answer that is not 2xx throws its {"error"} message. */
async function api(endpoint, body) {
  const init = { headers: { "X-Gcnc-Token": token } };
  if (body !== undefined) {
    init.method = "POST";
    init.headers["Content-Type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  let res;
  try {
    res = await fetch("/api/" + endpoint, init);
  } catch (e) {
    throw Object.assign(new Error(t.offline), { status: 0 });
  }
  const json = await res.json().catch(() => ({ error: res.statusText }));
  if (!res.ok) throw Object.assign(new Error(json.error || res.statusText), { status: res.status });
  return json;
}

/**
 * A write the server answers with 409 when it would replace a file it was not told to (a save over a
 * changed file, a profile saved under a name that exists): asked again with force once the user
 * confirms overwriting {@code shown}; any other failure throws.
 */
async function apiOverwriting(endpoint, body, shown) {
  try {
    return await api(endpoint, body);
  } catch (e) {
    if (e.status !== 409 || !confirm(t.overwrite(shown))) throw e;
    return api(endpoint, { ...body, force: true });
  }
}

function status(text, kind) {
  const s = $("status");
  s.textContent = text;
  s.className = kind || "";
}

// ---- the editor ---------------------------------------------------------------------------------------

/** gcnc's diagnostics for the text, as CodeMirror's; the error list is filled from the same answer. */
async function lint(view) {
  if (!current.name) return [];
  const text = view.state.doc.toString();
  let report;
  try {
    report = await api("check", { name: current.name, text });
  } catch (e) {
    status(e.message, "bad");
    return [];
  }
  if (view.state.doc.toString() !== text) return []; // typed on meanwhile: the next check will come
  showProblems(report, simFindings);
  scheduleSimulate();
  return cmDiagnostics(view, report.diagnostics);
}

/** gcnc's diagnostics as CodeMirror's: each underlined at its span on its line. */
function cmDiagnostics(view, diagnostics) {
  return diagnostics.map((d) => {
    const line = view.state.doc.line(Math.min(Math.max(d.line, 1), view.state.doc.lines));
    const from = Math.min(line.from + Math.max(d.column, 1) - 1, line.to);
    let to = d.endColumn ? Math.min(line.from + d.endColumn - 1, line.to) : from;
    if (to <= from) to = Math.min(line.to, from + 1);
    // a finding the program's waiver accepts (GCNC ALLOW) is shown as information, with the waiver's reason
    return { from, to: Math.max(to, from), severity: d.waived ? "info" : d.severity === "error" ? "error" : "warning",
      message: `${d.code} ${shownMessage(d)}`, source: d.simulator ? "gcnc simulator" : "gcnc" };
  });
}

/** Another machine profile is in use (Configure saved one): the text is judged again as it is. */
const profileChanged = StateEffect.define();

/** The block a run executes (Run): its line lit in the text, apart from the cursor. null: none. */
const runningLine = StateEffect.define();
const running = StateField.define({
  create: () => Decoration.none,
  update(lit, tr) {
    lit = lit.map(tr.changes);
    for (const e of tr.effects) {
      if (!e.is(runningLine)) continue;
      lit = e.value >= 1 && e.value <= tr.state.doc.lines
        ? Decoration.set([Decoration.line({ class: "cm-running" }).range(tr.state.doc.line(e.value).from)])
        : Decoration.none;
    }
    return lit;
  },
  provide: (f) => EditorView.decorations.from(f),
});
let runningAt = null;

/** The run's executing block lit in the text (scrolled into view) and on the path. */
function showRunning(line) {
  runningAt = line;
  const ok = line >= 1 && line <= view.state.doc.lines;
  view.dispatch({ effects: ok ? [runningLine.of(line), EditorView.scrollIntoView(view.state.doc.line(line).from, { y: "center" })]
    : [runningLine.of(null)] });
  lightPath.running && lightPath.running(ok ? line : null);
}

const view = new EditorView({
  parent: $("editor"),
  state: EditorState.create({ doc: "", extensions: extensions() }),
});

function extensions() {
  return [
    lineNumbers(), highlightActiveLineGutter(), undoHistory(), drawSelection(), highlightActiveLine(),
    syntaxHighlighting(defaultHighlightStyle, { fallback: true }), gcode, running,
    lintGutter(), linter(lint, { delay: 250, needsRefresh: (u) => u.transactions.some((tr) => tr.effects.some((e) => e.is(profileChanged))) }),
    gcodeHover((line, word) => current.name ? api("hover", { name: current.name, text: view.state.doc.toString(), line, word }) : null),
    keymap.of([...defaultKeymap, ...historyKeymap, ...searchKeymap, ...lintKeymap,
      { key: "Mod-s", preventDefault: true, run: () => { save(false); return true; } }]),
    EditorView.updateListener.of((u) => {
      if (u.docChanged) dirtyChanged();
      if (u.selectionSet || u.docChanged) cursorMoved();
    }),
  ];
}

function cursorLine() {
  const head = view.state.selection.main.head;
  const line = view.state.doc.lineAt(head);
  return { line: line.number, column: head - line.from + 1 };
}

/** The block under the cursor: lit on the path and in the DMC. */
function cursorMoved() {
  const c = cursorLine();
  $("cursor").textContent = t.cursor(c.line, c.column);
  $("cursor").dataset.line = c.line;
  lightPath(c.line);
  for (const e of document.querySelectorAll("#dmc .current")) e.classList.remove("current");
  const lit = dmcBySource.get(c.line) || []; // the lines that hold the block's commands, and the commands
  lit.forEach((e) => e.classList.add("current"));
  if (lit.length) lit[0].scrollIntoView({ block: "nearest" });
}

/** Puts the cursor at a line (and column) and shows it: from the error list, the path or the DMC. */
function goTo(line, column, keepFocus) {
  const doc = view.state.doc;
  const l = doc.line(Math.min(Math.max(line, 1), doc.lines));
  const pos = Math.min(l.from + Math.max((column || 1) - 1, 0), l.to);
  view.dispatch({ selection: { anchor: pos }, scrollIntoView: true });
  if (!keepFocus) view.focus();
}

function dirty() {
  return current.name !== null && view.state.doc.toString() !== current.saved;
}

function dirtyChanged() {
  $("name").textContent = (current.name || t.untitled) + (dirty() ? " •" : "");
  $("name").className = dirty() ? "dirty" : "";
}

// ---- the error list -----------------------------------------------------------------------------------

/** A finding's message; a waived one's with the waiver's reason before it ("waived: reason: ..."). */
function shownMessage(d) {
  return d.waived ? `${t.waived}: ${d.waived}: ${d.message}` : d.message;
}

/**
 * The error list: the check's findings and the simulator's alike (a simulation's answer holds both), each a
 * click to its line and, for a simulator's finding, to its place on the path. `pending`: the simulator's
 * findings of the last simulation, listed greyed beside a check's answer until the simulation of the new
 * text answers (a check does not simulate).
 */
let shownProblems = null;

function showProblems(report, pending = []) {
  const body = $("errors").querySelector("tbody");
  const rows = [...report.diagnostics, ...pending.map((d) => ({ ...d, pending: true }))]
    .sort((a, b) => a.line - b.line || a.column - b.column);
  // the same list again (a simulation that found what the check found): the rows stay as they are
  const key = JSON.stringify(rows);
  if (key === shownProblems && body.childElementCount === rows.length) return;
  shownProblems = key;
  body.replaceChildren();
  for (const d of rows) {
    const tr = document.createElement("tr");
    tr.className = (d.waived ? "waived" : d.severity) + (d.simulator ? " simulator" : "") + (d.pending ? " pending" : "");
    tr.dataset.line = d.line;
    tr.dataset.column = d.column;
    tr.dataset.code = d.code;
    for (const v of [d.code, shownMessage(d), d.line, d.column]) {
      const td = document.createElement("td");
      td.textContent = v;
      tr.appendChild(td);
    }
    if (d.pending) tr.title = t.pendingFinding;
    const jump = () => {
      goTo(d.line, d.column);
      if (d.simulator && lightPath.finding) lightPath.finding(d.code, d.line);
    };
    tr.tabIndex = 0; // reachable with Tab; Enter jumps as a click does
    tr.addEventListener("click", jump);
    tr.addEventListener("keydown", (e) => { if (e.key === "Enter") jump(); });
    body.appendChild(tr);
  }
  const errors = report.errors + pending.filter((d) => d.severity === "error").length;
  const warnings = report.warnings + pending.filter((d) => d.severity !== "error").length;
  $("counts").textContent = (errors + warnings === 0 ? "— " + t.noErrors : "— " + t.nErrors(errors, warnings))
    + (report.waived ? ", " + t.nWaived(report.waived) : "") + (pending.length ? " " + t.simulating : "");
}

// ---- tool path and DMC --------------------------------------------------------------------------------

function scheduleSimulate() {
  clearTimeout(simulateTimer);
  simulateTimer = setTimeout(simulate, 150);
}

/**
 * Simulates the text as it is now. One simulation at a time (a long program takes a good part of a
 * second): an edit meanwhile asks for one more, run when this one is done, with the text as it is then.
 */
let simulating = false;
let simulateAgain = false;

async function simulate() {
  if (!current.name) return;
  if (simulating) { simulateAgain = true; return; }
  simulating = true;
  const seq = ++simulateSeq;
  const text = view.state.doc.toString();
  try {
    const r = await api("simulate", { name: current.name, text });
    if (seq === simulateSeq) showSimulation(r, text);
  } catch (e) {
    status(e.message, "bad");
  } finally {
    simulating = false;
    if (simulateAgain) { simulateAgain = false; scheduleSimulate(); }
  }
}

/**
 * The path, the DMC and the summary of a simulation. When the program has an error there is no DMC
 * and no path: the last ones stay, greyed and marked as the last program without errors.
 */
function showSimulation(r, text) {
  const fresh = r.drawing && r.drawing.moves.length > 0;
  const compiled = r.dmc.length > 0; // no error: the DMC of this text
  $("path").classList.toggle("stale", !fresh && $("profile").childElementCount > 0);
  $("galil").classList.toggle("stale", !compiled && $("dmc").childElementCount > 0);
  if (fresh) {
    lightPath = drawProfile($("profile"), r.drawing, pick);
    if (runningAt !== null && lightPath.running) lightPath.running(runningAt);
    $("pathnote").textContent = "";
    scrubBlocks(r.drawing.moves);
  } else {
    $("pathnote").textContent = $("profile").childElementCount > 0 ? t.stalePath : t.noPath;
  }
  if (compiled) showDmc(r.dmc);
  const why = compiled ? "" : noDmc(r.diagnostics);
  $("dmcnote").textContent = why && $("dmc").childElementCount > 0 ? `${why}. ${t.staleDmc}` : why;
  // the whole truth: the check's findings and the simulator's, in the list, the count and the text
  simFindings = r.diagnostics.diagnostics.filter((d) => d.simulator);
  const terms = r.summary && (r.summary.program || r.summary.part);
  if (terms) programUnits = terms.unit;
  showProblems(r.diagnostics);
  if (view.state.doc.toString() === text) view.dispatch(setDiagnostics(view.state, cmDiagnostics(view, r.diagnostics.diagnostics)));
  showSummary(r, null, why);
  cursorMoved();
}

/** Why a simulation's answer has no DMC: its errors (and where the first is); the check's stop the translation there. */
function noDmc(report) {
  const errors = report.diagnostics.filter((d) => d.severity === "error");
  if (errors.length === 0) return t.noDmcYet;
  const first = errors[0].line;
  return errors.every((d) => d.simulator) ? t.noDmcSimulator(errors.length, first) : t.noDmcErrors(errors.length, first);
}

/** A click on a move: its line, in this program or in the called program it is written in. */
async function pick(line, file, elsewhere) {
  if (elsewhere) { status(t.elsewhere(line), "bad"); return; }
  if (!file || file === current.name) { goTo(line, 1); return; }
  await open(file);
  if (current.name === file) goTo(line, 1);
}

// ---- scrub: the stock after a block ---------------------------------------------------------------------

/** The blocks the slider steps through: each G-code line that moved the tool, in the order it first did. */
let scrubLines = [];
let scrubTimer = null;
let scrubSeq = 0;

function scrubBlocks(moves) {
  const was = scrubLines[$("scrub").value - 1];
  scrubLines = [];
  const seen = new Set();
  for (const m of moves) {
    if (!seen.has(m.line)) { seen.add(m.line); scrubLines.push(m.line); }
  }
  const slider = $("scrub");
  slider.max = String(scrubLines.length);
  const at = was === undefined ? -1 : scrubLines.indexOf(was);
  slider.value = String(at + 1);
  scrubbed();
}

/** The slider moved: 0 shows the finished part; k the stock after the k-th block. */
function scrubbed() {
  clearTimeout(scrubTimer);
  const k = Number($("scrub").value);
  if (k === 0) {
    scrubSeq++;
    lightPath.scrub && lightPath.scrub(null);
    $("scrubinfo").textContent = t.scrubEnd;
    $("scrubinfo").dataset.line = "";
    return;
  }
  const line = scrubLines[k - 1];
  $("scrubinfo").textContent = t.scrubAt(k, scrubLines.length, line) + " …";
  scrubTimer = setTimeout(() => showStock(line), 120);
}

async function showStock(line) {
  if (!current.name) return;
  const my = ++scrubSeq;
  let s;
  try {
    s = await api("stock", { name: current.name, text: view.state.doc.toString(), line });
  } catch (e) {
    status(e.message, "bad");
    return;
  }
  if (my !== scrubSeq) return;
  lightPath.scrub && lightPath.scrub(s);
  const k = scrubLines.indexOf(line) + 1;
  $("scrubinfo").textContent = t.scrubAt(k, scrubLines.length, line) + (s.found && s.tool ? ` · T${s.tool}` : "");
  $("scrubinfo").dataset.line = String(line);
  goTo(line, 1, true);
}

/**
 * The DMC as the file holds it, a packed line per item; each command of a line is a span with its
 * G-code line, so the cursor on a block lights its commands (and their lines), and a click on a
 * command goes to its block.
 */
function showDmc(lines) {
  const ol = $("dmc");
  ol.replaceChildren();
  dmcBySource = new Map();
  for (const l of lines) {
    const li = document.createElement("li");
    li.dataset.source = l.line;
    l.parts.forEach((p, k) => {
      if (k > 0) li.append(";");
      const span = document.createElement("span");
      span.textContent = p.text;
      span.dataset.source = p.line;
      if (p.file) span.dataset.file = p.file;
      if (p.line > 0) span.addEventListener("click", () => pick(p.line, p.file, p.elsewhere));
      li.appendChild(span);
      if (p.file || p.elsewhere) return; // a called program's line: not this file's cursor's
      if (!dmcBySource.has(p.line)) dmcBySource.set(p.line, []);
      const lit = dmcBySource.get(p.line);
      if (!lit.includes(li)) lit.push(li);
      lit.push(span);
    });
    ol.appendChild(li);
  }
}

function showSummary(r, compiled, noDmcWhy) {
  const s = r.summary;
  const box = $("summary");
  box.replaceChildren();
  const row = (k, v) => {
    const div = document.createElement("div");
    const b = document.createElement("b");
    b.textContent = k + ": ";
    div.append(b, v);
    box.appendChild(div);
  };
  if (compiled) row(t.compile, compiled);
  row(t.blocks, String(r.blocks));
  if (r.dmc) row(t.dmcLines, noDmcWhy || String(r.dmc.length));
  else if (r.dmcLines !== undefined) row(t.dmcLines, String(r.dmcLines));
  if (s) {
    if (s.cycleSeconds !== null) row(t.cycle, formatSeconds(s.cycleSeconds));
    // in the program's terms first, as gcnc simulate prints them: the part (feed moves), every move, the machine
    if (s.part) row(t.partEnvelope, programEnvelope(s.part) + " " + t.feedMoves);
    if (s.program) row(t.programEnvelope, programEnvelope(s.program));
    const e = s.machineExtents;
    if (e.xMinMm !== null) row(t.extents, `X ${e.xMinMm.toFixed(2)} … ${e.xMaxMm.toFixed(2)}, Z ${e.zMinMm.toFixed(2)} … ${e.zMaxMm.toFixed(2)}`);
  }
}

/** An envelope as the program writes coordinates: X (diameter or radius), Z from work zero, in its unit. */
function programEnvelope(p) {
  const d = p.unit === "in" ? 4 : 3;
  return `X ${p.xMin.toFixed(d)} … ${p.xMax.toFixed(d)} (${p.diameter ? t.diameter : t.radius}), `
    + `Z ${p.zMin.toFixed(d)} … ${p.zMax.toFixed(d)} ${p.unit} ${t.fromWorkZero}`;
}

function formatSeconds(sec) {
  const m = Math.floor(sec / 60);
  return (m > 0 ? `${m} min ` : "") + `${(sec - 60 * m).toFixed(1)} s`;
}

// ---- files --------------------------------------------------------------------------------------------

async function listFiles(files) {
  if (!files) files = (await api("files")).files;
  const sel = $("files");
  sel.replaceChildren();
  const none = document.createElement("option");
  none.value = "";
  none.textContent = files.length ? "—" : t.noProgram;
  sel.appendChild(none);
  for (const f of files) {
    const o = document.createElement("option");
    o.value = o.textContent = f.name;
    sel.appendChild(o);
  }
  if (current.name && !files.some((f) => f.name === current.name)) {
    const o = document.createElement("option");
    o.value = o.textContent = current.name;
    sel.appendChild(o);
  }
  sel.value = current.name || "";
}

function load(name, text, version) {
  current.name = name;
  current.version = version;
  current.saved = text;
  view.setState(EditorState.create({ doc: text, extensions: extensions() }));
  $("profile").replaceChildren(); // another program: nothing of the last one's path or DMC stays
  $("dmc").replaceChildren();
  $("dmcnote").textContent = t.noDmcYet;
  simFindings = [];
  programUnits = null;
  lightPath = () => 0;
  scrubLines = [];
  $("scrub").max = "0";
  $("scrub").value = "0";
  dmcBySource = new Map();
  $("files").value = name;
  dirtyChanged();
  cursorMoved();
  const u = new URL(location.href);
  u.searchParams.set("file", name);
  history.replaceState(null, "", u);
}

async function open(name) {
  if (dirty() && !confirm(t.discard)) {
    $("files").value = current.name || "";
    return;
  }
  try {
    const p = await api("file?name=" + encodeURIComponent(name));
    load(p.name, p.text, p.version);
    status(t.opened(p.name), "ok");
  } catch (e) {
    status(e.message, "bad");
  }
}

/** Saves the text; on any failure the text stays in the editor, unsaved, and the reason is shown. */
async function save(asNew, name) {
  if (!current.name) return false;
  const target = name || current.name;
  const text = view.state.doc.toString();
  const body = { name: target, text, version: asNew ? null : current.version };
  try {
    const p = await apiOverwriting("save", body, target);
    current.name = p.name;
    current.version = p.version;
    current.saved = text;
    await listFiles();
    dirtyChanged();
    status(t.saved(p.name), "ok");
    return true;
  } catch (e) {
    status(t.saveFailed(e.message), "bad");
    return false;
  }
}

async function newProgram() {
  if (dirty() && !confirm(t.discard)) return;
  const name = prompt(t.askName, "");
  if (!name) return;
  load(name, "", null);
  current.saved = "\u0000"; // nothing on disk yet: a new program is unsaved until saved
  dirtyChanged();
  await listFiles();
}

async function saveAs() {
  if (!current.name) return;
  const name = prompt(t.askSaveAs, current.name);
  if (!name || name === current.name) return save(false);
  if (await save(true, name)) {
    const u = new URL(location.href);
    u.searchParams.set("file", current.name);
    history.replaceState(null, "", u);
  }
}

async function compile() {
  if (!current.name) return;
  if (dirty() && !(await save(false))) return;
  status(t.compiling, "");
  try {
    const r = await api("compile", { name: current.name });
    showProblems(r.diagnostics);
    if (r.ok) {
      status(t.compiled(r.dmc, r.map), "ok");
      showSummary(r, `${r.dmc}, ${r.map}`);
    } else {
      status(t.compileFailed(t.nErrors(r.diagnostics.errors, r.diagnostics.warnings)), "bad");
    }
  } catch (e) {
    status(e.message, "bad");
  }
}

// ---- start --------------------------------------------------------------------------------------------

translatePage();
$("files").addEventListener("change", (e) => { if (e.target.value) open(e.target.value); });
$("new").addEventListener("click", newProgram);
$("save").addEventListener("click", () => save(false));
$("saveas").addEventListener("click", saveAs);
$("compile").addEventListener("click", compile);
$("scrub").addEventListener("input", scrubbed);
configure({
  api,
  apiOverwriting,
  program: () => (current.name ? { name: current.name, text: view.state.doc.toString() } : null),
  units: () => programUnits,
  goTo: (line) => goTo(line, 1),
  status,
  saved: async () => {
    // every check, simulation and compile now uses the saved profile: judge the program again
    await showInfo();
    view.dispatch({ effects: profileChanged.of(null) });
    scheduleSimulate();
  },
});

const run = runPanel({
  api,
  program: () => current.name,
  saveFirst: async () => !dirty() || save(false),
  showLine: showRunning,
  tool: (x, z) => lightPath.tool && lightPath.tool(x, z),
  goTo: (line) => goTo(line, 1),
  problems: showProblems,
  status,
});

async function showInfo() {
  const info = await api("info");
  $("where").textContent = `${info.folder} · ${info.profileFile || info.machine} · ${info.control}`;
}
window.addEventListener("beforeunload", (e) => {
  if (dirty()) { e.preventDefault(); e.returnValue = ""; }
});

(async () => {
  try {
    await showInfo();
    await listFiles();
    const events = new EventSource("/api/events?token=" + encodeURIComponent(token));
    events.addEventListener("files", (e) => listFiles(JSON.parse(e.data).files));
    run.attach(events);
    if (params.get("file")) await open(params.get("file"));
    await run.restore();
    document.body.dataset.ready = "true";
  } catch (e) {
    status(e.message, "bad");
  }
})();
