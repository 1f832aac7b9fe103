package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import java.util.ArrayList;
import java.util.List;

/** The moves of the tapping cycles on the spindle axis, which {@link HoleDrilling} writes once it has read their words. */
final class HoleTapping {
    private static final double EPS_MM = 0.001;

    private HoleTapping() {
    }

    /**
     * G84/G184 (Haas): a rapid to the hole's X, a rapid to the R plane, the tap fed to the bottom
     * (then the dwell P, if any), the spindle reversed (M04 after M03, M03 after M04), the tap fed
     * back out to the R plane, the spindle turned back, a rapid to {@code returnZ}, the initial level
     * (not under Fanuc B/C G99: the tap stays at the R plane). The feed is the F
     * in force (G99: the lead; G98: lead x r/min): gcnc does not gear the tap to the spindle, so the
     * tap must sit in a floating holder (docs/cycles.md). E629 when the spindle turns against the
     * tap (M04 for G84, M03 for G184).
     */
    static List<CheckedBlock> tap(CycleHost host, GRole kind, String name, RawBlock b, Word at, ModalState start,
                                  double x, double rPlane, double bottom, double returnZ, Word dwell, String label) {
        Point a = start.position();
        List<Move> moves = new ArrayList<>(5);
        if (Math.abs(x - a.x()) > EPS_MM * host.profile().x().countsPerMm()) {
            moves.add(Move.line(true, new Point(x, a.z()), 1));
        }
        moves.add(Move.line(true, new Point(x, rPlane), 1));
        int in = moves.size();
        moves.add(Move.line(false, new Point(x, bottom), 1));
        moves.add(Move.line(false, new Point(x, rPlane), 1));
        if (Math.abs(returnZ - rPlane) > EPS_MM * host.profile().z().countsPerMm()) {
            moves.add(Move.line(true, new Point(x, returnZ), 1)); // G98 (Haas, Fanuc A): the initial level
        }
        int turning = start.spindle();
        boolean rightHand = kind == GRole.TAP_CYCLE;
        if (turning == (rightHand ? 4 : 3)) {
            host.out().report(gcnc.diag.Diagnostic.warning(Code.E629_TAP_AGAINST_SPINDLE, at.span(), label,
                    rightHand ? "M04" : "M03", rightHand ? "M03" : "M04"));
        }
        gcnc.machine.MRole forward = turning == 4 ? gcnc.machine.MRole.SPINDLE_CCW : gcnc.machine.MRole.SPINDLE_CW;
        gcnc.machine.MRole back = forward == gcnc.machine.MRole.SPINDLE_CW ? gcnc.machine.MRole.SPINDLE_CCW
                : gcnc.machine.MRole.SPINDLE_CW;
        List<RawBlock> bottomBlocks = new ArrayList<>(2);
        if (dwell != null && NumberText.decimal(dwell.number()) > 0) {
            String g04 = host.profile().control().gFor(GRole.DWELL).map(f -> f.name().substring(1)).orElseThrow();
            bottomBlocks.add(new RawBlock(b.line(), List.of(new Word(Letter.G, g04, at.span()),
                    new Word(Letter.P, dwell.number(), at.span())), at.span(), false));
        }
        bottomBlocks.add(HoleBoring.spindle(host, b, back, at));
        return CycleBlocks.write(host, name, b.line(), at.span(), moves, 1, start,
                java.util.Map.of(in, bottomBlocks, in + 1, List.of(HoleBoring.spindle(host, b, forward, at))));
    }
}
