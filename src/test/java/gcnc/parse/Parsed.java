package gcnc.parse;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;
import java.io.IOException;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

/** Test helper: everything BlockReader makes of one source text. */
record Parsed(List<RawBlock> blocks, List<Diagnostic> diagnostics, int lines) {

    static Parsed of(String source) {
        return of(source, false);
    }

    /** With {@code lineComments}: as a Haas or Fanuc control reads comments (they end at their line's end). */
    static Parsed of(String source, boolean lineComments) {
        Diagnostics diagnostics = new Diagnostics();
        BlockReader reader = new BlockReader(new StringReader(source), diagnostics, true, false, lineComments,
                gcnc.diag.Origin.PROGRAM);
        List<RawBlock> blocks = new ArrayList<>();
        try {
            for (RawBlock b = reader.next(); b != null; b = reader.next()) {
                blocks.add(b);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return new Parsed(blocks, diagnostics.sorted(), reader.lines());
    }

    /** Diagnostics as "line:column E<n> args", easy to compare. */
    List<String> errors() {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : diagnostics) {
            out.add(d.span().line() + ":" + d.span().column() + " " + d.code().id() + " " + d.args());
        }
        return out;
    }

    /** Blocks as "line: words", "line: /level words" when marked for block delete, "!" when malformed. */
    List<String> shapes() {
        List<String> out = new ArrayList<>();
        for (RawBlock b : blocks) {
            StringBuilder sb = new StringBuilder().append(b.line()).append(':');
            if (b.blockDelete() > 0 && b.deleteColumn() == 0) {
                sb.append(" /").append(b.blockDelete());
            }
            boolean marked = b.deleteColumn() == 0;
            for (gcnc.ir.Word w : b.words()) {
                if (!marked && w.span().column() > b.deleteColumn()) {
                    sb.append(" /").append(b.blockDelete()); // a '/' in the middle, where it stands
                    marked = true;
                }
                sb.append(' ').append(w); // ",C1." for a comma word
            }
            if (!marked) {
                sb.append(" /").append(b.blockDelete());
            }
            out.add(b.malformed() ? sb.append(" !").toString() : sb.toString());
        }
        return out;
    }
}
