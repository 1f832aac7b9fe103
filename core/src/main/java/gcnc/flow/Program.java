package gcnc.flow;

import gcnc.diag.Origin;
import gcnc.diag.Span;
import gcnc.ir.RawBlock;
import java.util.List;

/**
 * A program that M98 can call: its number, the file it is written in ({@code null}: the program's
 * own file, after the main program's end), its blocks without the O header, and where it starts
 * (its O word; line 1 of a file of its own without one).
 */
record Program(int number, String file, List<RawBlock> blocks, Span start) implements Blocks {
    Program {
        blocks = List.copyOf(blocks);
    }

    @Override
    public RawBlock get(int index) {
        return index >= 0 && index < blocks.size() ? blocks.get(index) : null;
    }

    @Override
    public int first() {
        return 0;
    }

    /** Its number as the control shows it: O1000, O0100. */
    static String name(long number) {
        return String.format("%04d", number);
    }

    String name() {
        return name(number);
    }

    /** Where its own findings (no call) are placed: its file. */
    Origin origin() {
        return file == null ? Origin.PROGRAM : Origin.file(file);
    }
}
