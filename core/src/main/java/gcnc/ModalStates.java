package gcnc;

import gcnc.check.ModalState;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import gcnc.ir.RawBlock;
import gcnc.machine.Control;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.io.IOException;
import java.io.Reader;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The modal state the control is in after each line's block, for a front end's hover (the studio's,
 * the language server's): units, feed mode and feed, G96 surface speed and the rpm it gives at the
 * block's X, work offset, tool and offset, nose compensation, where the tool is. The state is the
 * checker's own (the checker's state after each block), so it is what the diagnostics were judged by.
 *
 * <p>The blocks are read as {@link Compiler} reads them for a check (the parser, then the program flow
 * where the control has calls or macros, the called programs looked for where the session says); a
 * block that runs more than once (a subprogram in the same file, a loop) shows its state at its first run.
 */
public final class ModalStates {
    /** The state after one line's block (first run), what the checker made of it, and how often the line ran. */
    public record Snapshot(ModalState state, CheckedBlock block, boolean accepted, int runs) {
    }

    /** A position in program terms (X as the program writes it: a diameter when {@code diameter}). */
    public record At(double x, double z, boolean diameter) {
    }

    /** A position in machine millimetres (a work or tool offset). */
    public record Mm(double x, double z) {
    }

    /**
     * A snapshot as a person reads it: G names as this control writes them, values rounded to
     * 0.001, offsets in machine mm; a value that is not set (no feed yet) is null.
     */
    public record Summary(boolean accepted, int runs, String units, String unitsG, String motion, boolean incremental,
                          boolean feedPerRev, String feedG, Double feed, boolean css, String spindleG,
                          Double surfaceSpeed, Double rpm, Double rpmClamp, Optional<Double> blockRpm,
                          String workOffset, Optional<Mm> workOffsetMm, int tool, int toolOffset,
                          Optional<Mm> toolOffsetMm, String nose, Optional<At> at) {
    }

    private ModalStates() {
    }

    /**
     * The state after each line of {@code text}'s own blocks (not those of a called file), by line: a
     * view of {@link Session#check(Reader, CompileObserver)}'s blocks, so the state is the one the
     * program's diagnostics were judged by.
     */
    public static Map<Integer, Snapshot> of(Session session, Reader text) throws IOException {
        Map<Integer, Snapshot> states = new HashMap<>();
        session.check(text, view(states));
        return states;
    }

    /** The observer that fills {@code states} with each own line's snapshot (its first run, and how often it ran). */
    public static CompileObserver view(Map<Integer, Snapshot> states) {
        return new CompileObserver() {
            @Override
            public void block(RawBlock raw, gcnc.diag.Origin from, java.util.List<CheckedBlock> checked,
                              ModalState after) {
                if (from.file() != null) {
                    return; // a block of a called file, not of this text
                }
                Snapshot before = states.get(raw.line());
                if (before != null) {
                    states.put(raw.line(), new Snapshot(before.state(), before.block(), before.accepted(), before.runs() + 1));
                } else {
                    states.put(raw.line(), new Snapshot(after, checked.isEmpty() ? null : checked.get(checked.size() - 1),
                            !checked.isEmpty(), 1));
                }
            }
        };
    }

    /** {@code s} as a person reads it on {@code p}'s control. */
    public static Summary summary(Snapshot s, MachineProfile p) {
        Control c = p.control();
        ModalState m = s.state();
        CheckedBlock b = s.block();
        Optional<Double> blockRpm = b != null && b.spindleRpm().isPresent()
                ? Optional.of(round(b.spindleRpm().getAsDouble())) : Optional.empty();
        Optional<At> at = Optional.empty();
        if (b != null && b.frame() != null) {
            ProgramFrame f = b.frame();
            at = Optional.of(new At(round((b.end().x() - f.origin().x()) / f.perX()),
                    round((b.end().z() - f.origin().z()) / f.perZ()), p.diameterX()));
        }
        return new Summary(s.accepted(), s.runs(), m.units() == Units.INCH ? "inch" : "mm",
                g(c, m.units() == Units.INCH ? GRole.INCH : GRole.METRIC), m.motion() < 0 ? null : "G0" + m.motion(),
                m.incremental(), m.feedPerRev(), g(c, m.feedPerRev() ? GRole.FEED_PER_REV : GRole.FEED_PER_MINUTE),
                finite(m.feed()), m.css(), g(c, m.css() ? GRole.CSS : GRole.RPM), finite(m.surfaceSpeed()),
                finite(m.rpm()), finite(m.rpmClamp()), blockRpm, "G" + m.workOffset(),
                p.workOffset(m.workOffset()).map(w -> mm(w, p)), m.tool(), m.toolOffset(),
                p.toolOffset(m.toolOffset()).map(t -> mm(t, p)), g(c, switch (m.nose()) {
                    case LEFT -> GRole.NOSE_COMP_LEFT;
                    case RIGHT -> GRole.NOSE_COMP_RIGHT;
                    case OFF -> GRole.NOSE_COMP_CANCEL;
                }), at);
    }

    private static String g(Control c, GRole role) {
        return c.gFor(role).map(GFunction::name).orElse(null);
    }

    private static Mm mm(Point counts, MachineProfile p) {
        return new Mm(round(counts.x() / p.x().countsPerMm()), round(counts.z() / p.z().countsPerMm()));
    }

    private static Double finite(double v) {
        return Double.isFinite(v) ? round(v) : null;
    }

    private static double round(double v) {
        return Math.round(v * 1000) / 1000.0;
    }
}
