package gcnc.flow;

import gcnc.ir.RawBlock;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * The main program's blocks by index, as {@link MainFile} reads them. A program without macro
 * statements is not held: each block is let go when the next is read. From the first macro
 * statement on, blocks are held (GOTO and END jump back) up to a limit; past it they are let go
 * again, once and for all, and a jump back before the first block held is E141.
 */
final class MainBlocks implements Blocks {
    private final MainFile file;
    private final int limit;
    private final List<RawBlock> held = new ArrayList<>();
    /** The index of held.get(0). */
    private int base;
    private boolean holding;
    /** The limit was reached: nothing is held any more. */
    private boolean full;

    MainBlocks(MainFile file, int limit) {
        this.file = file;
        this.limit = limit;
    }

    @Override
    public RawBlock get(int index) throws IOException {
        if (!holding && index == base + held.size() && held.size() == 1) {
            // the common case, a program without macro statements: the next block in place of the last
            RawBlock b = file.next();
            if (b == null) {
                return null;
            }
            if (b.macro() == null || full) {
                base++;
                held.set(0, b);
                return b;
            }
            holding = true;
            held.add(b);
            return b;
        }
        while (base + held.size() <= index) {
            RawBlock b = file.next();
            if (b == null) {
                return null;
            }
            if (b.macro() != null && !full) {
                holding = true;
            }
            if (holding && held.size() >= limit) {
                holding = false;
                full = true;
            }
            if (!holding) {
                base += held.size();
                held.clear();
            }
            held.add(b);
        }
        return index >= base ? held.get(index - base) : null;
    }

    /** Holds the blocks from the current one on (an M97 call searches its label ahead and comes back). */
    void hold() {
        if (!full) {
            holding = true;
        }
    }

    @Override
    public int first() {
        return base;
    }

    int limit() {
        return limit;
    }

    /** Whether the limit was reached (E137, reported once by the flow). */
    boolean full() {
        return full;
    }
}
