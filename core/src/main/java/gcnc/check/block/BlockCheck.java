package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;

/**
 * One of the 8 end-of-block operations of thesis §4.2.2 (L879-887; reading §6, §7.2), run once
 * every word of the block has been read. Reports through {@link BlockDraft#fail}. Its thesis
 * number is the one in its class's name (Eb07...), paired with it in {@link BlockChecks} alone.
 */
public interface BlockCheck {
    void run(BlockDraft d, Diagnostics out);

    /**
     * A rule about the machine's state (spindle, chuck, feed, S limits) rather than the block's
     * form. A block that breaks only such rules is still what the programmer meant, so the
     * checker carries on from the state it would have left (see the checker's {@code recover}).
     */
    default boolean prerequisite() {
        return false;
    }
}
