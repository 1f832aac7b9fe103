package gcnc.studio;

import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.check.Checker;
import gcnc.check.ModalState;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.flow.ProgramFlow;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import gcnc.ir.RawBlock;
import gcnc.machine.Control;
import gcnc.machine.FunctionText;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.parse.BlockReader;
import gcnc.parse.BlockSource;
import gcnc.parse.BoundedReader;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The hover: what a G or M word does on this control (its row of g_codes.csv or m_codes.csv, in
 * the page's language) and the modal state the control is in after the block of that line
 * (units, feed mode and feed, G96 surface speed and the rpm it gives at the block's X, work
 * offset, tool and offset, where the tool is). The state is the checker's own
 * ({@link Checker#state()} after each block), so it is what the diagnostics were judged by.
 *
 * <p>The blocks are read as {@code gcnc.Compiler} reads them for a check (the parser, then the
 * program flow where the control has calls or macros); a block that runs more than once (a
 * subprogram in the same file, a loop) shows its state at its first run. The last text's states
 * are kept, so hovering along one version of the program checks it once.
 */
final class Modal {
    /** The state after one line's block (first run), and what the checker made of it. */
    record Snapshot(ModalState state, CheckedBlock block, boolean accepted, int runs) {
    }

    private final Session session;
    private final ErrorMessages.Lang lang;
    private String lastKey;
    private Map<Integer, Snapshot> last = Map.of();

    Modal(Session session, ErrorMessages.Lang lang) {
        this.session = session;
        this.lang = lang;
    }

    /** {@code POST /api/hover}: the function of {@code word} (if a G or M) and the state after {@code line}'s block. */
    JsonObject hover(String name, String text, int line, String word, Optional<Path> folder) throws IOException {
        JsonObject o = new JsonObject();
        o.addProperty("line", line);
        if (word != null) {
            o.addProperty("word", word);
            JsonObject f = function(word);
            if (f != null) {
                o.add("function", f);
            }
        }
        Snapshot s = states(name, text, folder).get(line);
        if (s != null) {
            o.add("state", state(s));
        }
        return o;
    }

    /** The function a G or M word names on this control ({@link FunctionText}), or null (another letter). */
    JsonObject function(String word) {
        Optional<FunctionText> found = FunctionText.of(session.profile().control(), word);
        if (found.isEmpty()) {
            return null;
        }
        FunctionText f = found.get();
        JsonObject o = new JsonObject();
        o.addProperty("code", f.name());
        if (!f.known()) {
            o.addProperty("unknown", true);
        } else {
            o.addProperty("text", lang == ErrorMessages.Lang.ES ? f.spanish() : f.english());
            o.addProperty("group", f.group());
            if (f.letter() == 'G') {
                o.addProperty("modal", f.modal());
            } else {
                o.addProperty("moment", f.moment());
            }
        }
        o.addProperty("control", f.control());
        return o;
    }

    /** The states of a text, the last one's kept. */
    synchronized Map<Integer, Snapshot> states(String name, String text, Optional<Path> folder) throws IOException {
        String key = name + '\u0000' + folder.map(Path::toString).orElse("") + '\u0000' + text;
        if (!key.equals(lastKey)) {
            last = run(text, folder);
            lastKey = key;
        }
        return last;
    }

    private Map<Integer, Snapshot> run(String text, Optional<Path> folder) throws IOException {
        Diagnostics diags = new Diagnostics();
        MachineProfile profile = session.profile();
        BlockSource blocks = blocks(new StringReader(text), profile, diags, folder);
        Checker checker = new Checker(session.tables(), profile, diags);
        Map<Integer, Snapshot> states = new HashMap<>();
        for (RawBlock raw = blocks.next(); raw != null; raw = blocks.next()) {
            boolean own = diags.place().file() == null; // a block of this text, not of a called file
            var checked = checker.check(raw);
            if (!own) {
                continue;
            }
            Snapshot before = states.get(raw.line());
            if (before != null) {
                states.put(raw.line(), new Snapshot(before.state(), before.block(), before.accepted(), before.runs() + 1));
            } else {
                states.put(raw.line(), new Snapshot(checker.state(), checked.isEmpty() ? null : checked.get(checked.size() - 1),
                        !checked.isEmpty(), 1));
            }
        }
        return states;
    }

    /**
     * The blocks as the control runs them, as {@code gcnc.Compiler} puts the stages together for a
     * check (its {@code blocks}, which is private: keep the two alike).
     */
    private static BlockSource blocks(Reader text, MachineProfile profile, Diagnostics diags, Optional<Path> folder) {
        Reader source = new BoundedReader(text, diags, Origin.PROGRAM);
        Control control = profile.control();
        if (!control.hasProgramFlow()) {
            return BlockReader.forControl(source, diags, false, control.lineComments());
        }
        return new ProgramFlow(BlockReader.forControl(source, diags, control.macros(), control.lineComments()), control, diags,
                folder);
    }

    /** The state as the page shows it: G names as this control writes them, offsets in machine mm. */
    private JsonObject state(Snapshot s) {
        MachineProfile p = session.profile();
        Control c = p.control();
        ModalState m = s.state();
        JsonObject o = new JsonObject();
        o.addProperty("accepted", s.accepted());
        o.addProperty("runs", s.runs());
        o.addProperty("units", m.units() == Units.INCH ? "inch" : "mm");
        o.addProperty("unitsG", g(c, m.units() == Units.INCH ? GRole.INCH : GRole.METRIC));
        o.addProperty("motion", m.motion() < 0 ? null : "G0" + m.motion());
        o.addProperty("incremental", m.incremental());
        o.addProperty("feedPerRev", m.feedPerRev());
        o.addProperty("feedG", g(c, m.feedPerRev() ? GRole.FEED_PER_REV : GRole.FEED_PER_MINUTE));
        o.addProperty("feed", finite(m.feed()));
        o.addProperty("css", m.css());
        o.addProperty("spindleG", g(c, m.css() ? GRole.CSS : GRole.RPM));
        o.addProperty("surfaceSpeed", finite(m.surfaceSpeed()));
        o.addProperty("rpm", finite(m.rpm()));
        o.addProperty("rpmClamp", finite(m.rpmClamp()));
        if (s.block() != null && s.block().spindleRpm().isPresent()) {
            o.addProperty("blockRpm", round(s.block().spindleRpm().getAsDouble()));
        }
        o.addProperty("workOffset", "G" + m.workOffset());
        p.workOffset(m.workOffset()).ifPresent(w -> o.add("workOffsetMm", mm(w, p)));
        o.addProperty("tool", m.tool());
        o.addProperty("toolOffset", m.toolOffset());
        p.toolOffset(m.toolOffset()).ifPresent(t -> o.add("toolOffsetMm", mm(t, p)));
        o.addProperty("nose", g(c, switch (m.nose()) {
            case LEFT -> GRole.NOSE_COMP_LEFT;
            case RIGHT -> GRole.NOSE_COMP_RIGHT;
            case OFF -> GRole.NOSE_COMP_CANCEL;
        }));
        CheckedBlock b = s.block();
        if (b != null && b.frame() != null) {
            ProgramFrame f = b.frame();
            JsonObject at = new JsonObject();
            at.addProperty("x", round((b.end().x() - f.origin().x()) / f.perX()));
            at.addProperty("z", round((b.end().z() - f.origin().z()) / f.perZ()));
            at.addProperty("diameter", p.diameterX());
            o.add("at", at);
        }
        return o;
    }

    private static String g(Control c, GRole role) {
        return c.gFor(role).map(GFunction::name).orElse(null);
    }

    private static JsonObject mm(Point counts, MachineProfile p) {
        JsonObject o = new JsonObject();
        o.addProperty("x", round(counts.x() / p.x().countsPerMm()));
        o.addProperty("z", round(counts.z() / p.z().countsPerMm()));
        return o;
    }

    private static Double finite(double v) {
        return Double.isFinite(v) ? round(v) : null;
    }

    private static double round(double v) {
        return Math.round(v * 1000) / 1000.0;
    }
}
