package gcnc.check;

import gcnc.check.cycle.CycleWords;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.cycle.Pecking;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The peck cycles G74 (face grooving, peck drilling: pecks along Z, steps along X) and G75 (OD/ID
 * grooving and parting: pecks along X, steps along Z), in both forms (docs/cycles.md):
 * <ul>
 *   <li>Fanuc, two blocks: {@code G75 R(e: the retract after each peck)}, then
 *       {@code G75 X(U) Z(W) P(Δi) Q(Δk) R(Δd: the relief at the bottom) F}; P and Q in least
 *       increments without a point (G75: P the peck along X, Q the step along Z; G74: P the step
 *       along X, Q the peck along Z); the retract stays in force for later cycles of its kind;</li>
 *   <li>Haas, one block: {@code G75 X(U) Z(W) I(peck along X) K(step along Z) D(relief) F},
 *       {@code G74 X(U) Z(W) I(step along X) K(peck along Z) D F}; the retract is the control's
 *       {@code cycle.peck_retract_mm} (Setting 22).</li>
 * </ul>
 * The end coordinate along the peck axis is required (E182); the one along the step axis may be
 * left out for a single cut (a groove, a part-off, a plain peck-drilled hole). The moves are
 * {@link Pecking}'s, written as blocks at the cycle's line and checked one by one.
 */
final class Grooving {
    /** The most pecks one cycle is expanded into (over all its cuts). */
    static final int MAX_PECKS = 10_000;
    /** Geometric tolerance, mm. */
    private static final double EPS_MM = 0.001;
    private static final Set<Letter> OWN = EnumSet.of(Letter.P, Letter.Q, Letter.R, Letter.I, Letter.K, Letter.D);
    private static final Set<Letter> INCREMENTS = EnumSet.of(Letter.P, Letter.Q);

    private final CycleHost host;
    /** The retract a Fanuc first block left in force, mm, per cycle. */
    private final Map<GRole, Double> retracts = new EnumMap<>(GRole.class);

    Grooving(CycleHost host) {
        this.host = host;
    }

    /** A G74/G75 block ({@code g} its cycle word): its other words first, then its moves. */
    List<CheckedBlock> run(RawBlock b, Word g, GRole kind, boolean isFirst) {
        Units u = host.state().units();
        MachineProfile p = host.profile();
        double noPoint = u == Units.INCH ? p.noPointInch() : p.noPointMm();
        // Fanuc's P and Q count least increments of input (IS-B): 0.001 mm or 0.0001 in
        double increment = u == Units.INCH ? 0.0001 : 0.001;
        CycleWords words = CycleWords.read(b, g, "G" + g.number(), OWN, INCREMENTS, noPoint, increment,
                w -> w.letter() == Letter.G && isCycle(w), host.out());
        List<CheckedBlock> done = new ArrayList<>();
        List<Word> passOn = words != null ? words.passOn() : CycleBlocks.passOn(b, g, this::isCycle);
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        if (words == null) {
            return done;
        }
        String name = "G" + g.number();
        if (words.axes().isEmpty() && words.words().keySet().equals(Set.of(Letter.R))) {
            retract(words, kind, name, u);
            return done;
        }
        boolean haas = words.has(Letter.I) || words.has(Letter.K) || words.has(Letter.D);
        boolean fanuc = words.has(Letter.P) || words.has(Letter.Q) || words.has(Letter.R);
        if (haas && fanuc) {
            Word mixed = first(words, Letter.I, Letter.K, Letter.D);
            host.out().error(Code.E161_CYCLE_WORD, mixed.span(), name, mixed);
            return done;
        }
        boolean alongX = kind == GRole.GROOVE_PECK_CYCLE;
        if (!words.hasAxis(alongX)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, g.span(), name, alongX
                    ? Phrase.PECK_BOTTOM_X.arg() : Phrase.PECK_BOTTOM_Z.arg());
            return done;
        }
        ModalState start = host.state();
        Point end = CycleBlocks.target(host, b, words.axes(), start);
        if (end == null) {
            return done;
        }
        Cut cut = cut(g, words, name, haas, alongX, start.position(), end);
        if (cut == null) {
            return done;
        }
        Point a = start.position();
        double retractMm = retracts.getOrDefault(kind, p.control().peckRetractMm());
        double perMmPeck = alongX ? p.x().countsPerMm() : p.z().countsPerMm();
        Pecking plan = new Pecking(alongX, a, cut.peckEnd(), cut.steps() ? cut.stepEnd() : (alongX ? a.z() : a.x()),
                cut.peck(), cut.steps() ? cut.step() : Double.NaN, Double.isNaN(retractMm) ? 0 : retractMm * perMmPeck,
                cut.relief());
        if (plan.pecksPerCut() > 1 && Double.isNaN(retractMm)) {
            host.out().error(Code.E182_PECK_CYCLE_MISSING, g.span(), name,
                    Phrase.PECK_RETRACT.with(name));
            return done;
        }
        long pecks = (long) plan.cuts() * plan.pecksPerCut();
        if (pecks > MAX_PECKS) {
            host.out().error(Code.E167_CYCLE_TOO_MANY_PASSES, g.span(), name, cut.word(words), pecks, MAX_PECKS);
            return done;
        }
        Expansion.warnIfMany(host, name, cut.word(words), pecks);
        Pecking.Plan moves = plan.plan();
        done.addAll(CycleBlocks.write(host, name, b.line(), g.span(), moves.moves(), moves.passes(), start,
                -1, null));
        return done;
    }

    /** A Fanuc first block {@code G75 R(e)}: the retract after each peck, kept for later cycles of its kind. */
    private void retract(CycleWords words, GRole kind, String name, Units u) {
        double e = words.value(Letter.R);
        if (e < 0) {
            host.out().error(Code.E158_CYCLE_RETRACT, words.word(Letter.R).span(), name, words.word(Letter.R));
        } else {
            retracts.put(kind, e * (u == Units.INCH ? 25.4 : 1));
        }
    }

    /**
     * The cut a cycle block asks for, machine counts: the peck, the step between cuts and the relief
     * at the bottom, the ends along the peck and step axes, and whether it steps at all.
     */
    private record Cut(Letter peckLetter, Letter stepLetter, double peck, double step, double relief, double peckEnd,
                       double stepEnd, boolean steps) {
        /** The word that sets the cycle's count of pecks (the peck, else the step), where E167 and E330 point. */
        Word word(CycleWords words) {
            return words.word(peckLetter) != null ? words.word(peckLetter) : words.word(stepLetter);
        }
    }

    /**
     * The cut from the block's peck, step and relief words (Haas I K D, Fanuc P Q R) from {@code a}
     * to {@code end}; null after the error about one of them (E180, E181, E183-E185).
     */
    private Cut cut(Word g, CycleWords words, String name, boolean haas, boolean alongX, Point a, Point end) {
        Units u = host.state().units();
        MachineProfile p = host.profile();
        Letter peckL = haas ? (alongX ? Letter.I : Letter.K) : (alongX ? Letter.P : Letter.Q);
        Letter stepL = haas ? (alongX ? Letter.K : Letter.I) : (alongX ? Letter.Q : Letter.P);
        Letter reliefL = haas ? Letter.D : Letter.R;
        Coordinates c = host.coordinates();
        double perPeck = alongX ? c.perRadius(u) : c.perZ(u);
        double perStep = alongX ? c.perZ(u) : c.perRadius(u);
        double perMmPeck = alongX ? p.x().countsPerMm() : p.z().countsPerMm();
        double perMmStep = alongX ? p.z().countsPerMm() : p.x().countsPerMm();
        double peckEnd = alongX ? end.x() : end.z();
        double stepEnd = words.hasAxis(!alongX) ? (alongX ? end.z() : end.x()) : (alongX ? a.z() : a.x());
        double depth = Math.abs(peckEnd - (alongX ? a.x() : a.z()));
        double span = Math.abs(stepEnd - (alongX ? a.z() : a.x()));
        double peck = words.has(peckL) ? words.value(peckL) * perPeck : Double.NaN;
        double step = words.has(stepL) ? words.value(stepL) * perStep : Double.NaN;
        double relief = words.has(reliefL) ? words.value(reliefL) * perStep : 0;
        if (peck <= 0) {
            host.out().error(Code.E180_PECK_NOT_POSITIVE, words.word(peckL).span(), name, words.word(peckL),
                    "the peck depth");
            return null;
        }
        double eps = EPS_MM * Math.min(perMmPeck, perMmStep);
        // a step of zero is an error only where the cycle steps: drilling on the centreline
        // ({@code G74 Z-30. Q5000 P0}, as posts write it) never reads it, and the control runs it
        if (step <= 0 && span > eps) {
            host.out().error(Code.E180_PECK_NOT_POSITIVE, words.word(stepL).span(), name, words.word(stepL),
                    "the step between cuts");
            return null;
        }
        if (peck > depth + eps) {
            host.out().error(Code.E181_PECK_DEEPER_THAN_CUT, words.word(peckL).span(), name, words.word(peckL),
                    NumberText.plain(depth / perPeck, 4) + (alongX ? " on the radius" : " along Z"));
            return null;
        }
        boolean steps = span > eps;
        if (steps && Double.isNaN(step)) {
            host.out().error(Code.E185_STEP_MISSING, g.span(), name, NumberText.plain(span / perMmStep, 3),
                    alongX ? "Z" : "X", stepL + (haas ? " in the Haas form" : " in the Fanuc form"));
            return null;
        }
        if (steps && relief < 0) {
            host.out().error(Code.E184_RELIEF_SIGN, words.word(reliefL).span(), name, words.word(reliefL),
                    alongX ? "Z" : "X");
            return null;
        }
        if (steps && relief > step + eps) {
            host.out().error(Code.E183_RELIEF_TOO_LARGE, words.word(reliefL).span(), name, words.word(reliefL),
                    words.word(stepL));
            return null;
        }
        return new Cut(peckL, stepL, peck, step, relief, peckEnd, stepEnd, steps);
    }

    private static Word first(CycleWords words, Letter... letters) {
        Word best = null;
        for (Letter l : letters) {
            Word w = words.word(l);
            if (w != null && (best == null || w.span().compareTo(best.span()) < 0)) {
                best = w;
            }
        }
        return best;
    }

    private boolean isCycle(Word w) {
        if (w.number().isEmpty() || w.code() < 0 || w.code() > 999) {
            return false;
        }
        var f = host.functions().g((int) w.code());
        return f != null && (f.role().contourCycle() || f.role().singleCycle() || f.role().peckCycle()
                || f.role().drillCycle());
    }
}
