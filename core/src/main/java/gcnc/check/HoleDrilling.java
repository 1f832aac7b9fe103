package gcnc.check;

import gcnc.check.cycle.CycleWords;
import gcnc.check.cycle.Drilling;
import gcnc.check.cycle.Move;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/**
 * The drilling cycles on the spindle axis of the Haas lathe (docs/cycles.md): G81 drill, G82 spot
 * drill (a dwell P at the bottom, read as G04's P), G83 peck drill (Q the peck, or I the first
 * peck, J how much less each next one, K the smallest), each {@code X(U) Z(W) R F}: X where the
 * hole is (the spindle centre, X0, unless the drill is made to cut off centre: E186), Z the bottom,
 * R the Z of the R plane. The moves are {@link Drilling}'s. The cycle is modal in its group: a
 * later block with X, U, Z or W and no G of its group, of the motion group or one-shot drills
 * again there, with what it does not give as before; G80 or a motion G (G00-G03, G90, G94) ends it.
 */
final class HoleDrilling {
    /** The most pecks one hole is expanded into. */
    static final int MAX_PECKS = 10_000;
    private static final double EPS_MM = 0.001;
    private static final Set<Letter> OWN = EnumSet.of(Letter.R, Letter.P, Letter.Q, Letter.I, Letter.J, Letter.K,
            Letter.L);

    private final Checker host;
    /** The cycle in force, or null; its name, group and what later blocks keep. */
    private final ModalCycle modal = new ModalCycle(f -> f.role().motion() || f.role().singleCycle());
    private double bottom;
    private double rPlane;
    private double first;
    private double reduce;
    private double least;
    private Word dwell;

    HoleDrilling(Checker host) {
        this.host = host;
    }

    private GFunction function(Word w) {
        return CycleBlocks.function(host, w);
    }

    /** The cycle in force as the program wrote it ("G81"), for a finding about running it again. */
    String name() {
        return modal.name();
    }

    /** Whether the block drills again with the cycle in force: an axis word and no G that ends it or owns the words. */
    boolean repeats(RawBlock b) {
        return modal.repeats(host, b);
    }

    /** An ordinary block: G80, a motion G or a single-pass cycle ends the cycle. */
    void note(RawBlock b) {
        modal.note(host, b);
    }

    /** A G81/G82/G83 block ({@code g} its cycle word), or a block that drills again (g null). */
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        GRole role = g == null ? modal.kind() : function(g).role();
        String label = g == null ? modal.name() : "G" + g.number();
        Units u = host.state().units();
        MachineProfile p = host.profile();
        double noPoint = u == Units.INCH ? p.noPointInch() : p.noPointMm();
        Set<Letter> own = EnumSet.copyOf(OWN);
        Word at = g;
        CycleWords words = CycleWords.read(b, g, label, own, Set.of(),
                noPoint, 1, w -> isCycle(w), host.out());
        List<CheckedBlock> done = new ArrayList<>();
        List<Word> passOn = words != null ? words.passOn() : CycleBlocks.passOn(b, g, this::isCycle);
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        if (words == null) {
            if (g != null) {
                modal.end();
            }
            return done;
        }
        if (at == null) {
            at = words.axes().get(0);
        }
        if (!check(words, role, label, g)) {
            if (g != null) {
                modal.end();
            }
            return done;
        }
        ModalState start = host.state();
        Point end = CycleBlocks.target(host, b, words.axes(), start);
        if (end == null) {
            return done;
        }
        Coordinates c = host.coordinates();
        double perZ = c.perZ(u);
        Point a = start.position();
        boolean newZ = words.hasAxis(false);
        if (g != null && !newZ) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, g.span(), label, Phrase.DRILL_BOTTOM.arg());
            modal.end();
            return done;
        }
        double zOrigin = c.origin(start.next()).z();
        double holeBottom = newZ ? end.z() : bottom;
        double plane = words.has(Letter.R) ? zOrigin + words.value(Letter.R) * perZ : g != null ? a.z() : rPlane;
        double eps = EPS_MM * p.z().countsPerMm();
        double toBottom = holeBottom - a.z();
        double toPlane = plane - a.z();
        if (Math.abs(holeBottom - plane) <= eps || Math.signum(toPlane) * Math.signum(toBottom) < 0
                || Math.abs(toPlane) > Math.abs(toBottom)) {
            Word r = words.word(Letter.R);
            host.out().error(Code.E187_DRILL_R_PLANE, r != null ? r.span() : at.span(), label,
                    NumberText.plain((plane - zOrigin) / perZ, 4), NumberText.plain((a.z() - zOrigin) / perZ, 4),
                    NumberText.plain((holeBottom - zOrigin) / perZ, 4));
            if (g != null) {
                modal.end();
            }
            return done;
        }
        if (g != null) {
            modal.start(role, function(g), label);
            first = Double.NaN;
            reduce = 0;
            least = Double.NaN;
            dwell = null;
        }
        bottom = holeBottom;
        rPlane = plane;
        if (words.has(Letter.Q)) {
            first = words.value(Letter.Q) * perZ;
            least = first;
            reduce = 0;
        } else if (words.has(Letter.I)) {
            first = words.value(Letter.I) * perZ;
            reduce = words.has(Letter.J) ? words.value(Letter.J) * perZ : 0;
            least = words.has(Letter.K) ? words.value(Letter.K) * perZ : first;
        }
        if (words.has(Letter.P)) {
            dwell = words.word(Letter.P);
        }
        double xOrigin = c.origin(start.next()).x();
        double holeX = (end.x() - xOrigin) / c.perX(u);
        if (Math.abs(end.x() - xOrigin) > EPS_MM * p.x().countsPerMm()) {
            Word x = words.axes().stream().filter(w -> w.letter() == Letter.X || w.letter() == Letter.U).findFirst()
                    .orElse(at);
            host.out().report(gcnc.diag.Diagnostic.warning(Code.E186_DRILL_OFF_CENTRE, x.span(), label,
                    NumberText.plain(holeX, 4)));
        }
        double clearance = p.control().peckRetractMm();
        if (modal.kind() == GRole.PECK_DRILL_CYCLE && Double.isNaN(clearance)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, at.span(), label,
                    Phrase.DRILL_CLEARANCE.arg());
            return done;
        }
        Drilling drill = new Drilling(a, end.x(), rPlane, bottom, modal.kind() == GRole.PECK_DRILL_CYCLE ? first : Double.NaN,
                reduce, least, Double.isNaN(clearance) ? 0 : clearance * p.z().countsPerMm());
        int pecks = drill.pecks(MAX_PECKS).size();
        if (pecks > MAX_PECKS) {
            host.out().error(Code.E167_CYCLE_TOO_MANY_PASSES, at.span(), label,
                    words.has(Letter.Q) ? words.word(Letter.Q) : at, "more than " + MAX_PECKS, MAX_PECKS);
            return done;
        }
        Expansion.warnIfMany(host, label, words.has(Letter.Q) ? words.word(Letter.Q) : at, pecks);
        List<Move> moves = drill.plan(MAX_PECKS);
        int bottomFeed = -1;
        for (int i = 0; i < moves.size(); i++) {
            if (moves.get(i).kind() == Move.Kind.FEED) {
                bottomFeed = i;
            }
        }
        RawBlock pause = null;
        if (modal.kind() == GRole.SPOT_DRILL_CYCLE && dwell != null) {
            String g04 = p.control().gFor(GRole.DWELL).map(f -> f.name().substring(1)).orElseThrow();
            pause = new RawBlock(b.line(), List.of(new Word(Letter.G, g04, at.span()),
                    new Word(Letter.P, dwell.number(), at.span())), at.span(), false);
        }
        done.addAll(CycleBlocks.write(host, modal.name(), b.line(), at.span(), moves, 1, start, bottomFeed, pause));
        return done;
    }

    /** The words this cycle takes, with the right signs; false after the first error. */
    private boolean check(CycleWords words, GRole role, String label, Word g) {
        if (words.has(Letter.L)) {
            host.out().error(Code.E188_PECK_OPTION_NOT_SUPPORTED, words.word(Letter.L).span(), label,
                    words.word(Letter.L), Phrase.DRILL_REPEATS.arg());
            return false;
        }
        for (Letter l : List.of(Letter.Q, Letter.I, Letter.J, Letter.K, Letter.P)) {
            Word w = words.word(l);
            if (w == null) {
                continue;
            }
            boolean peckWord = l != Letter.P;
            if (peckWord && role != GRole.PECK_DRILL_CYCLE || !peckWord && role != GRole.SPOT_DRILL_CYCLE) {
                host.out().error(Code.E161_CYCLE_WORD, w.span(), label, w);
                return false;
            }
            double v = words.value(l);
            if (l == Letter.J ? v < 0 : v <= 0) {
                host.out().error(Code.E180_PECK_NOT_POSITIVE, w.span(), label, w, switch (l) {
                    case Q -> "the peck depth";
                    case I -> "the first peck";
                    case J -> "how much less each next peck is: zero or more";
                    case K -> "the smallest peck";
                    default -> "the dwell";
                });
                return false;
            }
        }
        if (words.has(Letter.Q) && (words.has(Letter.I) || words.has(Letter.J) || words.has(Letter.K))) {
            Word w = words.word(words.has(Letter.I) ? Letter.I : words.has(Letter.J) ? Letter.J : Letter.K);
            host.out().error(Code.E161_CYCLE_WORD, w.span(), label, w);
            return false;
        }
        if (g != null && role == GRole.PECK_DRILL_CYCLE && !words.has(Letter.Q) && !words.has(Letter.I)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, g.span(), label, Phrase.DRILL_PECK.arg());
            return false;
        }
        if (words.has(Letter.J) && !words.has(Letter.I) || words.has(Letter.J) && !words.has(Letter.K)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, words.word(Letter.J).span(), label,
                    Phrase.DRILL_PECK_J.arg());
            return false;
        }
        if (g != null && role == GRole.SPOT_DRILL_CYCLE && !words.has(Letter.P)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, g.span(), label, Phrase.DRILL_DWELL.arg());
            return false;
        }
        return true;
    }

    private boolean isCycle(Word w) {
        GFunction f = function(w);
        return f != null && (f.role().contourCycle() || f.role().singleCycle() || f.role().peckCycle()
                || f.role().drillCycle());
    }
}
