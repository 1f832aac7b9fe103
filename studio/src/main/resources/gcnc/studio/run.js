// Run: the thesis's MEMORY mode from the page (docs/studio.md, "Run"). Arm (POST /api/run/arm) compiles the saved
// program as `gcnc run` does and tries it on the chosen controller without motion (`--dry-run`): it shows what
// would move, and only an arm can be started (POST /api/run/start). The run's events, the lines
// `gcnc run --format json` prints, arrive over the page's event stream as "run" events and drive the live display:
// position in program coordinates, the block executing lit in the text and on the path, feed, spindle, progress.
import { t } from "/static/i18n.js";
import { testCutForm } from "/static/testcut.js";

const $ = (id) => document.getElementById(id);

const fmt = (v, d = 3) => (v === null || v === undefined ? "—" : Number(v).toFixed(d).replace(/\.?0+$/, "") || "0");

function clock(sec) {
  if (sec === null || sec === undefined) return "—";
  const s = Math.max(0, Math.round(sec));
  return `${Math.floor(s / 3600)}:${String(Math.floor(s / 60) % 60).padStart(2, "0")}:${String(s % 60).padStart(2, "0")}`;
}

/**
 * The Run panel. `api(endpoint, body)` calls the studio; `program()` gives the open program's name (or null);
 * `saveFirst()` saves unsaved changes (false when that failed); `showLine(line)` lights the executing block in
 * the text and on the path (null: none); `tool(x, z)` puts the tool's mark on the path; `goTo(line)` moves the
 * cursor; `problems(report)` fills the error list; `status(text, kind)` the status line.
 */
export function runPanel({ api, program, saveFirst, showLine, tool, goTo, problems, status }) {
  const panel = $("run");
  let armed = null; // the arm answer that Start may start
  let running = false;
  let step = false;
  let stopWaiting = false; // at a program stop (M00; M01 with the switch on): Start goes on
  let held = false;
  /**
   * Whether the run has ended: its "finished" or "stopped" event came. The run's events and the answer
   * to POST /api/run/start travel apart (the event stream and the request), so a short run can end
   * before its start is answered: nothing after the end may say it is running.
   */
  let over = false;
  /** Whether the run's thread has ended ("run-ended"): nothing of it is going on any more. */
  let ended = false;
  /** The test cut after a run (testcut.js): opened by its button, and by itself when a run ends finished. */
  const testCut = testCutForm({ api, program, status });

  function setState(state, text) {
    $("run-state").dataset.state = state;
    $("run-state").textContent = text;
  }

  function buttons() {
    $("run-arm").disabled = running;
    $("run-start").disabled = running || !armed;
    $("run-hold").disabled = !running || held;
    $("run-resume").disabled = !running || !held;
    $("run-step").disabled = !running || !step;
    $("run-continue").disabled = !running || !stopWaiting;
    $("run-stop").disabled = !running;
    $("run-override").disabled = !running;
    for (const i of panel.querySelectorAll("#runform input, #runform select")) i.disabled = running;
    if ($("run-resumeat")) $("run-resumeat").disabled = running; // the stopped run's thread ends just after its stop
  }

  function target() {
    const kind = panel.querySelector("input[name=target]:checked").value;
    if (kind === "tcp") return { kind, address: $("runtcp").value.trim() };
    if (kind === "serial") return { kind, device: $("runport").value.trim(), baud: Number($("runbaud").value),
      handshake: $("runhandshake").checked ? "hardware" : "none" };
    return { kind };
  }

  function line(parent, text, cls) {
    const div = document.createElement("div");
    div.textContent = text;
    if (cls) div.className = cls;
    parent.appendChild(div);
    return div;
  }

  function finding(parent, f) {
    const div = line(parent, `${f.code} ${f.line > 0 ? t.line + " " + f.line + ": " : ""}${f.message}`, "finding " + f.severity);
    if (f.line > 0) div.addEventListener("click", () => goTo(f.line));
    return div;
  }

  /** The pre-flight as `gcnc run` prints it: what the controller has against what the program needs. */
  function preflight(p) {
    const parts = [p.model, t.pfLines(p.programLinesNeeded, p.programLines), t.pfLabels(p.labelsNeeded, p.labelsLeft),
      t.pfSlots(p.vectorSlotsNeeded, p.vectorSlots), p.limitSwitches ? t.pfLimits(p.limitSwitches) : t.pfLimitsClear,
      t.pfAxes(p.where || p.position.map((v) => fmt(v, 0)).join(","))];
    return t.preflight + ": " + parts.join(", ");
  }

  /** A wear event as `gcnc run` prints it: T01 X+0.040 Z0.000 (diameter, mm). */
  function wear(e) {
    const signed = (v) => (v > 0 ? "+" : "") + Number(v).toFixed(Math.max(3, (String(v).split(".")[1] || "").length));
    return `T${e.offset < 10 ? "0" + e.offset : e.offset} X${signed(e.x)} Z${signed(e.z)} (${e.diameter ? "diameter" : "radius"}, ${e.unit})`;
  }

  /** The arm's answer: what will move, on what, and what pre-flight found; or why nothing is armed. */
  function showArm(a) {
    const box = $("runarmed");
    box.replaceChildren();
    box.className = a.armed ? "armed" : "refused";
    if (a.refused) {
      line(box, t.armRefused(a.refused), "head");
      problems(a.diagnostics);
      return;
    }
    const started = (a.events || []).find((e) => e.event === "started");
    const connected = (a.events || []).find((e) => e.event === "connected");
    line(box, a.armed ? t.armed : t.notArmed, "head");
    line(box, t.armProgram(a.name, started ? started.blocks : "?", a.dmcLines, started ? clock(started.seconds) : "—",
      a.form, a.step, a.resumeAt));
    line(box, t.armController(a.target + (a.address ? ` (${a.address})` : ""), connected ? connected.controller : "—"));
    for (const e of a.events || []) {
      if (e.event === "preflight") line(box, preflight(e));
      if (e.event === "downloaded") line(box, t.downloaded(e.lines));
      if (e.event === "wear") line(box, t.wearInForce(e.file, wear(e)), "wear");
      if (e.event === "finding") finding(box, e);
      if (e.event === "message") line(box, e.text, "message");
    }
  }

  async function arm() {
    const name = program();
    if (!name) { status(t.runNoProgram, "bad"); return; }
    if (!(await saveFirst())) return;
    armed = null;
    buttons();
    $("runstopped").replaceChildren();
    setState("arming", t.arming);
    try {
      const body = { name, target: target(), step: $("runstep").checked, optionalStop: $("runoptional").checked };
      const at = $("runresume").value.trim();
      if (at) body.resumeAt = at;
      const a = await api("run/arm", body);
      showArm(a);
      if (a.armed) {
        armed = a;
        setState("armed", t.armedState);
        status(t.armed, "ok");
      } else {
        setState("idle", t.notArmed);
        status(a.refused || t.notArmed, "bad");
      }
    } catch (e) {
      setState("idle", t.notArmed);
      status(e.message, "bad");
    }
    buttons();
  }

  async function start() {
    if (!armed) return;
    const a = armed;
    armed = null; // an arm moves the machine once
    // cleared before the request: the run's first events may arrive before its answer
    $("runlog").replaceChildren();
    $("runstopped").replaceChildren();
    over = false;
    ended = false;
    try {
      await api("run/start", { arm: a.arm });
      if (!over) status(t.runStarted(a.name), "ok");
      if (!ended) { // still going (its end, when it came first, has said how it ended)
        running = true;
        step = a.step;
        if (!over) { held = false; setState("running", t.runningState); }
      }
    } catch (e) {
      status(e.message, "bad");
    }
    buttons();
  }

  async function command(endpoint, body) {
    try {
      await api("run/" + endpoint, body || {});
    } catch (e) {
      status(e.message, "bad");
    }
  }

  /** The live display from a status event. */
  function display(s) {
    $("dro-x").textContent = s.program ? fmt(s.program[0]) : "—";
    $("dro-z").textContent = s.program ? fmt(s.program[1]) : "—";
    $("dro-counts").textContent = s.counts ? t.counts(s.counts.map((v) => fmt(v, 0)).join(", ")) : "";
    $("dro-block").textContent = s.line > 0 ? (s.number ? `N${s.number} · ` : "") + `${t.line} ${s.line}` + (s.file ? ` (${s.file})` : "") : "—";
    $("dro").dataset.line = s.line;
    $("dro").dataset.polls = String(Number($("dro").dataset.polls || 0) + 1);
    $("dro-feed").textContent = s.feed === null ? "—" : `F${fmt(s.feed)} ${s.perRev ? "/rev" : "/min"}`;
    $("dro-spindle").textContent = (s.rpm === null ? "S —" : `S${fmt(s.rpm, 0)}`) + " " + (s.spindle ? t.spindleDir[s.spindle] : "");
    $("dro-progress").value = s.progress || 0;
    $("dro-left").textContent = `${Math.round(100 * (s.progress || 0))}% · ${t.left(clock(s.secondsLeft))}`
      + (s.override !== 1 && s.override !== null ? ` · ${t.override} ${Math.round(100 * s.override)}%` : "");
    if (s.program && !s.file) tool(s.program[0], s.program[1]);
    if (s.held !== held) { held = s.held; buttons(); }
    if (running && !over) setState(held ? "held" : "running", held ? t.heldState : t.runningState);
  }

  function onEvent(e) {
    const log = $("runlog");
    switch (e.event) {
      case "connected": line(log, t.connected(e.link, e.controller)); break;
      case "preflight": line(log, preflight(e)); break;
      case "wear": line(log, t.wearInForce(e.file, wear(e)), "wear"); break;
      case "started":
        line(log, t.startedLine(e.blocks, e.lines, clock(e.seconds), e.resumeAt));
        running = true; step = e.step; over = false; ended = false;
        break;
      case "downloaded": if (!step) line(log, t.downloaded(e.lines)); break;
      case "block": showLine(e.line); break;
      case "step-wait":
        showLine(e.line);
        $("dro").dataset.line = e.line;
        setState("step", t.stepWait((e.number ? `N${e.number} · ` : "") + `${t.line} ${e.line}`));
        break;
      case "program-stop":
        showLine(e.line);
        stopWaiting = true;
        line(log, t.programStop(e.line, e.comment), "message");
        setState("stop", t.programStopState((e.number ? `N${e.number} · ` : "") + `${t.line} ${e.line}`, e.comment));
        buttons();
        break;
      case "program-stop-continued":
        stopWaiting = false;
        setState("running", t.runningState);
        buttons();
        break;
      case "status": display(e); break;
      case "hold":
        held = e.held;
        if (!over) setState(held ? "held" : "running", held ? t.heldState : t.runningState);
        buttons();
        break;
      case "finding": finding(log, e); break;
      case "message": line(log, e.text, "message"); break;
      case "stopped": stopped(e); break;
      case "finished":
        over = true;
        setState("finished", t.finished(clock(e.seconds)));
        $("dro-progress").value = 1;
        testCut.open();
        break;
      case "run-ended":
        running = false;
        held = false;
        ended = true;
        if (e.status === 2 && $("run-state").dataset.state !== "stopped") setState("idle", t.notStarted);
        buttons();
        break;
      default: break;
    }
  }

  /** A stop: where exactly, and the resume (a button that arms it, and the command line that does the same). */
  function stopped(e) {
    over = true;
    setState("stopped", t.stoppedState(e.reason));
    const box = $("runstopped");
    box.replaceChildren();
    line(box, t.stoppedAt(e.completed, e.executing), "head");
    if (e.where) line(box, e.wherePolled ? t.axesLastSeen(e.where) : t.axesAt(e.where));
    if (e.resumeAt) {
      const b = document.createElement("button");
      b.id = "run-resumeat";
      b.textContent = t.resumeAtButton(e.resumeAt);
      b.addEventListener("click", () => {
        $("runresume").value = e.resumeAt;
        arm();
      });
      box.appendChild(b);
      buttons();
      const code = document.createElement("code");
      code.textContent = e.resume;
      box.appendChild(code);
    }
    if (e.executing > 0) showLine(e.executing);
  }

  function open() {
    panel.hidden = false;
    document.body.classList.add("runscreen");
  }

  function close() {
    panel.hidden = true;
    document.body.classList.remove("runscreen");
  }

  $("run-open").addEventListener("click", () => (panel.hidden ? open() : close()));
  $("run-close").addEventListener("click", close);
  $("run-arm").addEventListener("click", arm);
  $("run-start").addEventListener("click", start);
  $("run-hold").addEventListener("click", () => command("hold"));
  $("run-resume").addEventListener("click", () => command("resume"));
  $("run-step").addEventListener("click", () => { if (!over) setState("running", t.runningState); command("step"); });
  $("run-continue").addEventListener("click", () => command("continue"));
  $("run-stop").addEventListener("click", () => command("stop"));
  $("run-testcut").addEventListener("click", () => testCut.open());
  $("run-override").addEventListener("change", (e) => command("override", { percent: Number(e.target.value) }));
  $("run-override").addEventListener("input", (e) => { $("run-overridevalue").textContent = `${e.target.value}%`; });
  setState("idle", t.idleState);
  buttons();

  return {
    /** The page's event stream: a run's events come as "run" events. */
    attach(events) {
      events.addEventListener("run", (m) => onEvent(JSON.parse(m.data)));
    },
    /** Where the Run screen stands when the page opens (a run may be going on already). */
    async restore() {
      const s = await api("run");
      if (s.state === "running") {
        open();
        running = true;
        step = !!s.step;
        held = !!s.held;
        stopWaiting = !!s.stopWaiting;
        for (const e of s.events) onEvent(e);
        if (s.status) display(s.status);
      }
      buttons();
    },
  };
}
