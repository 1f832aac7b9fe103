package gcnc.flow;

import gcnc.ir.RawBlock;
import java.io.IOException;

/** The blocks of a program being run, by index from its first: a called program's list, or the main program as it is read. */
interface Blocks {
    /** The block at {@code index}, or null past the end (or before {@link #first()}: no longer held). */
    RawBlock get(int index) throws IOException;

    /** The first index still held: 0 for a called program; for the main program, its first macro statement's. */
    int first();
}
