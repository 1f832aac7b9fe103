package gcnc.path;

import java.util.List;

/**
 * One move of the interpreted path (gcnc path, docs/path.md): what the control does for one
 * motion of a checked block, in the program's terms and the machine's. Every number is already
 * the text the formats write (fixed 4 decimals), empty where the move has none (a rapid has no
 * feed, only an arc a centre), so that CSV and JSON carry exactly the same values.
 *
 * @param kind        what the move is
 * @param file        the file its line is in (the program as the user named it, or a called program's file)
 * @param line        the line of the block that made it (a cycle's passes: the cycle's line)
 * @param block       the block's N number and cycle pass ("N110 G71 pass 4 of 9"), or empty
 * @param x           the end point's X as the program writes it (a diameter where X is one), from the work zero
 * @param z           the end point's Z from the work zero, in the program's units
 * @param machineX    the end point in the machine frame, mm, X a radius from machine X zero
 * @param machineZ    the end point in the machine frame, mm
 * @param centerX     an arc's centre, X as the program writes it; else empty
 * @param centerZ     an arc's centre, Z from the work zero; else empty
 * @param radius      an arc's radius in the program's units; else empty
 * @param feed        the F in force as written (a thread's lead); empty for a rapid or a dwell
 * @param feedUnit    mm/min, mm/rev, in/min or in/rev; empty where there is no feed
 * @param spindle     the spindle speed in force, r/min (G96 already worked out at the block), or empty
 * @param spindleDir  cw, ccw or stop: the spindle's direction in force
 * @param tool        the T word in force as the checker read it, or empty
 * @param seconds     a dwell's time; else empty
 */
public record PathMove(Kind kind, String file, int line, String block, String x, String z, String machineX,
                       String machineZ, String centerX, String centerZ, String radius, String feed, String feedUnit,
                       String spindle, String spindleDir, String tool, String seconds) {
    /** The kinds of move, with the name the formats write. */
    public enum Kind {
        RAPID, FEED, ARC_CW, ARC_CCW, THREAD, DWELL;

        /** The constant's name in lower case ({@code arc_cw}), as the CSV and JSON write it. */
        public String written() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /** The columns, in order: the CSV header and the JSON names (the format's version 1; docs/path.md). */
    public static final List<String> COLUMNS = List.of("kind", "file", "line", "block", "x", "z", "machine_x",
            "machine_z", "center_x", "center_z", "radius", "feed", "feed_unit", "spindle", "spindle_dir", "tool",
            "seconds");

    /** The values in the order of {@link #COLUMNS}. */
    public List<String> values() {
        return List.of(kind.written(), file, Integer.toString(line), block, x, z, machineX, machineZ, centerX, centerZ,
                radius, feed, feedUnit, spindle, spindleDir, tool, seconds);
    }

    /** Whether the column at {@code index} holds a number (written bare in JSON), else text. */
    static boolean numeric(int index) {
        String c = COLUMNS.get(index);
        return !(c.equals("kind") || c.equals("file") || c.equals("block") || c.equals("feed_unit")
                || c.equals("spindle_dir"));
    }
}
