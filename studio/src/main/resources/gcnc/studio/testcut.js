// The test cut after a run (docs/studio.md, "Test cut"): per tool offset the program uses, what was measured
// against what the program cuts (X as the program writes it, Z). POST /api/wear/cut computes the wear as
// `gcnc offsets wear` does (gcnc.TestCut, the same code), holds it to wear.max_step and wear.max_total,
// re-verifies the program with it (the simulator runs again) and saves the wear.N line atomically; a refusal
// says which limit or which new finding, and nothing is written. The next Arm's pre-flight names the wear.
import { t } from "/static/i18n.js";

const $ = (id) => document.getElementById(id);
const two = (n) => (n < 10 ? "0" + n : String(n));

function el(tag, text, cls) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (cls) e.className = cls;
  return e;
}

/** The form: `api(endpoint, body)` calls the studio, `program()` names the open program, `status(text, kind)`. */
export function testCutForm({ api, program, status }) {
  const box = $("testcut");

  function field(form, id, label, placeholder) {
    const l = el("label");
    l.appendChild(el("span", label + " "));
    const i = el("input");
    i.id = id;
    i.size = 9;
    i.placeholder = placeholder;
    i.inputMode = "decimal";
    l.appendChild(i);
    form.appendChild(l);
    return i;
  }

  function toolForm(name, f, tool) {
    const form = el("form", undefined, "wearform");
    const n = tool.offset;
    form.id = `wear-${n}`;
    form.dataset.offset = n;
    const head = el("div", t.wearTool(`T${two(n)}`, tool.wear), "head");
    form.appendChild(head);
    const x = f.diameter ? t.xDiameter : t.xRadius;
    const mx = field(form, `wear-${n}-mx`, `${x} ${t.measured}`, f.units === "in" ? "1.4980" : "25.37");
    const px = field(form, `wear-${n}-px`, t.programmed, f.units === "in" ? "1.5000" : "25.40");
    form.appendChild(el("br"));
    const mz = field(form, `wear-${n}-mz`, `Z ${t.measured}`, f.units === "in" ? "-1.0020" : "-20.05");
    const pz = field(form, `wear-${n}-pz`, t.programmed, f.units === "in" ? "-1.0000" : "-20.");
    const save = el("button", t.wearSave);
    save.type = "submit";
    save.id = `wear-${n}-save`;
    form.appendChild(save);
    const result = el("div", undefined, "wearresult");
    result.id = `wear-${n}-result`;
    form.appendChild(result);
    form.addEventListener("submit", async (ev) => {
      ev.preventDefault();
      save.disabled = true;
      form.dataset.state = "saving";
      result.replaceChildren(el("div", t.wearVerifying));
      try {
        const r = await api("wear/cut", { name, offset: n, measuredX: mx.value, programmedX: px.value,
          measuredZ: mz.value, programmedZ: pz.value });
        result.replaceChildren();
        if (r.saved) {
          for (const c of r.changes) result.appendChild(el("div", t.wearChange(c, r.wearUnit)));
          result.appendChild(el("div", t.wearSaved(r.wear, r.file, r.errors, r.findings), "ok"));
          head.textContent = t.wearTool(`T${two(n)}`, r.wear);
          form.dataset.state = "saved";
          status(t.wearSaved(r.wear, r.file, r.errors, r.findings), "ok");
        } else {
          result.appendChild(el("div", t.wearRefused(r.file, r.line, r.message), "bad"));
          form.dataset.state = "refused";
          status(t.wearNotSaved, "bad");
        }
      } catch (e) {
        result.replaceChildren(el("div", e.message, "bad"));
        form.dataset.state = "refused";
        status(e.message, "bad");
      }
      save.disabled = false;
    });
    return form;
  }

  /** Opens the form for the open program: its tool offsets and the wear of each. */
  async function open() {
    const name = program();
    if (!name) return;
    box.hidden = false;
    box.dataset.state = "loading";
    box.replaceChildren(el("h3", t.testCutTitle));
    let f;
    try {
      f = await api("wear", { name });
    } catch (e) {
      box.appendChild(el("div", e.message, "bad"));
      box.dataset.state = "error";
      return;
    }
    box.appendChild(el("div", t.testCutHelp(f.units, f.diameter)));
    if (f.nowhere) {
      box.appendChild(el("div", f.nowhere, "bad"));
      box.dataset.state = "nowhere";
      return;
    }
    box.appendChild(el("div", t.testCutFile(f.file)));
    if (f.tools.length === 0) box.appendChild(el("div", t.testCutNoTools));
    for (const tool of f.tools) box.appendChild(toolForm(name, f, tool));
    box.dataset.state = "ready";
  }

  function close() {
    box.hidden = true;
    box.replaceChildren();
  }

  return { open, close };
}
