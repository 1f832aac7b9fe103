package gcnc;

import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.parse.BlockReader;
import java.io.IOException;
import java.io.Reader;
import java.util.Optional;

/**
 * A program's number as its header writes it ({@code O1201}, Fanuc's tape form {@code :1201}
 * read as O), for a drawing's title block and a setup sheet: the O word that starts one of the
 * first blocks, read by gcnc's own parser. Nothing is reported: the program's findings come from
 * its check, not from this look at its head.
 */
public final class ProgramNumber {
    /** How many blocks may come before the header (a '%' line, a comment or two, a stock header). */
    private static final int LOOK = 8;

    private ProgramNumber() {
    }

    /** "O1201", or empty when none of the first blocks starts with an O word. */
    public static Optional<String> of(Reader program) throws IOException {
        BlockReader blocks = new BlockReader(program, new Diagnostics());
        for (int i = 0; i < LOOK; i++) {
            RawBlock b = blocks.next();
            if (b == null) {
                break;
            }
            if (!b.words().isEmpty() && b.words().get(0).letter() == Letter.O) {
                return Optional.of("O" + b.words().get(0).number());
            }
        }
        return Optional.empty();
    }
}
