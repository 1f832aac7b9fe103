package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.ProgramFrame;
import java.util.List;

/**
 * Where a block that a cycle made (or follows again) comes from: "G71 pass 4 of 9" of the cycle
 * at {@code cycleLine} with the contour N(p)..N(q). {@code again}: a contour block that G70
 * follows again (its findings of the first reading are not repeated, its N is not a repeat).
 */
record CycleOrigin(String cycle, int pass, int passes, int cycleLine, long p, long q, boolean again) {

    /** A G90/G94 single-pass cycle: one pass, no contour; its findings are on its own block already. */
    static CycleOrigin single(String cycle, int line) {
        return new CycleOrigin(cycle, 1, 1, line, -1, -1, false);
    }

    /** {@code p} of a thread cycle's pass: no contour; the note names the depth instead (E199). */
    private static final long THREAD = -2;

    /** A pass of a thread cycle (G76, G92/G78), {@code depth} its depth as the note prints it. */
    static CycleOrigin thread(String cycle, int pass, int passes, int line, long depthMicrons) {
        return new CycleOrigin(cycle, pass, passes, line, THREAD, depthMicrons, false);
    }

    /** Whether a finding in the block gets the note: not for a single-pass cycle (p = -1). */
    boolean noted() {
        return p >= 0 || p == THREAD;
    }

    /** The note after each finding in the block (E165; E199 for a thread pass). */
    Diagnostic note(Span at) {
        if (p == THREAD) {
            return new Diagnostic(Code.E199_THREAD_PASS, Severity.NOTE, at, List.of(cycle, Integer.toString(pass),
                    Integer.toString(passes), Integer.toString(cycleLine),
                    gcnc.check.geom.NumberText.plain(q / 1e6, 4)));
        }
        return new Diagnostic(Code.E165_CYCLE_PASS, Severity.NOTE, at, List.of(cycle, Integer.toString(pass),
                Integer.toString(passes), Integer.toString(cycleLine), Long.toString(p), Long.toString(q)));
    }

    /** The checked block with the pass as its sequence, for the simulator's findings. */
    CheckedBlock label(CheckedBlock b) {
        ProgramFrame f = b.frame();
        if (f == null) {
            return b;
        }
        String name = cycle + " pass " + pass + " of " + passes;
        ProgramFrame labelled = f.inPass(name);
        return b.inFrame(labelled);
    }
}
