package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import java.util.BitSet;
import java.util.List;

/**
 * The warnings a committed block gives for what the program did before: an M code without output
 * (E113, once per code) and a repeated N (E114, on controls where N may repeat).
 */
final class RepeatWarnings {
    private final MachineProfile profile;
    private final Diagnostics out;
    /** M codes already warned about (E113), N numbers seen (E114, controls where N may repeat). */
    private final BitSet warnedM = new BitSet();
    private final BitSet seenN = new BitSet();

    RepeatWarnings(MachineProfile profile, Diagnostics out) {
        this.profile = profile;
        this.out = out;
    }

    /** E113 for each of the block's M codes without output not warned about before. */
    void unpowered(BlockDraft d) {
        List<Word> ws = d.unpowered();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            int m = (int) w.code();
            if (!warnedM.get(m)) {
                warnedM.set(m);
                out.report(Diagnostic.warning(Code.E113_M_WITHOUT_OUTPUT, w.span(), m, profile.name()));
            }
        }
    }

    /** A repeated N (E114) where N may repeat; remembers the block's N. */
    void sequence(BlockDraft d) {
        if (d.has(Letter.N) && !profile.control().increasingN() && d.block.depth() == 0) {
            long n = (long) d.value(Letter.N);
            if (n >= 0 && n < Integer.MAX_VALUE) {
                if (seenN.get((int) n)) {
                    Word w = d.word(Letter.N);
                    out.report(Diagnostic.warning(Code.E114_DUPLICATE_SEQUENCE_NUMBER, w.span(), w.number()));
                }
                seenN.set((int) n);
            }
        }
    }

    /** Takes what {@code other} has seen so far (the other position of the block delete switch). */
    void takeFrom(RepeatWarnings other) {
        seenN.or(other.seenN);
        warnedM.or(other.warnedM);
    }
}
