package gcnc.send;

import gcnc.check.ModalState;
import gcnc.ir.CheckedBlock;
import gcnc.ir.ProgramFrame;
import gcnc.ir.RawBlock;
import gcnc.machine.Units;
import java.util.HashMap;
import java.util.Map;

/**
 * What the checker knows at each G-code line of the main program, for the status line and the
 * resume report: the block's program frame (to show the tool in program coordinates), its N
 * number, and the modal state after it (tool, work offset, feed and its mode, spindle): a view of the
 * compile that judged the program ({@link View}), not a check of its own.
 */
public final class BlockTable {
    /**
     * The state at one G-code line.
     *
     * @param frame      where its program coordinates are, or null when the checker has none
     * @param number     its N word as written, or null
     * @param feed       F in force (per minute or per revolution), NaN before any
     * @param perRev     G99/G95 feed per revolution
     * @param inch       G20 in force
     * @param rpm        spindle speed in force (r/min), NaN before any
     * @param css        G96 constant surface speed in force
     * @param surfaceSpeed G96 S (m/min, ft/min under G20), NaN before any
     * @param rpmClamp   G50 S, the highest speed G96 may ask, NaN when none
     * @param spindle    3, 4 or 5 (M03, M04, M05), -1 before any
     * @param tool       tool number in force
     * @param toolOffset tool offset number in force
     * @param workOffset 54..59
     */
    public record Block(ProgramFrame frame, String number, double feed, boolean perRev, boolean inch, double rpm,
                        boolean css, double surfaceSpeed, double rpmClamp, int spindle, int tool, int toolOffset,
                        int workOffset) {
        /** Machine counts (lathe X radius, Z) in the block's program coordinates (X as written: a diameter where the machine takes one). */
        public double[] program(double[] machine) {
            if (frame == null || frame.perX() == 0 || frame.perZ() == 0) {
                return null;
            }
            return new double[] {(machine[0] - frame.origin().x()) / frame.perX(),
                    (machine[1] - frame.origin().z()) / frame.perZ()};
        }
    }

    private final Map<Integer, Block> blocks;
    /** The text of the first comment of each main-program line that has one (a program stop shows it). */
    private final Map<Integer, String> comments;
    /** How many blocks the compile judged in all, and before each main-program line's first block. */
    private final long judged;
    private final Map<Integer, Long> before;

    private BlockTable(Map<Integer, Block> blocks, Map<Integer, String> comments, long judged, Map<Integer, Long> before) {
        this.blocks = blocks;
        this.comments = comments;
        this.judged = judged;
        this.before = before;
    }

    /** An empty table (the program could not be read again): the status line then shows machine counts. */
    public static BlockTable none() {
        return new BlockTable(Map.of(), Map.of(), 0, Map.of());
    }

    /**
     * The blocks the compile judged from the first block of main-program line {@code line} on (0: the
     * whole program): the count {@code gcnc compile} prints, for the part of the program a run sends.
     * A subprogram's blocks count once per call, as the compile counts them.
     */
    public long blocksFrom(int line) {
        return judged - (line == 0 ? 0 : before.getOrDefault(line, judged));
    }

    /** The first comment on G-code line {@code line}, without its parentheses ("" when it has none). */
    public String comment(int line) {
        return comments.getOrDefault(line, "");
    }

    /** The first {@code ( )} comment of each line of {@code text} that has one, by line number from 1. */
    private static Map<Integer, String> comments(String text) {
        Map<Integer, String> out = new HashMap<>();
        int line = 1;
        int from = 0;
        while (from <= text.length()) {
            int end = text.indexOf('\n', from);
            String l = text.substring(from, end < 0 ? text.length() : end);
            int open = l.indexOf('(');
            if (open >= 0) {
                int close = l.indexOf(')', open);
                out.put(line, l.substring(open + 1, close < 0 ? l.length() : close).strip());
            }
            if (end < 0) {
                break;
            }
            from = end + 1;
            line++;
        }
        return out;
    }

    /**
     * The table as the compile fills it ({@link gcnc.CompileObserver#block}): each main-program line's
     * state after its block, from the one check that judged the program; the comments from the
     * program's text as the compile read it.
     */
    public static final class View implements gcnc.CompileObserver {
        private final Map<Integer, Block> out = new HashMap<>();
        private final Map<Integer, Long> before = new HashMap<>();
        private long judged;
        /** The frame of the last main-program block that had one: the frame in force. */
        private ProgramFrame last;

        @Override
        public void block(RawBlock raw, gcnc.diag.Origin from, java.util.List<CheckedBlock> checked, ModalState s) {
            if (raw.depth() == 0) {
                before.putIfAbsent(raw.line(), judged);
            }
            judged++;
            ProgramFrame frame = null;
            for (CheckedBlock b : checked) {
                if (b.frame() != null && b.origin().file() == null) {
                    frame = b.frame();
                }
            }
            if (raw.depth() > 0) {
                return; // a called program's line: its own file's numbering
            }
            String number = frame == null ? null : frame.number();
            if (frame != null) {
                last = frame;
            } else if (checked.isEmpty() && last != null) {
                // a line that makes no block of its own: a contour block a cycle reads (G71's N(p)..N(q)),
                // whose segments the cycle's passes and G70 run with this line's name; its positions are
                // in the frame in force (offsets change only in a block of their own), without its N
                frame = new ProgramFrame(last.origin(), last.perX(), last.perZ(), null, null, last.file());
            }
            out.put(raw.line(), new Block(frame, number, s.feed(), s.feedPerRev(),
                    s.units() == Units.INCH, s.rpm(), s.css(), s.surfaceSpeed(), s.rpmClamp(), s.spindle(), s.tool(), s.toolOffset(), s.workOffset()));
        }

        /** The table of the blocks seen, with the comments of {@code text} (the program as the compile read it). */
        public BlockTable table(String text) {
            return new BlockTable(Map.copyOf(out), comments(text), judged, Map.copyOf(before));
        }
    }

    /** The tool offsets (1..99) in force at some line of the main program, in order. */
    public java.util.SortedSet<Integer> toolOffsets() {
        java.util.SortedSet<Integer> used = new java.util.TreeSet<>();
        for (Block b : blocks.values()) {
            if (b.toolOffset() != 0) {
                used.add(b.toolOffset());
            }
        }
        return used;
    }

    /** The state at G-code line {@code line}, or null for a line with no block. */
    public Block at(int line) {
        return blocks.get(line);
    }
}
