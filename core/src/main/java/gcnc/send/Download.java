package gcnc.send;

import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.dmc.LinePacker;
import gcnc.dmc.SequencePart;
import gcnc.dmc.Source;
import java.util.ArrayList;
import java.util.List;

/**
 * What is downloaded at once: the whole program, one step's block, or a resume program; each of its
 * commands with the compiled program's instruction it stands for ({@code origin}, 0-based), so that
 * what the controller executes always maps back to the G-code through the one source map. The
 * commands are packed into lines as the compile packs them ({@link LinePacker}, the model's line
 * width), so the whole program downloads as the bytes of FILE.dmc; {@link #lastOf} turns the line the
 * controller reports ({@code _XQ0}) into the command it stands in.
 */
public record Download(List<Command> commands, int[] origin, List<String> lines, int[] lineStart) {
    public Download {
        commands = List.copyOf(commands);
        lines = List.copyOf(lines);
        if (origin.length != commands.size() || lineStart.length != lines.size()) {
            throw new IllegalArgumentException("a command without its origin");
        }
    }

    /** The commands packed into lines of {@code width} characters, each printed once ({@link gcnc.dmc.DmcPrinter}). */
    public Download(List<Command> commands, int[] origin, int width) {
        this(commands, origin, packed(commands, width));
    }

    private Download(List<Command> commands, int[] origin, List<LinePacker.Line> packed) {
        this(commands, origin, packed.stream().map(LinePacker.Line::text).toList(), starts(packed));
    }

    /** {@code commands} as they are downloaded: packed into lines of {@code width} characters, as the compile writes them. */
    static List<String> packedLines(List<Command> commands, int width) {
        return packed(commands, width).stream().map(LinePacker.Line::text).toList();
    }

    private static List<LinePacker.Line> packed(List<Command> commands, int width) {
        List<Instruction> is = new ArrayList<>(commands.size());
        for (Command c : commands) {
            is.add(new Instruction(c, Source.NONE));
        }
        return LinePacker.pack(is, width);
    }

    private static int[] starts(List<LinePacker.Line> packed) {
        int[] at = new int[packed.size()];
        int n = 0;
        for (int i = 0; i < at.length; i++) {
            at[i] = n;
            n += packed.get(i).instructions().size();
        }
        return at;
    }

    /** The whole program. */
    public static Download whole(DmcProgram p) {
        int[] o = new int[p.instructions().size()];
        List<Command> c = new ArrayList<>(o.length);
        for (int i = 0; i < o.length; i++) {
            o[i] = i;
            c.add(p.command(i));
        }
        return new Download(c, o, p.lineWidth());
    }

    /** The compiled program's instruction for command {@code j} of the piece (0-based), or -1. */
    public int originOf(int j) {
        return j >= 0 && j < origin.length ? origin[j] : -1;
    }

    /** The first command on the controller's line {@code n} (0-based), or -1 beyond the piece. */
    public int firstOf(int n) {
        return n >= 0 && n < lineStart.length ? lineStart[n] : -1;
    }

    /**
     * The last command on the controller's line {@code n} (0-based), or -1 beyond the piece: where
     * thread 0 stands while {@code _XQ0} reads {@code n}, since a packed line ends at each wait.
     */
    public int lastOf(int n) {
        return n < 0 || n >= lineStart.length ? -1 : n + 1 < lineStart.length ? lineStart[n + 1] - 1 : commands.size() - 1;
    }

    /**
     * The vector sequence the piece's command {@code n} is in: the compiled instructions its segments
     * stand for, in the controller's order (the segment executing while {@code _CSS} reads k is
     * {@code origins[k]}: the counter starts at zero), and whether command {@code n} is at or past its {@code BGS} (the
     * motion has begun). Null when command {@code n} is in no vector sequence.
     */
    public Segments segmentsAt(int n, DmcProgram program) {
        int start = n;
        for (; start >= 0; start--) {
            SequencePart part = SequencePart.of(program.command(originOf(start)));
            if (part == SequencePart.SPEED) {
                break;
            }
            if (start != n && (part == SequencePart.AWAIT || part == SequencePart.OUTSIDE)) {
                return null;
            }
        }
        if (start < 0) {
            return null;
        }
        List<Integer> origins = new ArrayList<>();
        boolean begun = false;
        for (int j = start + 1; j < commands.size(); j++) {
            SequencePart part = SequencePart.of(program.command(originOf(j)));
            if (part == SequencePart.AWAIT) {
                break;
            }
            if (part == SequencePart.SEGMENT) {
                origins.add(originOf(j));
            } else if (part == SequencePart.BEGIN && j <= n) {
                begun = true;
            }
        }
        return new Segments(origins.stream().mapToInt(Integer::intValue).toArray(), begun);
    }

    /**
     * The sequence fed while it runs that the controller's line {@code n} lies wholly inside, as the
     * index of its {@code VS}; -1 when there is none. Wholly inside: the line's first command is past the
     * sequence's {@code BGS} and neither the line nor anything before it is its {@code VE}, so thread 0,
     * anywhere on the line, has begun the motion and not yet ended the segments: the sequence must be
     * moving ({@code _BGS} 1) unless its buffer ran dry.
     */
    public int fedSequenceOn(int n, DmcProgram program) {
        int first = firstOf(n);
        boolean begun = false;
        for (int j = lastOf(n); first >= 0 && j >= 0; j--) {
            switch (SequencePart.of(program.command(originOf(j)))) {
                case SPEED -> {
                    return begun ? j : -1;
                }
                case VECTOR_END, AWAIT, OUTSIDE -> {
                    return -1;
                }
                case BEGIN -> {
                    if (j >= first) {
                        return -1; // the thread may stand before it
                    }
                    begun = true;
                }
                case SEGMENT, ROOM_WAIT, TRIP, NONE -> {
                }
            }
        }
        return -1;
    }

    /** The segments of one vector sequence of a piece: see {@link #segmentsAt}. */
    public record Segments(int[] origins, boolean begun) {
        /**
         * The compiled line of the segment executing when the controller's {@code _CSS} reads {@code css}:
         * the segment counter starts at zero ("during the first segment ... _CS ... will be zero ... at
         * the second segment ... _CS equals 1", DMC-40x0 User Manual p.86). After the sequence has ended
         * the manuals do not say what it reads (the number of segments, or the last one's); either names
         * the last segment here.
         */
        public int executing(int css) {
            return origins[segment(css, origins.length)];
        }

        /** The index, from zero, of the segment of a sequence of {@code n} executing when {@code _CSS} reads {@code css}. */
        public static int segment(int css, int n) {
            return Math.max(0, Math.min(n - 1, css));
        }
    }

    /** Builds a piece command by command. */
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

        /** @param width the characters of a controller line ({@link DmcProgram#lineWidth}) */
        public Download build(int width) {
            return new Download(commands, origin.stream().mapToInt(Integer::intValue).toArray(), width);
        }
    }
}
