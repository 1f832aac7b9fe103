package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import gcnc.ModalStates;
import gcnc.Session;
import gcnc.TestCut;
import gcnc.diag.Diagnostic;
import gcnc.diag.Messages;
import gcnc.machine.MachineProfile;
import gcnc.machine.ToolWear;
import gcnc.machine.Units;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.SortedSet;
import java.util.TreeSet;

/**
 * The test-cut form after a run (docs/studio.md, "Test cut"): per tool offset the program uses, what
 * was measured against what the program cuts, in X as the program writes it and in Z. The wear is
 * computed, limited, re-verified and saved by {@link TestCut#cut}, exactly as {@code gcnc offsets wear}
 * does: this class only reads the form and answers JSON. A saved wear is in force from then on
 * ({@link Api} replaces its session), so the next arm's pre-flight names it.
 */
record TestCuts(Workspace workspace, Messages messages) {

    /**
     * POST /api/wear {name}: the tool offsets the saved program selects, each with its wear in force,
     * the program's units, and where a test cut is saved (or why it cannot be).
     */
    JsonObject form(Session session, JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        Path program = Workspace.refusing(() -> workspace.existing(name));
        MachineProfile p = session.profile();
        SortedSet<Integer> offsets = new TreeSet<>();
        Units units = p.units();
        try (Reader in = Session.decode(Files.newInputStream(program))) {
            java.util.Map<Integer, ModalStates.Snapshot> states =
                    ModalStates.of(session.withPrograms(Optional.ofNullable(program.getParent())), in);
            int last = 0;
            for (java.util.Map.Entry<Integer, ModalStates.Snapshot> e : states.entrySet()) {
                int t = e.getValue().state().toolOffset();
                if (t != 0 && p.toolOffset(t).isPresent()) {
                    offsets.add(t);
                }
                if (e.getKey() > last) {
                    last = e.getKey();
                    units = e.getValue().state().units(); // the program's units at its end, as the test cut reads them
                }
            }
        }
        JsonObject o = new JsonObject();
        o.addProperty("name", name);
        o.addProperty("units", units == Units.INCH ? "in" : "mm");
        o.addProperty("diameter", p.diameterX());
        ToolWear wear = p.wear();
        o.addProperty("wearUnit", wear.unit());
        try {
            o.addProperty("file", shown(TestCut.target(session)));
        } catch (TestCut.Refused r) {
            o.addProperty("nowhere", message(r.diagnostic()));
        }
        JsonArray tools = new JsonArray();
        for (int n : offsets) {
            JsonObject t = new JsonObject();
            t.addProperty("offset", n);
            Optional<ToolWear.Wear> w = wear.of(n);
            t.addProperty("x", w.map(ToolWear.Wear::x).orElse(0.0));
            t.addProperty("z", w.map(ToolWear.Wear::z).orElse(0.0));
            t.addProperty("wear", TestCut.describe(wear, n, p));
            tools.add(t);
        }
        o.add("tools", tools);
        return o;
    }

    /** A saved test cut: the answer, and the session with the new wear in force. */
    record Cut(JsonObject answer, Optional<MachineProfile> profile) {
    }

    /**
     * POST /api/wear/cut {name, offset, measuredX?, programmedX?, measuredZ?, programmedZ?}: the test cut of
     * {@link TestCut#cut} on the saved program, each value as the program writes it (X a diameter on a
     * diameter machine). Answers {@code saved} with the change per axis, the wear now in force, the
     * file and the re-verified program's findings; or {@code saved: false} with the refusal's code,
     * file, line and message (nothing was written).
     */
    Cut cut(Session session, JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        int n = Http.integer(req, "offset", 1, 99);
        Path program = Workspace.refusing(() -> workspace.existing(name));
        List<TestCut.Measurement> ms = new ArrayList<>();
        for (TestCut.Axis axis : TestCut.Axis.values()) {
            String measured = Http.string(req, "measured" + axis);
            String programmed = Http.string(req, "programmed" + axis);
            if (blank(measured) && blank(programmed)) {
                continue;
            }
            Optional<TestCut.Measurement> m = blank(measured) || blank(programmed) ? Optional.empty()
                    : TestCut.Measurement.parse(axis + measured.strip(), axis + programmed.strip());
            if (m.isEmpty()) {
                throw new Http.Fail(400, "give " + axis + " as two numbers, measured and programmed, as the program writes"
                        + " them (" + (axis == TestCut.Axis.X ? "25.37 and 25.40" : "-20.05 and -20.") + ")");
            }
            ms.add(m.get());
        }
        if (ms.isEmpty()) {
            throw new Http.Fail(400, "give what was measured and what the program cuts, in X, in Z or both");
        }
        JsonObject o = new JsonObject();
        o.addProperty("name", name);
        o.addProperty("offset", n);
        TestCut.Saved saved;
        try {
            saved = TestCut.cut(session, program, session.simulation(), n, ms, messages);
        } catch (TestCut.Refused r) {
            Diagnostic d = r.diagnostic();
            o.addProperty("saved", false);
            o.addProperty("code", d.code().id());
            o.addProperty("file", shownName(r.path()));
            o.addProperty("line", d.span().line());
            o.addProperty("message", message(d));
            return new Cut(o, Optional.empty());
        }
        MachineProfile p = session.profile().withWear(saved.wear());
        o.addProperty("saved", true);
        JsonArray changes = new JsonArray();
        for (TestCut.Change c : saved.changes()) {
            JsonObject j = new JsonObject();
            j.addProperty("axis", c.measurement().axis().name());
            j.addProperty("programmed", c.measurement().programmedText());
            j.addProperty("measured", c.measurement().measuredText());
            j.addProperty("before", TestCut.signed(c.before()));
            j.addProperty("step", TestCut.signed(c.step()));
            j.addProperty("after", TestCut.signed(c.after()));
            changes.add(j);
        }
        o.add("changes", changes);
        o.addProperty("wear", TestCut.describe(saved.wear(), n, p));
        o.addProperty("wearUnit", saved.wear().unit());
        o.addProperty("file", shown(saved.file()));
        o.addProperty("errors", saved.verified().diagnostics().errorCount());
        o.addProperty("findings", saved.verified().diagnostics().size());
        return new Cut(o, Optional.of(p));
    }

    private String message(Diagnostic d) {
        return d.code().id() + ": " + messages.render(d.code(), d.args());
    }

    /** A file under the studio's folder by its name there; any other by its path. */
    private String shown(Path p) {
        Path abs = p.toAbsolutePath().normalize();
        return abs.startsWith(workspace.root()) ? workspace.name(abs) : abs.toString();
    }

    private String shownName(String path) {
        try {
            return shown(Path.of(path));
        } catch (java.nio.file.InvalidPathException e) {
            return path;
        }
    }

    private static boolean blank(String s) {
        return s == null || s.isBlank();
    }
}
