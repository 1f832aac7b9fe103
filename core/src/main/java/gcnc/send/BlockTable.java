package gcnc.send;

import gcnc.check.Checker;
import gcnc.check.ModalState;
import gcnc.diag.Diagnostics;
import gcnc.flow.ProgramFlow;
import gcnc.ir.CheckedBlock;
import gcnc.ir.ProgramFrame;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.parse.BlockReader;
import gcnc.parse.BlockSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * What the checker knows at each G-code line of the main program, for the status line and the
 * resume report: the block's program frame (to show the tool in program coordinates), its N
 * number, and the modal state after it (tool, work offset, feed and its mode, spindle). A second,
 * check-only pass over a program that {@code compile} already found clean (so it reports nothing).
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
     * @param spindle    3, 4 or 5 (M03, M04, M05), -1 before any
     * @param tool       tool number in force
     * @param toolOffset tool offset number in force
     * @param workOffset 54..59
     */
    public record Block(ProgramFrame frame, String number, double feed, boolean perRev, boolean inch, double rpm,
                        boolean css, int spindle, int tool, int toolOffset, int workOffset) {
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

    private BlockTable(Map<Integer, Block> blocks) {
        this.blocks = blocks;
    }

    /** An empty table (the program could not be read again): the status line then shows machine counts. */
    public static BlockTable none() {
        return new BlockTable(Map.of());
    }

    /** Checks {@code source} again as the compiler did, keeping each main-program line's state. */
    public static BlockTable of(Reader source, Tables tables, MachineProfile profile, Optional<Path> programs)
            throws IOException {
        Diagnostics ignored = new Diagnostics();
        gcnc.machine.Control control = profile.control();
        BlockSource reader = control.hasProgramFlow()
                ? new ProgramFlow(BlockReader.forControl(source, ignored, control.macros(), control.lineComments()),
                        control, ignored, programs)
                : BlockReader.forControl(source, ignored, false, control.lineComments());
        Checker checker = new Checker(tables, profile, ignored);
        Map<Integer, Block> out = new HashMap<>();
        for (RawBlock raw = reader.next(); raw != null; raw = reader.next()) {
            ProgramFrame frame = null;
            for (CheckedBlock b : checker.check(raw)) {
                if (b.frame() != null && b.origin().file() == null) {
                    frame = b.frame();
                }
            }
            if (raw.depth() > 0) {
                continue; // a called program's line: its own file's numbering
            }
            ModalState s = checker.state();
            out.put(raw.line(), new Block(frame, frame == null ? null : frame.number(), s.feed(), s.feedPerRev(),
                    s.units() == Units.INCH, s.rpm(), s.css(), s.spindle(), s.tool(), s.toolOffset(), s.workOffset()));
        }
        return new BlockTable(out);
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
