package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.tables.Tables.Param;
import java.util.Set;

/**
 * Thesis end-of-block operation 1: the block's parameters belong to a function (Table 7). The
 * function is the block's one-shot G, else its motion G, else (axis words only) the modal motion;
 * axis words with no motion in force are 44, a P with no function 32. Then Table 7, which was dead
 * code in the thesis (§12.1): X 21, Z 22, U 23, W 24, R 25, I 26, K 27, X with U 28, Z with W 29,
 * P 36. Each at the word to blame: 44 at the first axis word, 32 at the P. Emits E021-E029, E032,
 * E036, E044; an M19's orientation angle P or R is the M19's (SpindleOrientAngle, E703). Writes d.function.
 */
public final class Eb01ParameterOwner implements BlockCheck {
    private static final Letter[] ORDER = {Letter.X, Letter.Z, Letter.U, Letter.W, Letter.R, Letter.I, Letter.K};
    private static final Code[] NOT_ALLOWED = {Code.E021_X_NOT_ALLOWED, Code.E022_Z_NOT_ALLOWED,
        Code.E023_U_NOT_ALLOWED, Code.E024_W_NOT_ALLOWED, Code.E025_R_NOT_ALLOWED, Code.E026_I_NOT_ALLOWED,
        Code.E027_K_NOT_ALLOWED};
    private static final Param[] PARAMS = {Param.X, Param.Z, Param.U, Param.W, Param.R, Param.I, Param.K};

    @Override
    public void run(BlockDraft d, Diagnostics out) {
        if (SpindleOrientAngle.owns(d, out)) {
            return; // Haas M19 P/R: the angle is the M19's (E703)
        }
        int mov = d.motionWords();
        if (d.oneShot != BlockDraft.NONE) {
            d.function = d.oneShot;
        } else if (d.motionG != BlockDraft.NONE) {
            d.function = d.motionG;
        } else if (mov > 0) {
            if (d.prior.motion() == BlockDraft.NONE) {
                Word w = d.firstMotionWord();
                d.fail(out, Code.E044_NO_MOTION_G, w.span(), w.letter());
                return;
            }
            d.function = d.prior.motion();
        } else if (d.has(Letter.P) && !liveToolSpeed(d)) {
            d.fail(out, Code.E032_UNASSOCIATED_PARAMETER, d.word(Letter.P).span(), Letter.P);
            return;
        }
        if (d.function != BlockDraft.NONE) {
            allowed(d, out);
        }
        if (!d.failed()) {
            unused(d, out);
        }
    }

    /**
     * A P beside a C-axis or live-tool M code (Haas {@code M133 P1500}: the live tool's r/min): the
     * code's own word, which the control runs with it and gcnc, driving nothing for it, reads no further.
     */
    private static boolean liveToolSpeed(BlockDraft d) {
        java.util.List<gcnc.ir.Word> ws = d.block.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            gcnc.ir.Word w = ws.get(at);
            if (w.letter() == Letter.M && !w.number().isEmpty()) {
                gcnc.machine.MFunction f = d.functions.m(w.code());
                if (f != null && f.role() == gcnc.machine.MRole.AXIS_OPTION) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * Grbl's "unused words": a letter the control reads for its cycles and threads (Q, D, A, E ...)
     * that no function of this block takes is E108, naming it (never ignored).
     */
    private static void unused(BlockDraft d, Diagnostics out) {
        java.util.List<Word> ws = d.block.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            if (!THESIS_LETTERS.contains(w.letter())) {
                String owner = d.function != BlockDraft.NONE ? d.ownerName() : "parameterless";
                d.fail(out, Code.E108_WORD_NOT_USED, w.span(), w.letter(), owner);
                return;
            }
        }
    }

    /** The thesis's letters; the others belong to functions gcnc does not support yet. */
    private static final java.util.Set<Letter> THESIS_LETTERS = java.util.EnumSet.of(Letter.N, Letter.O, Letter.G,
            Letter.M, Letter.X, Letter.Z, Letter.U, Letter.W, Letter.I, Letter.K, Letter.R, Letter.P, Letter.S,
            Letter.F, Letter.T);

    private static void allowed(BlockDraft d, Diagnostics out) {
        Set<Param> ok = d.functions.allowed(d.owner());
        if (ok == null) {
            return;
        }
        for (int i = 0; i < ORDER.length; i++) {
            if (d.has(ORDER[i]) && !ok.contains(PARAMS[i])) {
                d.fail(out, NOT_ALLOWED[i], d.word(ORDER[i]).span(), d.ownerName());
                return;
            }
        }
        if (d.has(Letter.X) && d.has(Letter.U)) {
            d.fail(out, Code.E028_X_AND_U, d.word(Letter.U).span());
        } else if (d.has(Letter.Z) && d.has(Letter.W)) {
            d.fail(out, Code.E029_Z_AND_W, d.word(Letter.W).span());
        } else if (d.has(Letter.P) && !ok.contains(Param.P)) {
            d.fail(out, Code.E036_P_NOT_ALLOWED, d.word(Letter.P).span(), d.ownerName());
        }
    }
}
