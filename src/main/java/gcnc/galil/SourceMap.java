package gcnc.galil;

import java.util.function.Consumer;

/**
 * The side file that traces DMC output lines back to G-code lines when the map is not inline
 * (docs/dmc-format.md). Like a line-number table, it has one "{@code <dmc line> <source line>}"
 * entry where a run of output lines from one source line starts; the run goes on to the line
 * before the next entry. Source line 0 marks lines from no block (header, footer). Entries are
 * handed on as they arise, so memory stays flat however long the program.
 */
public final class SourceMap {
    private final Consumer<String> mapLines;
    private int dmcLines;
    private int lastSource = -1;

    /** @param mapLines receives each line of the map file, in output order */
    public SourceMap(Consumer<String> mapLines) {
        this.mapLines = mapLines;
    }

    /** A sink that numbers the lines passing to {@code out} and records where each run came from. */
    public LineSink wrap(LineSink out) {
        return line -> {
            dmcLines++;
            if (line.sourceLine() != lastSource) {
                lastSource = line.sourceLine();
                mapLines.accept(dmcLines + " " + lastSource);
            }
            out.accept(line);
        };
    }

    /** How many DMC lines have passed. */
    public int lines() {
        return dmcLines;
    }
}
