package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The closing '%' ends the tape (docs/language.md): a control stops reading there, and so does the
 * reader gcnc gives a control ({@link BlockReader#forControl}). Text after it is not read, with the
 * note E705 once; a program after it (an O word: a file with several programs) is read again; a
 * lone DOS end-of-file byte is silent. The grammar's reader (the other constructors) reads on.
 */
class TapeEndTest {
    private static final String MAIN = "%\nO1000\nG00 X10.\nM30\n%\n";

    /** The lines of the blocks read, then the findings as "line:column code". */
    private static String read(String text, boolean control) throws Exception {
        Diagnostics d = new Diagnostics();
        BlockReader r = control ? BlockReader.forControl(new StringReader(text), d, false)
                : new BlockReader(new StringReader(text), d);
        List<String> out = new ArrayList<>();
        for (RawBlock b = r.next(); b != null; b = r.next()) {
            out.add(Integer.toString(b.line()));
        }
        for (Diagnostic f : d.sorted()) {
            out.add(f.span().line() + ":" + f.span().column() + " " + f.code().id() + " " + f.severity());
        }
        return String.join(" ", out);
    }

    @Test
    void textAfterTheClosingPercentIsNotReadWithOneNote() throws Exception {
        assertEquals("2 3 4 6:3 E705 NOTE", read(MAIN + "  JUNK TEXT\nmore junk\nG01 X5.\n", true));
        // the grammar's reader reads it (and finds the text)
        assertEquals("2 3 4 6 7 8 6:3 E109 ERROR 7:1 E109 ERROR", read(MAIN + "  JUNK TEXT\nmore junk\nG01 X5.\n", false));
    }

    @Test
    void aProgramAfterTheClosingPercentIsRead() throws Exception {
        assertEquals("2 3 4 6 7 8", read(MAIN + "O2000\nG00 X5.\nM99\n%\n", true));
        assertEquals("2 3 4 7 8 9 6:1 E705 NOTE", read(MAIN + "(SUB)\nO2000\nG00 X5.\nM99\n%\n", true));
        assertEquals("2 3 4 7 8", read(MAIN + "%\n:2000\nM99\n", true));
    }

    @Test
    void aDosEndOfFileByteAndBlankLinesAreSilent() throws Exception {
        assertEquals("2 3 4", read(MAIN + "\u001a", true));
        assertEquals("2 3 4", read(MAIN + "\n  \n\u001a\n", true));
    }

    @Test
    void aPercentBeforeTheFirstBlockIsTheTapesStart() throws Exception {
        assertEquals("3 4", read("\n%\nO1000\nM30\n", true));
        // a '%' inside a block's line is the rest of the line ignored, as before
        assertEquals("2 3 4", read("%\nO1000\nG00 X10. %\nM30\n", true));
    }
}
