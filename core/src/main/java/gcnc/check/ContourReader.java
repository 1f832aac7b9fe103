package gcnc.check;

import gcnc.check.cycle.Contour;
import gcnc.check.cycle.CycleCall;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import java.util.ArrayList;
import java.util.List;
import java.util.function.IntFunction;

/**
 * The contour N(P)..N(Q) of a cycle, followed from the cycle's start without changing the
 * program's state (shared by G71 and G72; G70 follows the same blocks again as ordinary blocks).
 * Each block is checked aside: its own errors are reported on its own line, once; what a contour
 * cannot hold is E162. Its chamfers and corners were made before ({@link CornerInsertion#inContour}).
 */
final class ContourReader {
    private final CycleHost host;
    private final IntFunction<GRole> role;

    ContourReader(CycleHost host, IntFunction<GRole> role) {
        this.host = host;
        this.role = role;
    }

    /**
     * Follows the contour blocks from the cycle's start, each checked aside (E162 for what a
     * contour cannot hold); their moves, or null when a block has an error.
     */
    List<Contour.Piece> follow(CycleCall call, int line, List<RawBlock> blocks, ModalState start) {
        List<Contour.Piece> pieces = new ArrayList<>();
        ModalState s = start;
        boolean ok = true;
        for (RawBlock b : blocks) {
            if (b.malformed()) {
                ok = false;
                continue;
            }
            Word foreign = foreign(b);
            if (foreign != null) {
                host.out().error(Code.E162_CONTOUR_WORD, foreign.span(), call.name(), line, foreign);
                ok = false;
                continue;
            }
            Diagnostics found = new Diagnostics();
            Dry dry = host.dry(b, s, found);
            host.reportAside(found);
            if (dry == null) {
                ok = false;
                continue;
            }
            s = dry.next();
            for (Motion m : dry.block().motions()) {
                pieces.add(new Contour.Piece(m, b.line()));
            }
        }
        return ok ? pieces : null;
    }

    /** The first word of a contour block that a contour cannot hold: an M, a T, a G other than a move. */
    private Word foreign(RawBlock b) {
        for (Word w : b.words()) {
            if (w.letter() == Letter.M || w.letter() == Letter.T) {
                return w;
            }
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                GRole r = role.apply((int) w.code());
                if (r != null && !r.motion() && r != GRole.NOSE_COMP_CANCEL && r != GRole.NOSE_COMP_LEFT
                        && r != GRole.NOSE_COMP_RIGHT && r != GRole.CSS && r != GRole.RPM) {
                    return w;
                }
            }
        }
        return null;
    }

}
