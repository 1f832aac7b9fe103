package gcnc.plan;

/**
 * Why the machine stops where a vector sequence ends: recorded with the sequence (the source map's
 * {@code # stop} lines, the JSON summary), so that "why does the machine stop here?" has an answer.
 */
public enum Stop {
    /** The exact-stop planner: every motion is a sequence of its own (the thesis dialect, {@code plan.blend = off}). */
    EXACT_STOP,
    /** The next block changes the spindle's speed or direction. */
    SPINDLE,
    /** The next block changes the tool. */
    TOOL,
    /** An M code with outputs: they switch when the axes stand still. */
    OUTPUT,
    /** G09 in the block: its move ends at rest and is checked in position (one block). */
    EXACT_STOP_BLOCK,
    /** G61 exact stop mode (until G64): every move ends at rest. */
    EXACT_STOP_MODE,
    /** A dwell (G04). */
    DWELL,
    /** A thread pass: geared to the spindle, never blended. */
    THREAD,
    /** A rapid after a feed or a feed after a rapid. */
    RAPID_FEED,
    /** The path turns back on itself: a corner no speed above zero can take. */
    REVERSAL,
    /** The sequence's total length reached the controller's limit. */
    LENGTH,
    /** A program stop (M00; M01 with the optional stop switch on): the machine waits for the operator at rest. */
    PROGRAM_STOP,
    /** The next motion is in another program file (a call or a return). */
    CALL,
    /** The program ends. */
    END;

    /** The name in the source map and the JSON summary: the constant's, in lower case with hyphens ({@code exact-stop}). */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }
}
