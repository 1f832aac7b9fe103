package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The single-pass cycles G90 (turning along Z) and G94 (facing along X) of Fanuc system A and
 * Haas (Fanuc system B: G77, G79), as four checked moves from the start point A: for G90 a rapid
 * in X to the cut's diameter, a feed to the end point (X, Z), a feed out in X to A's diameter and a
 * rapid back in Z; for G94 the same with the axes swapped. A taper is R (Fanuc; Haas I for G90, K
 * for G94): the cut's start minus its end, X a radius. The cycle is modal in its group: a later
 * block with X, U, Z or W and no G of that group makes it again, with the words it does not give
 * (the other end coordinate, the taper) as before; a G of the group ends it (docs/cycles.md).
 */
final class SingleCycle extends ModalExpansion {
    /** The end point of the cycle in force, counts, and its taper (counts along X for G90, Z for G94). */
    private Point end;
    private double taper;

    SingleCycle(CycleHost host) {
        super(host, new ModalCycle());
    }

    /** A G90/G94 block ({@code g} its cycle word) or a block that makes the cycle in force again (g null). */
    @Override
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        GRole role = role(g);
        String label = label(g);
        Letter taperWord = role == GRole.TURNING_SINGLE_CYCLE ? Letter.I : Letter.K;
        List<Word> axes = new ArrayList<>();
        List<Word> passOn = new ArrayList<>();
        Word taperGiven = null;
        Word foreign = null;
        for (Word w : b.words()) {
            if (w == g) {
                continue;
            }
            switch (w.letter()) {
                case X, U, Z, W -> axes.add(w);
                case N, F, S, T, M -> passOn.add(w);
                case G -> foreign = otherG(w, passOn, foreign);
                default -> {
                    if ((w.letter() == Letter.R || w.letter() == taperWord) && taperGiven == null) {
                        taperGiven = w;
                    } else {
                        foreign = foreign == null ? w : foreign;
                    }
                }
            }
        }
        List<CheckedBlock> done = new ArrayList<>();
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        Word at = g != null ? g : axes.get(0);
        if (foreign != null) {
            host.out().error(Code.E161_CYCLE_WORD, foreign.span(), label, foreign);
            return done;
        }
        boolean x = has(axes, Letter.X, Letter.U);
        boolean z = has(axes, Letter.Z, Letter.W);
        if (g != null && axes.isEmpty() && taperGiven == null) {
            // a bare G90/G94: a safe-start line written for a mill or Fanuc system B, where G90 is
            // absolute. The control takes the block and moves nothing (E645); gcnc does not keep the
            // cycle in force (no end point to repeat)
            host.out().report(gcnc.diag.Diagnostic.warning(Code.E645_CYCLE_WITHOUT_END_POINT, g.span(), label));
            modal.end();
            return done;
        }
        if (g != null && (!x || !z)) {
            host.out().error(Code.E169_SINGLE_CYCLE_END_MISSING, g.span(), label);
            modal.end();
            return done;
        }
        ModalState start = host.state();
        Point reached = target(b, axes, start);
        if (reached == null) {
            return done;
        }
        if (g != null) {
            modal.start(role, function(g), label);
            taper = 0;
        }
        end = new Point(x ? reached.x() : end.x(), z ? reached.z() : end.z());
        if (taperGiven != null) {
            double v = NumberText.decimal(taperGiven.number());
            if (Double.isNaN(v)) {
                host.out().error(Code.E014_DECIMAL_EXPECTED, taperGiven.span(), taperGiven.letter());
                return done;
            }
            Units u = start.units();
            if (!NumberText.hasPoint(taperGiven.number())) {
                v *= u == Units.INCH ? host.profile().noPointInch() : host.profile().noPointMm();
            }
            Coordinates c = host.coordinates();
            taper = v * (modal.kind() == GRole.TURNING_SINGLE_CYCLE ? c.perRadius(u) : c.perZ(u));
        }
        return moves(done, start, at, b.line());
    }

    private static boolean has(List<Word> words, Letter a, Letter b) {
        return words.stream().anyMatch(w -> w.letter() == a || w.letter() == b);
    }

    /** Where the block's axis words lead from the start (a rapid followed aside), or null after its error. */
    private Point target(RawBlock b, List<Word> axes, ModalState start) {
        return CycleBlocks.target(host, b, axes, start);
    }

    /** The cycle's four moves from the start, written and checked; after one fails, back to the start. */
    private List<CheckedBlock> moves(List<CheckedBlock> done, ModalState start, Word at, int line) {
        Point a = start.position();
        Point[] path;
        if (modal.kind() == GRole.TURNING_SINGLE_CYCLE) {
            path = new Point[] {new Point(end.x() + taper, a.z()), end, new Point(a.x(), end.z()), a};
        } else {
            path = new Point[] {new Point(a.x(), end.z() + taper), end, new Point(end.x(), a.z()), a};
        }
        boolean[] rapid = {true, false, false, true};
        MoveWriter writer = new MoveWriter(CycleBlocks.frame(host, start), line, at.span());
        CycleOrigin origin = CycleOrigin.single(modal.name(), line);
        Point from = a;
        for (int i = 0; i < path.length; i++) {
            if (path[i].distanceTo(from) <= 1e-9) {
                continue;
            }
            Optional<CheckedBlock> r = host.one(writer.block(Move.line(rapid[i], path[i], 1), from), false, origin);
            if (r.isEmpty()) {
                CycleBlocks.abandon(host, writer, a, origin).ifPresent(done::add);
                break;
            }
            done.add(r.get());
            from = host.state().position();
        }
        return done;
    }
}
