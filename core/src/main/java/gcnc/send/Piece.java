package gcnc.send;

import java.util.ArrayList;
import java.util.List;

/**
 * What is downloaded at once: the whole program, one step's block, or a resume program; each of its
 * lines with the compiled program's line it stands for ({@code origin}, 0-based), so that what the
 * controller executes always maps back to the G-code through the one source map.
 */
public record Piece(List<String> lines, int[] origin) {
    public Piece {
        lines = List.copyOf(lines);
        if (origin.length != lines.size()) {
            throw new IllegalArgumentException("a line without its origin");
        }
    }

    /** The whole program. */
    public static Piece whole(DmcProgram p) {
        int[] o = new int[p.lines().size()];
        for (int i = 0; i < o.length; i++) {
            o[i] = i;
        }
        return new Piece(p.lines(), o);
    }

    /** The compiled program's line for the controller's line {@code n} (0-based), or -1. */
    public int originOf(int n) {
        return n >= 0 && n < origin.length ? origin[n] : -1;
    }

    /** Builds a piece line by line. */
    public static final class Builder {
        private final List<String> lines = new ArrayList<>();
        private final List<Integer> origin = new ArrayList<>();

        public Builder add(String line, int from) {
            lines.add(line);
            origin.add(from);
            return this;
        }

        public int size() {
            return lines.size();
        }

        public Piece build() {
            return new Piece(lines, origin.stream().mapToInt(Integer::intValue).toArray());
        }
    }
}
