package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.geom.NumberText;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.MRole;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * The boring cycles on the spindle axis (docs/cycles.md), the moves {@link HoleDrilling} writes
 * for them once it has read their words: a rapid to the hole's X, a rapid to the R plane, the bar
 * fed to the bottom, and then
 * <ul>
 *   <li>Haas G85 (bore in, bore out), Fanuc G85 (face boring): fed back out to the R plane, with
 *       Fanuc's dwell P at the bottom first when it gives one;</li>
 *   <li>Haas G89 (bore in, dwell, bore out): the dwell P at the bottom, then fed out;</li>
 *   <li>Haas G86 (bore and stop): the spindle stopped at the bottom (M05), a rapid out, the
 *       spindle started again the way it turned (the Haas lathe manual says the spindle stops and
 *       the tool then retracts; that it turns again after the retract is read from the mill
 *       manual and LinuxCNC's G86, since the lathe manual is silent on it);</li>
 * </ul>
 * then a rapid to the return level (G98, Haas, Fanuc A: the initial level; Fanuc B G99: the R
 * plane). The feed out is the programmed F; where a control feeds out faster (a parameter), the
 * path is the same and only its time differs.
 */
final class HoleBoring {
    private static final double EPS_MM = 0.001;

    private HoleBoring() {
    }

    static List<CheckedBlock> bore(CycleHost host, GRole kind, String label, RawBlock b, Word at, ModalState start,
                                   double x, double rPlane, double bottom, double returnZ, Word dwell) {
        Point a = start.position();
        double epsX = EPS_MM * host.profile().x().countsPerMm();
        double epsZ = EPS_MM * host.profile().z().countsPerMm();
        List<Move> moves = new ArrayList<>(5);
        if (Math.abs(x - a.x()) > epsX) {
            moves.add(Move.line(true, new Point(x, a.z()), 1));
        }
        if (Math.abs(rPlane - a.z()) > epsZ) {
            moves.add(Move.line(true, new Point(x, rPlane), 1));
        }
        int in = moves.size();
        moves.add(Move.line(false, new Point(x, bottom), 1));
        boolean stop = kind == GRole.BORE_STOP_CYCLE;
        if (stop) {
            moves.add(Move.line(true, new Point(x, returnZ), 1));
        } else {
            moves.add(Move.line(false, new Point(x, rPlane), 1));
            if (Math.abs(returnZ - rPlane) > epsZ) {
                moves.add(Move.line(true, new Point(x, returnZ), 1));
            }
        }
        List<RawBlock> atBottom = new ArrayList<>(2);
        if (dwell != null && NumberText.decimal(dwell.number()) > 0) {
            String g04 = host.profile().control().gFor(GRole.DWELL).map(f -> f.name().substring(1)).orElseThrow();
            atBottom.add(new RawBlock(b.line(), List.of(new Word(Letter.G, g04, at.span()),
                    new Word(Letter.P, dwell.number(), at.span())), at.span(), false));
        }
        int turning = start.spindle();
        if (stop) {
            atBottom.add(spindle(host, b, MRole.SPINDLE_STOP, at));
        }
        java.util.Map<Integer, List<RawBlock>> after = new java.util.HashMap<>();
        if (!atBottom.isEmpty()) {
            after.put(in, atBottom);
        }
        if (stop && (turning == 3 || turning == 4)) {
            after.put(moves.size() - 1, List.of(spindle(host, b,
                    turning == 4 ? MRole.SPINDLE_CCW : MRole.SPINDLE_CW, at)));
        }
        return CycleBlocks.write(host, label, b.line(), at.span(), moves, 1, start, Map.copyOf(after));
    }

    /** A block of the spindle M code of {@code role} on this control, at the cycle's line. */
    static RawBlock spindle(CycleHost host, RawBlock b, MRole role, Word at) {
        int code = host.profile().control().mFor(role).orElseThrow().code();
        return new RawBlock(b.line(), List.of(new Word(Letter.M, String.format("%02d", code), at.span())), at.span(),
                false);
    }
}
