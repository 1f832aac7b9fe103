package gcnc.galil;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The side file that maps DMC output lines back to G-code lines when the map is not inline
 * (docs/dmc-format.md): one "{@code <dmc line> <source line>}" per output line that came from a
 * block, both 1-based; header and footer lines (source line 0) are not listed.
 * Wrap the sink the dialect writes to with {@link #wrap}.
 */
public final class SourceMap {
    private int dmcLines;
    private int[] pairs = new int[256];
    private int size;

    /** A sink that numbers the lines passing to {@code out} and remembers where each came from. */
    public LineSink wrap(LineSink out) {
        return line -> {
            dmcLines++;
            if (line.sourceLine() > 0) {
                add(dmcLines, line.sourceLine());
            }
            out.accept(line);
        };
    }

    private void add(int dmc, int source) {
        if (size + 2 > pairs.length) {
            pairs = Arrays.copyOf(pairs, pairs.length * 2);
        }
        pairs[size++] = dmc;
        pairs[size++] = source;
    }

    /** The map file's lines, in output order. */
    public List<String> lines() {
        List<String> out = new ArrayList<>(size / 2);
        for (int i = 0; i < size; i += 2) {
            out.add(pairs[i] + " " + pairs[i + 1]);
        }
        return out;
    }
}
