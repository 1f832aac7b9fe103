package gcnc.galil;

import java.util.function.Consumer;

/**
 * The side file that maps DMC output lines back to G-code lines when the map is not inline
 * (docs/dmc-format.md): one "{@code <dmc line> <source line>}" per output line that came from a
 * block, both 1-based; header and footer lines (source line 0) are not listed. The map lines are
 * handed on as they arise, so memory stays flat however long the program.
 */
public final class SourceMap {
    private final Consumer<String> mapLines;
    private int dmcLines;

    /** @param mapLines receives each line of the map file, in output order */
    public SourceMap(Consumer<String> mapLines) {
        this.mapLines = mapLines;
    }

    /** A sink that numbers the lines passing to {@code out} and reports where each came from. */
    public LineSink wrap(LineSink out) {
        return line -> {
            dmcLines++;
            if (line.sourceLine() > 0) {
                mapLines.accept(dmcLines + " " + line.sourceLine());
            }
            out.accept(line);
        };
    }

    /** How many DMC lines have passed. */
    public int lines() {
        return dmcLines;
    }
}
