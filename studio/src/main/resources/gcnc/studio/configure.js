// Configure: the machine profile's travel, work offsets, tool offsets and tool geometry as a form (GET /api/profile),
// in the open program's terms (its units, X as it writes X), the profile's own key and value beside each field.
// Each change is sent to POST /api/profile/impact with the open program: the server reads the edited profile as
// gcnc's loader does (a refusal is shown at its field) and says which lines become errors or collisions with it and
// which stop being, before anything is saved. Save as writes NAME.machine in the studio's folder (POST /api/profile/save)
// and the studio uses it from then on.
import { t } from "/static/i18n.js";

const $ = (id) => document.getElementById(id);

/** How many inputs a key's value is written with: a pair (min, max or x, z or radius, tip), or one text. */
const parts = (key) => (key.startsWith("sim.tool.") ? 1 : 2);

/** Whether a field is shown in the program's terms (the server converts it both ways), else as the file writes it. */
const inProgramTerms = (field) => field.program !== undefined;

/** The text a field shows: the program's terms when the server gives them. */
const shownValue = (field) => (inProgramTerms(field) ? field.program : field.value);

function inputsFor(field) {
  const n = parts(field.key);
  const shown = shownValue(field);
  const placeholder = inProgramTerms(field) ? field.programPlaceholder : field.placeholder;
  const values = shown === "" ? [] : n === 1 ? [shown] : shown.split(",").map((v) => v.trim());
  const holders = placeholder === "" ? [] : n === 1 ? [placeholder] : placeholder.split(",").map((v) => v.trim());
  if (values.length > n) values.splice(n - 1, values.length, values.slice(n - 1).join(", "));
  const cell = document.createElement("td");
  const inputs = [];
  for (let i = 0; i < n; i++) {
    const input = document.createElement("input");
    input.type = "text";
    input.value = values[i] || "";
    input.placeholder = holders[i] || "";
    input.dataset.key = field.key;
    input.dataset.part = i;
    input.dataset.terms = inProgramTerms(field) ? "program" : "file";
    input.size = n === 1 ? 14 : 11;
    input.setAttribute("aria-label", `${field.key} ${i + 1}`);
    cell.appendChild(input);
    inputs.push(input);
  }
  return { cell, inputs };
}

/**
 * The Configure panel. `program()` gives {name, text} of the open program (or null); `goTo(line)` moves the
 * cursor; `saved(answer)` is called after a save; `apiOverwriting` is the studio's write that asks before
 * replacing a file (409).
 */
export function configure({ api, apiOverwriting, program, units, goTo, saved, status }) {
  const panel = $("configure");
  const fields = new Map(); // key -> {inputs, initial, program, file}
  let timer = null;
  let seq = 0;
  let formUnits = null; // the units the form is in ("in", "mm"), as the server gave them

  function value(key) {
    const f = fields.get(key);
    const vs = f.inputs.map((i) => i.value.trim());
    return vs.every((v) => v === "") ? "" : vs.join(", ");
  }

  /**
   * The keys changed since the form was filled, with their new values: `program` those typed in the
   * program's terms (the server converts them to the file's), `values` those in the file's own.
   */
  function changes() {
    const out = { values: {}, program: {}, units: formUnits };
    for (const [key, f] of fields) {
      const v = value(key);
      if (v !== f.initial) (f.program ? out.program : out.values)[key] = v;
    }
    return out;
  }

  const changed = (c) => Object.keys(c.values).length + Object.keys(c.program).length > 0;

  function table(caption, rows, labels) {
    const section = document.createElement("section");
    const h = document.createElement("h3");
    h.textContent = caption;
    section.appendChild(h);
    const tbl = document.createElement("table");
    const head = document.createElement("tr");
    for (const l of ["", ...labels, t.profileFileValue]) {
      const th = document.createElement("th");
      th.textContent = l;
      head.appendChild(th);
    }
    tbl.appendChild(head);
    for (const field of rows) {
      const tr = document.createElement("tr");
      tr.dataset.key = field.key;
      const name = document.createElement("td");
      name.textContent = field.key;
      tr.appendChild(name);
      const { cell, inputs } = inputsFor(field);
      tr.appendChild(cell);
      // the profile's own key and value as its file holds them, and what an edit would write there
      const file = document.createElement("td");
      file.className = "filevalue";
      file.textContent = field.value === "" ? `(${field.key} ${t.notInFile})` : `${field.key} = ${field.value}`;
      tr.appendChild(file);
      const err = document.createElement("td");
      err.className = "fielderror";
      tr.appendChild(err);
      tbl.appendChild(tr);
      const shown = shownValue(field);
      const initial = shown === "" ? "" : (parts(field.key) === 1 ? shown : shown.split(",").map((v) => v.trim()).join(", "));
      fields.set(field.key, { inputs, initial, error: err, row: tr, program: inProgramTerms(field), file, fileText: file.textContent });
      inputs.forEach((i) => i.addEventListener("input", schedule));
    }
    section.appendChild(tbl);
    return section;
  }

  async function open() {
    let form;
    try {
      const u = units();
      form = await api("profile" + (u ? "?units=" + encodeURIComponent(u) : ""));
    } catch (e) {
      status(e.message, "bad");
      return;
    }
    fields.clear();
    const body = $("configform");
    body.replaceChildren();
    $("configtitle").textContent = t.configureTitle(form.machine, form.profileFile || form.source);
    panel.dataset.machine = form.machine;
    formUnits = form.units;
    panel.dataset.units = form.units;
    $("confignote").textContent = t.configureNote(form.units, form.diameter, form.offsetsUnit);
    body.appendChild(table(t.travel, form.travel, [t.minMax]));
    body.appendChild(table(t.workOffsets, form.work, [t.xz]));
    body.appendChild(table(t.toolOffsets, form.toolOffsets, [t.xz]));
    body.appendChild(table(t.geometry, form.geometry, [t.geometryValues]));
    $("impact").replaceChildren();
    $("impactnote").textContent = t.impactNone;
    panel.hidden = false;
    document.body.classList.add("configuring");
    panel.dataset.ready = "true";
  }

  function close() {
    panel.hidden = true;
    panel.dataset.ready = "false";
    document.body.classList.remove("configuring");
  }

  function schedule() {
    clearTimeout(timer);
    timer = setTimeout(judge, 350);
  }

  function showError(key, message) {
    for (const [, f] of fields) {
      f.row.classList.remove("invalid");
      f.error.textContent = "";
    }
    if (!message) return;
    const f = key && fields.get(key);
    if (f) {
      f.row.classList.add("invalid");
      f.error.textContent = message;
    }
  }

  /** Beside each edited field, the value its key would have in the file. */
  function showWritten(written) {
    for (const [key, f] of fields) {
      f.file.textContent = key in written ? `${f.fileText} → ${key} = ${written[key] === "" ? t.leftOut : written[key]}` : f.fileText;
      f.file.classList.toggle("edited", key in written);
    }
  }

  function impactList(title, list, kind) {
    const box = $("impact");
    const h = document.createElement("h4");
    h.textContent = `${title} (${list.length})`;
    box.appendChild(h);
    const ul = document.createElement("ul");
    ul.className = kind;
    for (const d of list) {
      const li = document.createElement("li");
      li.dataset.line = d.line;
      li.dataset.code = d.code;
      li.textContent = `${t.line} ${d.line}: ${d.code} ${d.message}`;
      li.tabIndex = 0;
      li.addEventListener("click", () => goTo(d.line));
      ul.appendChild(li);
    }
    box.appendChild(ul);
  }

  /** The edited profile judged by the server; the answer shown if it is still the latest. */
  async function judge() {
    const edits = changes();
    const my = ++seq;
    const p = program();
    const req = { ...edits };
    if (p) Object.assign(req, p);
    $("impactnote").textContent = t.impactRunning;
    let r;
    try {
      r = await api("profile/impact", req);
    } catch (e) {
      if (my === seq) $("impactnote").textContent = e.message;
      return;
    }
    if (my !== seq) return;
    $("impact").replaceChildren();
    panel.dataset.valid = String(r.valid);
    if (!r.valid) {
      showError(r.key, r.error);
      $("impactnote").textContent = t.profileInvalid(r.key, r.error);
      return;
    }
    showError(null, null);
    showWritten(r.written || {});
    if (!changed(edits)) {
      $("impactnote").textContent = t.impactNone;
      return;
    }
    if (!r.became) {
      $("impactnote").textContent = t.impactNoProgram;
      return;
    }
    $("impactnote").textContent = r.became.length + r.gone.length === 0 ? t.impactSame : t.impactHead;
    impactList(t.impactBecame, r.became, "became");
    impactList(t.impactGone, r.gone, "gone");
  }

  async function saveAs() {
    const file = prompt(t.askProfile, (panel.dataset.machine || "machine") + ".machine");
    if (!file) return;
    const body = { file, ...changes() };
    try {
      const r = await apiOverwriting("profile/save", body, file);
      status(t.profileSaved(r.file), "ok");
      await open();
      saved(r);
    } catch (e) {
      status(t.profileNotSaved(e.message), "bad");
    }
  }

  $("configure-open").addEventListener("click", () => (panel.hidden ? open() : close()));
  $("configure-close").addEventListener("click", close);
  $("configure-save").addEventListener("click", saveAs);
  return { open, close };
}
