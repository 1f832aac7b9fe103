package gcnc;

import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.Units;
import gcnc.parse.BlockReader;
import java.io.IOException;
import java.io.Reader;
import java.util.Optional;

/**
 * The units a program says it is written in, for the options read before it (a {@code --stock} value
 * without a unit, the plugin's {@code stock}): the first inch or metric word of its control (G20 or
 * G21 on Haas and Fanuc) in its head, read by gcnc's own parser, before its first axis word. A program
 * that says neither there gets no answer: its units are the control's power-up state, which a blank
 * given on the command line should not silently follow. Nothing is reported: the program's findings
 * come from its check.
 */
public final class ProgramUnits {
    /** The blocks looked at, at most: a program's units come in its first lines. */
    private static final int LOOK = 200;

    /** What the program said, and where: {@code G20} at line 2. */
    public record Declared(Units units, String word, int line) {
    }

    private ProgramUnits() {
    }

    /** The program's declared units, or empty when its head says neither (or a motion comes first). */
    public static Optional<Declared> of(Reader program, Control control) throws IOException {
        BlockReader blocks = new BlockReader(program, new Diagnostics());
        for (int i = 0; i < LOOK; i++) {
            RawBlock b = blocks.next();
            if (b == null) {
                break;
            }
            boolean axis = false;
            for (Word w : b.words()) {
                if (w.letter() == Letter.G && w.code() >= 0 && w.code() < Integer.MAX_VALUE) {
                    GFunction f = control.g().get((int) w.code());
                    if (f != null && (f.role() == GRole.INCH || f.role() == GRole.METRIC)) {
                        return Optional.of(new Declared(f.role() == GRole.INCH ? Units.INCH : Units.MM, w.toString(),
                                b.line()));
                    }
                }
                axis |= w.letter() == Letter.X || w.letter() == Letter.Z || w.letter() == Letter.U || w.letter() == Letter.W;
            }
            if (axis) {
                break;
            }
        }
        return Optional.empty();
    }
}
