package gcnc.check;

/**
 * Blocks the control runs under G41/G42 without offsetting their moves (docs/nose-compensation.md,
 * "Under G41/G42"): the compensated path ends perpendicular before them, their moves go as
 * programmed (the first from where the tool stands), and the next move starts the compensation
 * again as a start-up does.
 */
enum NoseSuspend {
    /** An ordinary block: offset as the side says. */
    NONE,
    /**
     * Fanuc's temporary cancel: G28, G29, G30, G53, a G50/G92 position register, and a T word
     * (the new offset's nose applies from the next move).
     */
    FOR_THE_BLOCK,
    /** A block a cycle other than G70 made (roughing, single-pass, thread, peck and drilling cycles) or a G32. */
    CYCLE
}
