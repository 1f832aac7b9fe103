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
 * peck, J how much less each next one, K the smallest), G84/G184 tapping, G85/G86/G89 boring
 * ({@link HoleBoring}); on the Fanuc 0i-TF G83 face drilling, G84 face tapping, G85 face boring
 * and the Series 15 format G81/G82 (G83 without pecks; G82 with its dwell), each {@code X(U) Z(W) R F}: X where the
 * hole is (the spindle centre, X0, unless the drill is made to cut off centre: E186), Z the bottom,
 * R the Z of the R plane. The moves are {@link Drilling}'s. The cycle is modal in its group: a
 * later block with X, U, Z or W and no G of its group, of the motion group or one-shot drills
 * again there, with what it does not give as before; G80 or a motion G (G00-G03, G90, G94) ends it.
 */
final class HoleDrilling extends ModalExpansion {
    /** The most pecks one hole is expanded into. */
    static final int MAX_PECKS = 10_000;
    /** The most repeats (K, L) of one hole gcnc expands. */
    static final int MAX_REPEATS = 99;
    private static final double EPS_MM = 0.001;
    private static final Set<Letter> OWN = EnumSet.of(Letter.R, Letter.P, Letter.Q, Letter.I, Letter.J, Letter.K,
            Letter.L);
    /**
     * Fanuc's words (control key cycle.drill_words = fanuc): R, P the dwell, Q the peck, K the
     * repeats (L in the Series 15 format of G81/G82).
     */
    private static final Set<Letter> FANUC_OWN = EnumSet.of(Letter.R, Letter.P, Letter.Q, Letter.K, Letter.L,
            Letter.C, Letter.H);

    private double bottom;
    private double rPlane;
    /** Fanuc: the initial level, the Z where the cycle in force was commanded (a repeat after G99 starts at the R point). */
    private double initialZ;
    private double first;
    private double reduce;
    private double least;
    private Word dwell;

    HoleDrilling(CycleHost host) {
        // the cycle in force ends at G80, a motion G or a single-pass cycle
        super(host, new ModalCycle(f -> f.role().motion() || f.role().singleCycle()));
    }

    /** A G81/G82/G83 block ({@code g} its cycle word), or a block that drills again (g null). */
    @Override
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        GRole role = role(g);
        String label = label(g);
        Units u = host.state().units();
        MachineProfile p = host.profile();
        boolean fanuc = p.control().fanucDrilling();
        Word at = g;
        CycleWords words = words(b, g, label, u, fanuc);
        List<CheckedBlock> done = new ArrayList<>();
        List<Word> passOn = words != null ? words.passOn() : CycleBlocks.passOn(b, g, this::isCycle);
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        if (words == null) {
            return refused(g, done);
        }
        if (at == null) {
            at = words.axes().get(0);
        }
        if (!(fanuc ? checkFanuc(words, role, label) : check(words, role, label, g))) {
            return refused(g, done);
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
            return refused(g, done);
        }
        double holeBottom = newZ ? end.z() : bottom;
        // Haas: R is the R plane's Z; Fanuc: the distance from the initial level (where the cycle
        // starts) to it, or with cycle.drill_r = absolute (parameter RAB) in G90 mode its Z
        boolean rFromStart = fanuc && (!p.control().drillRAbsolute() || start.incremental());
        double initial = fanuc && g == null ? initialZ : a.z();
        double zOrigin = c.origin(start.next()).z();
        double plane = !words.has(Letter.R) ? g != null ? a.z() : rPlane
                : (rFromStart ? initial : zOrigin) + words.value(Letter.R) * perZ;
        if (!between(words, at, label, a.z(), plane, holeBottom, zOrigin, perZ)) {
            return refused(g, done);
        }
        if (g != null) {
            begin(g, role, label, a.z());
        }
        bottom = holeBottom;
        rPlane = plane;
        pecks(words, perZ);
        offCentre(words, at, label, end.x(), c.origin(start.next()).x(), c.perX(u));
        // Fanuc B/C G99: back to the R point after the hole; G98 (and Haas, Fanuc A): to the initial level
        double returnZ = start.returnToR() ? rPlane : initial;
        // K (Fanuc) or L (Haas, Fanuc Series 15): the same hole that many times, each from the
        // return level; K0 keeps the cycle's data and drills nothing (checked: check, checkFanuc)
        Word rep = words.has(Letter.L) ? words.word(Letter.L) : fanuc ? words.word(Letter.K) : null;
        int repeats = rep == null ? 1 : (int) NumberText.decimal(rep.number());
        int errors = host.out().errorCount();
        for (int k = 0; k < repeats && host.out().errorCount() == errors; k++) {
            if (!hole(b, at, k == 0 ? start : host.state(), end.x(), returnZ, label, words, done)) {
                break;
            }
        }
        return done;
    }

    /** After an error: a cycle word's cycle ends there (a block that drills again leaves it in force). */
    private List<CheckedBlock> refused(Word g, List<CheckedBlock> done) {
        if (g != null) {
            modal.end();
        }
        return done;
    }

    /** A cycle word starts the cycle: from the level {@code z}, with no pecks or dwell until its words give them. */
    private void begin(Word g, GRole role, String label, double z) {
        initialZ = z;
        modal.start(role, function(g), label);
        first = Double.NaN;
        reduce = 0;
        least = Double.NaN;
        dwell = null;
    }

    /**
     * The cycle's words of the block; null after the error about one. Fanuc's Q without a decimal
     * point counts least increments of input (IS-B), as G74/G75's P and Q do; with a point it is a
     * length in the program's unit, as the Fusion fanuc post writes it (Q2.5: docs/language.md),
     * since a point is never read as increments.
     */
    private CycleWords words(RawBlock b, Word g, String label, Units u, boolean fanuc) {
        MachineProfile p = host.profile();
        double noPoint = u == Units.INCH ? p.noPointInch() : p.noPointMm();
        double increment = u == Units.INCH ? 0.0001 : 0.001;
        boolean qInIncrements = fanuc && b.words().stream()
                .noneMatch(w -> w.letter() == Letter.Q && NumberText.hasPoint(w.number()));
        return CycleWords.read(b, g, label, fanuc ? FANUC_OWN : OWN,
                qInIncrements ? Set.of(Letter.Q) : Set.of(), noPoint, increment, w -> isCycle(w), host.out());
    }

    /**
     * Whether the R plane lies between the start and the bottom of the hole (the tool feeds from it
     * to the bottom, so it must): else E187, naming the three levels in the program's Z.
     */
    private boolean between(CycleWords words, Word at, String label, double startZ, double plane, double holeBottom,
                            double zOrigin, double perZ) {
        double eps = EPS_MM * host.profile().z().countsPerMm();
        double toBottom = holeBottom - startZ;
        double toPlane = plane - startZ;
        if (Math.abs(holeBottom - plane) <= eps || Math.signum(toPlane) * Math.signum(toBottom) < 0
                || Math.abs(toPlane) > Math.abs(toBottom)) {
            Word r = words.word(Letter.R);
            host.out().error(Code.E187_DRILL_R_PLANE, r != null ? r.span() : at.span(), label,
                    NumberText.plain((plane - zOrigin) / perZ, 4), NumberText.plain((startZ - zOrigin) / perZ, 4),
                    NumberText.plain((holeBottom - zOrigin) / perZ, 4));
            return false;
        }
        return true;
    }

    /** The pecks this block gives (Q, or Haas I J K), kept in force for the blocks that drill again; a P dwell too. */
    private void pecks(CycleWords words, double perZ) {
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
    }

    /** Warning E186 when the hole is off the centre line (X not 0): a lathe drills on it. */
    private void offCentre(CycleWords words, Word at, String label, double x, double xOrigin, double perX) {
        if (Math.abs(x - xOrigin) > EPS_MM * host.profile().x().countsPerMm()) {
            Word xw = words.axes().stream().filter(w -> w.letter() == Letter.X || w.letter() == Letter.U).findFirst()
                    .orElse(at);
            host.out().report(gcnc.diag.Diagnostic.warning(Code.E186_DRILL_OFF_CENTRE, xw.span(), label,
                    NumberText.plain((x - xOrigin) / perX, 4)));
        }
    }

    /** One hole from {@code start}'s position, its blocks added to {@code done}; false after an error. */
    private boolean hole(RawBlock b, Word at, ModalState start, double x, double returnZ, String label,
                         CycleWords words, List<CheckedBlock> done) {
        MachineProfile p = host.profile();
        Point a = start.position();
        if (modal.kind().tapCycle()) {
            done.addAll(HoleTapping.tap(host, modal.kind(), modal.name(), b, at, start, x, rPlane, bottom, returnZ,
                    dwell, label));
            return true;
        }
        if (modal.kind().boreCycle()) {
            done.addAll(HoleBoring.bore(host, modal.kind(), modal.name(), b, at, start, x, rPlane, bottom,
                    returnZ, dwell));
            return true;
        }
        double clearance = p.control().peckRetractMm();
        if (modal.kind() == GRole.PECK_DRILL_CYCLE && Double.isNaN(clearance)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, at.span(), label,
                    Phrase.DRILL_CLEARANCE.arg());
            return false;
        }
        Drilling drill = new Drilling(a, x, rPlane, bottom, modal.kind() == GRole.PECK_DRILL_CYCLE ? first : Double.NaN,
                reduce, least, Double.isNaN(clearance) ? 0 : clearance * p.z().countsPerMm());
        int pecks = drill.pecks(MAX_PECKS).size();
        if (pecks > MAX_PECKS) {
            host.out().error(Code.E167_CYCLE_TOO_MANY_PASSES, at.span(), label,
                    words.has(Letter.Q) ? words.word(Letter.Q) : at, "more than " + MAX_PECKS, MAX_PECKS);
            return false;
        }
        Expansion.warnIfMany(host, label, words.has(Letter.Q) ? words.word(Letter.Q) : at, pecks);
        List<Move> moves = drill.plan(MAX_PECKS, returnZ);
        int bottomFeed = -1;
        for (int i = 0; i < moves.size(); i++) {
            if (moves.get(i).kind() == Move.Kind.FEED) {
                bottomFeed = i;
            }
        }
        RawBlock pause = null;
        boolean dwells = modal.kind() == GRole.SPOT_DRILL_CYCLE
                || p.control().fanucDrilling() && NumberText.decimal(dwell == null ? "0" : dwell.number()) > 0;
        if (dwells && dwell != null) {
            String g04 = p.control().gFor(GRole.DWELL).map(f -> f.name().substring(1)).orElseThrow();
            pause = new RawBlock(b.line(), List.of(new Word(Letter.G, g04, at.span()),
                    new Word(Letter.P, dwell.number(), at.span())), at.span(), false);
        }
        done.addAll(CycleBlocks.write(host, modal.name(), b.line(), at.span(), moves, 1, start, bottomFeed, pause));
        return true;
    }

    /**
     * Fanuc's words (G83, G84 on the spindle axis): C/H (C-axis positioning of live tooling), W or
     * G91 Z (the bottom from the R point) and repeats K/L stepped along X or not a whole number are not
     * supported yet (E188); Q only on G83, more than 0 (E180; without it G83 drills in one
     * feed); P the dwell at the bottom, zero or more. False after the first error.
     */
    private boolean checkFanuc(CycleWords words, GRole role, String label) {
        for (Letter l : List.of(Letter.C, Letter.H)) {
            if (words.has(l)) {
                // a hole off the centre line, by the C axis: live tooling
                host.out().error(Code.E188_PECK_OPTION_NOT_SUPPORTED, words.word(l).span(), label, words.word(l),
                        Phrase.DRILL_C_AXIS.arg());
                return false;
            }
        }
        for (Word w : words.axes()) {
            // W, or Z in G91 mode (system B): the distance from the R point to the bottom, not a move
            // from where the tool stands as gcnc would read it
            if (w.letter() == Letter.W || w.letter() == Letter.Z && host.state().incremental()) {
                host.out().error(Code.E188_PECK_OPTION_NOT_SUPPORTED, w.span(), label, w, Phrase.DRILL_BOTTOM_W.arg());
                return false;
            }
        }
        for (Letter l : List.of(Letter.K, Letter.L)) {
            if (words.has(l) && !repeatsFollowed(words, words.word(l))) {
                host.out().error(Code.E188_PECK_OPTION_NOT_SUPPORTED, words.word(l).span(), label, words.word(l),
                        Phrase.DRILL_REPEATS.arg());
                return false;
            }
        }
        if (words.has(Letter.Q) && role.tapCycle()) {
            host.out().error(Code.E188_PECK_OPTION_NOT_SUPPORTED, words.word(Letter.Q).span(), label,
                    words.word(Letter.Q), Phrase.TAP_PECK.arg());
            return false;
        }
        for (Letter l : List.of(Letter.Q, Letter.P)) {
            if (words.has(l) && (l == Letter.Q ? words.value(l) <= 0 : words.value(l) < 0)) {
                host.out().error(Code.E180_PECK_NOT_POSITIVE, words.word(l).span(), label, words.word(l),
                        l == Letter.Q ? "the peck depth" : "the dwell");
                return false;
            }
        }
        return true;
    }

    /** The words this cycle takes, with the right signs; false after the first error. */
    private boolean check(CycleWords words, GRole role, String label, Word g) {
        if (words.has(Letter.L) && !repeatsFollowed(words, words.word(Letter.L))) {
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
            if (peckWord && role.tapCycle()) {
                // the Fusion posts' "tapping with chip breaking" (G84 ... Q)
                host.out().error(Code.E188_PECK_OPTION_NOT_SUPPORTED, w.span(), label, w, Phrase.TAP_PECK.arg());
                return false;
            }
            if (peckWord && role != GRole.PECK_DRILL_CYCLE
                    || !peckWord && role != GRole.SPOT_DRILL_CYCLE && role != GRole.BORE_DWELL_CYCLE
                    && !role.tapCycle()) {
                host.out().error(Code.E161_CYCLE_WORD, w.span(), label, w);
                return false;
            }
            double v = words.value(l);
            // a tap's P may be 0 (no dwell at the bottom: the Fusion posts write P0)
            if (l == Letter.J || l == Letter.P && role.tapCycle() ? v < 0 : v <= 0) {
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
        if (g != null && (role == GRole.SPOT_DRILL_CYCLE || role == GRole.BORE_DWELL_CYCLE) && !words.has(Letter.P)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, g.span(), label, Phrase.DRILL_DWELL.arg());
            return false;
        }
        return true;
    }

    /**
     * Whether gcnc follows the repeats {@code rep} (Fanuc K, Haas and Fanuc Series 15 L): a whole
     * number from 0 to {@link #MAX_REPEATS} without a decimal point, and more than one only for a
     * hole at an absolute X (each repeat drills the same hole again); repeats stepped by U or by
     * X in G91 make a row of holes off the centre line, which needs live tooling (E188).
     */
    private boolean repeatsFollowed(CycleWords words, Word rep) {
        if (NumberText.hasPoint(rep.number()) || rep.number().startsWith("-")) {
            return false;
        }
        double n = NumberText.decimal(rep.number());
        boolean stepped = words.axes().stream().anyMatch(w -> w.letter() == Letter.U
                || w.letter() == Letter.X && host.state().incremental());
        return n <= MAX_REPEATS && (n <= 1 || !stepped);
    }

    private boolean isCycle(Word w) {
        GFunction f = function(w);
        return f != null && (f.role().contourCycle() || f.role().singleCycle() || f.role().peckCycle()
                || f.role().drillCycle());
    }
}
