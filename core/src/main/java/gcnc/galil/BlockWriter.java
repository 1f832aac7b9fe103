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
    private Source source;

    private final long ordinal;

    /** @param ordinal which block of the run this is (Source#block) */
    BlockWriter(Consumer<Instruction> sink, CheckedBlock block, boolean inlineSourceMap, long ordinal) {
        this.sink = sink;
        this.block = block;
        this.commented = !inlineSourceMap;
        this.ordinal = ordinal;
        this.source = new Source(block.origin(), block.line(), -1, ordinal);
    }

    CheckedBlock block() {
        return block;
    }

    /** The instructions after this carry out the block's motion {@code index} (-1: none). */
    void motion(int index) {
        if (index != source.motion()) {
            source = new Source(block.origin(), block.line(), index, ordinal);
        }
    }

    void emit(Command command) {
        if (!commented) {
            commented = true;
            sink.accept(new Instruction(new Command.SourceMark(block.line()), source));
        }
        assert DmcPrinter.print(command).length() <= MAX_LINE : "DMC line longer than " + MAX_LINE + ": " + command;
        sink.accept(new Instruction(command, source));
    }
}
