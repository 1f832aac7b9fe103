package gcnc.dmc;

import java.util.function.Consumer;

/**
 * The side file that traces DMC output lines back to G-code lines when the map is not inline
 * (docs/dmc-format.md). Like a line-number table, it has one "{@code <dmc line> <source line>}"
 * entry where a run of output commands from one source line starts, followed by the file when the
 * line is in another file than the program's (a called subprogram, {@code O2000.nc}); the run goes
 * on to the command before the next entry. On a packed line ({@link LinePacker}) a run that starts
 * at its k-th command (counted from 0) is "{@code <dmc line>.<k> <source line>}". Source line 0
 * marks commands from no block (header, footer). Entries are handed on as they arise, so memory
 * stays flat however long the program.
 */
public final class SourceMap {
    /** Where the entries go, as numbers: an output that writes them as text without making strings. */
    public interface Entries {
        /**
         * @param statement the command on the DMC line where the run starts, counted from 0
         * @param file      the G-code file, or null for the program's own
         */
        void entry(int dmcLine, int statement, int sourceLine, String file);
    }

    private final Entries entries;
    private Stops stops = (line, why) -> { };

    /** Where the map's stop lines go: the DMC line where the machine stops, and why. */
    public interface Stops {
        void stop(int dmcLine, gcnc.plan.Stop why);
    }

    /** The same map, handing each stop to {@code stops} ({@code # stop <dmc line> <reason>} lines). */
    public SourceMap withStops(Stops stops) {
        this.stops = stops;
        return this;
    }

    /** How a stop is written in the map file. */
    public static String stopLine(int dmcLine, gcnc.plan.Stop why) {
        return STOP + dmcLine + " " + why.key();
    }

    /** What a map's stop line starts with: {@code # stop <dmc line> <reason>} (readers skip it as a comment). */
    public static final String STOP = "# stop ";
    private int dmcLines;
    private int lastSource = -1;
    private String lastFile;

    /** @param mapLines receives each line of the map file ("{@code <dmc line> <source line>}"), in output order */
    public SourceMap(Consumer<String> mapLines) {
        this((Entries) (dmc, statement, source, file) -> mapLines.accept(dmc + (statement == 0 ? "" : "." + statement)
                + " " + source + (file == null ? "" : " " + file)));
        this.stops = (line, why) -> mapLines.accept(stopLine(line, why));
    }

    private SourceMap(Entries entries) {
        this.entries = entries;
    }

    /** A map whose entries go to {@code entries} as numbers, in output order. */
    public static SourceMap toEntries(Entries entries) {
        return new SourceMap(entries);
    }

    /** A sink that numbers the instructions passing to {@code out} (one line each) and records where each run came from. */
    public Consumer<Instruction> wrap(Consumer<Instruction> out) {
        return i -> {
            dmcLines++;
            entry(i, 0);
            out.accept(i);
            stop(i);
        };
    }

    /** A sink that numbers packed lines passing to {@code out} and records where each run of their commands came from. */
    public Consumer<LinePacker.Line> wrapLines(Consumer<LinePacker.Line> out) {
        return l -> {
            dmcLines++;
            java.util.List<Instruction> is = l.instructions();
            for (int k = 0; k < is.size(); k++) {
                entry(is.get(k), k);
            }
            out.accept(l);
            for (Instruction i : is) {
                stop(i);
            }
        };
    }

    private void entry(Instruction i, int statement) {
        Source s = i.source();
        if (s.line() != lastSource || !java.util.Objects.equals(s.file(), lastFile)) {
            lastSource = s.line();
            lastFile = s.file();
            entries.entry(dmcLines, statement, lastSource, lastFile);
        }
    }

    private void stop(Instruction i) {
        if (i.command() instanceof Command.AwaitSequence a && a.why() != null) {
            stops.stop(dmcLines, a.why());
        }
    }

    /** How many DMC lines have passed. */
    public int lines() {
        return dmcLines;
    }

    /** What the map's last line starts with, before the SHA-256 of the DMC it was written with (hex). */
    public static final String DMC_HASH = "# dmc sha256 ";
    /** A resident program's map names its stream ({@code # stream <name>}) and the stream's SHA-256 (stream form). */
    public static final String STREAM = "# stream ";
    public static final String STREAM_HASH = "# stream sha256 ";
    /** What the map's second line starts with, before the G-code file's SHA-256 (hex). */
    public static final String SOURCE_HASH = "# source sha256 ";

    /** The first line of a map file: the G-code file the DMC was compiled from. */
    public static String sourceLine(String fileName) {
        return "# source " + fileName;
    }

    /**
     * A map file read back: where each DMC command came from (null where a run came from no block,
     * or before the first entry), the G-code file's name when the map names it, the SHA-256 of
     * the DMC it was written with (none in a map of gcnc before 2026-11: it cannot be trusted), and
     * for a resident program the SHA-256 of its stream.
     */
    public record Table(Locator at, java.util.Optional<String> source,
                        java.util.Optional<String> dmcSha256, java.util.Optional<String> streamSha256) {
        /** Where the first command of each DMC line came from. */
        public java.util.function.IntFunction<Source> lines() {
            return n -> at.source(n, 0);
        }

        /** The G-code line of each DMC line's first command, whatever its file (0: from no block). */
        public java.util.function.IntUnaryOperator lineNumbers() {
            return n -> {
                Source s = at.source(n, 0);
                return s == null ? 0 : s.line();
            };
        }

        /** Whether the map was written with the DMC of this SHA-256 (lowercase hex). */
        public boolean belongsTo(String sha256) {
            return dmcSha256.map(sha256::equals).orElse(false);
        }
    }

    /** Where a DMC command came from: its line (from 1) and its place on the line (from 0). */
    @FunctionalInterface
    public interface Locator {
        Source source(int dmcLine, int statement);
    }

    /** Reads a map file back; lines that are neither an entry, {@code # source} nor {@code # dmc sha256} are skipped. */
    public static Table read(java.io.BufferedReader in) throws java.io.IOException {
        java.util.List<long[]> runs = new java.util.ArrayList<>();
        java.util.List<String> files = new java.util.ArrayList<>();
        String source = null;
        String dmc = null;
        String stream = null;
        for (String l = in.readLine(); l != null; l = in.readLine()) {
            if (l.startsWith(STREAM_HASH)) {
                stream = l.substring(STREAM_HASH.length()).strip();
                continue;
            }
            if (l.startsWith(DMC_HASH)) {
                dmc = l.substring(DMC_HASH.length()).strip();
                continue;
            }
            if (l.startsWith("# source ") && source == null) {
                source = l.substring("# source ".length());
                continue;
            }
            String[] f = l.strip().split(" ", 3);
            long at = f.length >= 2 ? place(f[0]) : -1;
            if (at >= 0 && number(f[1])) {
                runs.add(new long[] {at, Integer.parseInt(f[1])});
                files.add(f.length == 3 ? f[2] : null);
            }
        }
        long[] start = new long[runs.size()];
        Source[] from = new Source[runs.size()];
        for (int i = 0; i < start.length; i++) {
            start[i] = runs.get(i)[0];
            int line = (int) runs.get(i)[1];
            from[i] = line == 0 ? null : files.get(i) == null ? Source.line(line)
                    : new Source(gcnc.diag.Origin.file(files.get(i)), line, -1);
        }
        return new Table((dmcLine, statement) -> {
            int i = java.util.Arrays.binarySearch(start, key(dmcLine, statement));
            int run = i >= 0 ? i : -i - 2;
            return run < 0 ? null : from[run];
        }, java.util.Optional.ofNullable(source), java.util.Optional.ofNullable(dmc), java.util.Optional.ofNullable(stream));
    }

    /** A command's place as one number that sorts as the program runs: its line, then its place on the line. */
    public static long key(int dmcLine, int statement) {
        return ((long) dmcLine << 16) | statement;
    }

    /** An entry's place, {@code L} or {@code L.K}, as {@link #key}; -1 when it is neither. */
    public static long place(String s) {
        int dot = s.indexOf('.');
        String line = dot < 0 ? s : s.substring(0, dot);
        String statement = dot < 0 ? "0" : s.substring(dot + 1);
        if (!number(line) || !number(statement) || statement.length() > 4) {
            return -1;
        }
        return key(Integer.parseInt(line), Integer.parseInt(statement));
    }

    private static boolean number(String s) {
        return !s.isEmpty() && s.length() < 10 && s.chars().allMatch(c -> c >= '0' && c <= '9');
    }
}
