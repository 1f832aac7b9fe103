package gcnc.galil;

import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import java.util.function.Consumer;

/**
 * The writer of each block's instructions, one a block so that its inline map comment comes once, and the
 * block's number in the run ({@link gcnc.dmc.Source#block}), counted in the same way for every dialect.
 */
final class BlockWriters {
    private final boolean inlineSourceMap;
    /** The writer in use: the last block's, or the one a dialect went back to ({@link #resume}). */
    private BlockWriter current;
    /** The blocks written so far: each new one's number in the run. */
    private long blocks;

    /** @param inlineSourceMap put a {@code NO L<line>} comment before each block's lines */
    BlockWriters(boolean inlineSourceMap) {
        this.inlineSourceMap = inlineSourceMap;
    }

    /** The writer in use when it is block {@code b}'s, else null ({@link #start} one). */
    BlockWriter current(CheckedBlock b) {
        return current != null && current.block() == b ? current : null;
    }

    /** A writer of the next block of the run, {@code b}, onto {@code sink}: the one in use from now on. */
    BlockWriter start(CheckedBlock b, Consumer<Instruction> sink) {
        current = new BlockWriter(sink, b, inlineSourceMap, blocks++);
        return current;
    }

    /** Goes on writing with {@code w} (its block's writer). */
    void resume(BlockWriter w) {
        current = w;
    }
}
