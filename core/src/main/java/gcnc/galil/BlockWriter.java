package gcnc.galil;

import gcnc.dmc.Command;
import gcnc.dmc.DmcPrinter;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.ir.CheckedBlock;
import java.util.function.Consumer;

/**
 * Hands on one block's instructions, each with its source (the block's file, line and the motion
 * being written), preceded by {@code NO L<line>} when the source map goes inline (only if the block
 * writes anything). Enforces the 80-character line limit of Galil program memory: every command a
 * dialect builds prints short by construction, so a longer one is a bug here, not bad input.
 */
final class BlockWriter {
    static final int MAX_LINE = 80;

    private final Consumer<Instruction> sink;
    private final CheckedBlock block;
    private boolean commented;
    /** The block's motion the next instructions carry out (-1: none), and their source, made when one is emitted. */
    private int motion = -1;
    private Source source;

    private final long ordinal;

    /** @param ordinal which block of the run this is (Source#block) */
    BlockWriter(Consumer<Instruction> sink, CheckedBlock block, boolean inlineSourceMap, long ordinal) {
        this.sink = sink;
        this.block = block;
        this.commented = !inlineSourceMap;
        this.ordinal = ordinal;
    }

    CheckedBlock block() {
        return block;
    }

    /** The instructions after this carry out the block's motion {@code index} (-1: none). */
    void motion(int index) {
        if (index != motion) {
            motion = index;
            source = null; // most blocks set their motion before they emit: one source a block, not two
        }
    }

    private Source source() {
        if (source == null) {
            source = new Source(block.origin(), block.line(), motion, ordinal);
        }
        return source;
    }

    void emit(Command command) {
        if (!commented) {
            commented = true;
            sink.accept(new Instruction(new Command.SourceMark(block.line()), source()));
        }
        assert DmcPrinter.print(command).length() <= MAX_LINE : "DMC line longer than " + MAX_LINE + ": " + command;
        sink.accept(new Instruction(command, source()));
    }
}
