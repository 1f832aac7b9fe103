package gcnc.send;

import gcnc.dmc.Command;
import java.util.ArrayList;
import java.util.List;

/**
 * What is downloaded at once: the whole program, one step's block, or a resume program; each of its
 * lines with the compiled program's line it stands for ({@code origin}, 0-based), so that what the
 * controller executes always maps back to the G-code through the one source map.
 */
public record Piece(List<Command> commands, int[] origin, List<String> lines) {
    public Piece {
        commands = List.copyOf(commands);
        lines = List.copyOf(lines);
        if (origin.length != commands.size() || lines.size() != commands.size()) {
            throw new IllegalArgumentException("a line without its origin");
        }
    }

    /** The commands, each printed once ({@link gcnc.dmc.DmcPrinter}): the lines downloaded. */
    public Piece(List<Command> commands, int[] origin) {
        this(commands, origin, commands.stream().map(gcnc.dmc.DmcPrinter::print).toList());
    }

    /** The whole program. */
    public static Piece whole(DmcProgram p) {
        int[] o = new int[p.lines().size()];
        List<Command> c = new ArrayList<>(o.length);
        for (int i = 0; i < o.length; i++) {
            o[i] = i;
            c.add(p.command(i));
        }
        return new Piece(c, o, p.lines());
    }

    /** The compiled program's line for the controller's line {@code n} (0-based), or -1. */
    public int originOf(int n) {
        return n >= 0 && n < origin.length ? origin[n] : -1;
    }

    /**
     * The vector sequence the controller's line {@code n} is in, as this piece gives it: the compiled
     * lines its segments stand for, in the controller's order (segment k of the sequence, {@code _CSS}
     * = k, is {@code origins[k - 1]}), and whether line {@code n} is at or past its {@code BGS} (the
     * motion has begun). Null when line {@code n} is in no vector sequence.
     */
    public Segments segmentsAt(int n, DmcProgram program) {
        int start = n;
        for (; start >= 0; start--) {
            Command c = program.command(originOf(start));
            if (c instanceof Command.VectorSpeed) {
                break;
            }
            if (start != n && (c instanceof Command.AwaitSequence || c instanceof Command.AfterMotion
                    || c instanceof Command.End)) {
                return null;
            }
        }
        if (start < 0) {
            return null;
        }
        List<Integer> origins = new ArrayList<>();
        boolean begun = false;
        for (int j = start + 1; j < lines.size(); j++) {
            Command c = program.command(originOf(j));
            if (c instanceof Command.AwaitSequence) {
                break;
            }
            if (DmcProgram.isSegment(c)) {
                origins.add(originOf(j));
            } else if (c instanceof Command.BeginSequence && j <= n) {
                begun = true;
            }
        }
        return new Segments(origins.stream().mapToInt(Integer::intValue).toArray(), begun);
    }

    /** The segments of one vector sequence of a piece: see {@link #segmentsAt}. */
    public record Segments(int[] origins, boolean begun) {
        /** The compiled line of the segment executing when the controller's {@code _CSS} reads {@code css}. */
        public int executing(int css) {
            return origins[Math.max(0, Math.min(origins.length - 1, css - 1))];
        }
    }

    /** Builds a piece line by line. */
    public static final class Builder {
        private final List<Command> commands = new ArrayList<>();
        private final List<Integer> origin = new ArrayList<>();

        public Builder add(Command command, int from) {
            commands.add(command);
            origin.add(from);
            return this;
        }

        public int size() {
            return commands.size();
        }

        public Piece build() {
            return new Piece(commands, origin.stream().mapToInt(Integer::intValue).toArray());
        }
    }
}
