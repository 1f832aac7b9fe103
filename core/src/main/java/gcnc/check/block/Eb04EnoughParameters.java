package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;

/**
 * Thesis end-of-block operation 4: a function has the parameters it needs. G04 needs X, U or P;
 * G28, G29, G53 and G92 an axis word (30; a bare G28 homes both axes where the control says so,
 * Haas); G50 (Fanuc B: G92) S or X/Z (31); G96 without S runs on the S in force, read as the
 * surface speed (writes next.surfaceSpeed; Advisories warns, E648); G02/G03 R or I/K in the block (49; the thesis reused a modal R, and
 * raised 52 for a missing I/K, §12.10). Each is reported at the function that lacks its
 * parameters (the G04, G28, G50, G96, or the arc's G02/G03), not at the last word. Emits E030, E031, E049.
 */
public final class Eb04EnoughParameters implements BlockCheck {
    @Override
    public void run(BlockDraft d, Diagnostics out) {
        boolean axis = d.has(Letter.X) || d.has(Letter.Z) || d.has(Letter.U) || d.has(Letter.W);
        switch (d.function) {
            case 4 -> {
                if (!d.has(Letter.X) && !d.has(Letter.U) && !d.has(Letter.P)) {
                    d.fail(out, Code.E030_PARAMETER_EXPECTED, d.oneShotWord.span(), "G04");
                }
            }
            case 28, 29, 53, 92 -> {
                gcnc.machine.Control.BareG28 bare = d.function == 28 ? d.functions.control().bareG28()
                        : gcnc.machine.Control.BareG28.ERROR;
                if (!axis && bare == gcnc.machine.Control.BareG28.NOTHING) {
                    // Fanuc: a G28 returns the axes it names; naming none moves nothing (no alarm)
                    out.report(gcnc.diag.Diagnostic.warning(Code.E704_BARE_G28_MOVES_NOTHING, d.oneShotWord.span(),
                            d.ownerName()));
                } else if (!axis && bare == gcnc.machine.Control.BareG28.ERROR) {
                    d.fail(out, Code.E030_PARAMETER_EXPECTED, d.oneShotWord.span(), d.ownerName());
                }
            }
            case 50 -> {
                if (!axis && !d.has(Letter.S)) {
                    d.fail(out, Code.E031_S_EXPECTED, d.oneShotWord.span(), d.ownerName());
                }
            }
            case 2, 3 -> {
                if (!d.has(Letter.R) && !d.has(Letter.I) && !d.has(Letter.K)) {
                    d.fail(out, Code.E049_NO_ARC_RADIUS, d.blame());
                }
            }
            default -> {
            }
        }
        if (d.g96 != null && !d.has(Letter.S) && !d.prior.css() && !Double.isNaN(d.prior.rpm())) {
            // the control keeps one S: G96 alone reads the S in force, given as r/min, as the
            // surface speed until the next S (Fusion's Haas post writes G96 and its S on separate
            // lines; warning E648 when a cut comes first, gcnc.check.Advisories). Before any S there
            // is nothing to take: the S of a later block sets it.
            d.next.surfaceSpeed = d.prior.rpm();
        }
    }
}
