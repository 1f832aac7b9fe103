package gcnc.plan;

/**
 * Why the machine stops where a vector sequence ends: recorded with the sequence (the source map's
 * {@code # stop} lines, the JSON summary), so that "why does the machine stop here?" has an answer.
 */
public enum Stop {
    /** The exact-stop planner: every motion is a sequence of its own (the thesis dialect, {@code plan.blend = off}). */
    EXACT_STOP("exact-stop"),
    /** The next block changes the spindle's speed or direction. */
    SPINDLE("spindle"),
    /** The next block changes the tool. */
    TOOL("tool"),
    /** An M code with outputs: they switch when the axes stand still. */
    OUTPUT("output"),
    /** G09 in the block: its move ends at rest and is checked in position (one block). */
    EXACT_STOP_BLOCK("exact-stop-block"),
    /** G61 exact stop mode (until G64): every move ends at rest. */
    EXACT_STOP_MODE("exact-stop-mode"),
    /** A dwell (G04). */
    DWELL("dwell"),
    /** A thread pass: geared to the spindle, never blended. */
    THREAD("thread"),
    /** A rapid after a feed or a feed after a rapid. */
    RAPID_FEED("rapid-feed"),
    /** The path turns back on itself: a corner no speed above zero can take. */
    REVERSAL("reversal"),
    /** The sequence's total length reached the controller's limit. */
    LENGTH("length"),
    /** A program stop (M00; M01 with the optional stop switch on): the machine waits for the operator at rest. */
    PROGRAM_STOP("program-stop"),
    /** The next motion is in another program file (a call or a return). */
    CALL("call"),
    /** The program ends. */
    END("end");

    private final String key;

    Stop(String key) {
        this.key = key;
    }

    /** The name in the source map and the JSON summary. */
    public String key() {
        return key;
    }
}
