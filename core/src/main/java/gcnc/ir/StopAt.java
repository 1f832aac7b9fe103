package gcnc.ir;

/**
 * Where a block's motion must come to rest, as the program asks it (Haas and Fanuc lathe manuals:
 * G09 "exact stop" for its own block, G61 "exact stop mode" until G64): the planner ends its vector
 * sequence there, with the reason recorded (gcnc.plan.Stop).
 */
public enum StopAt {
    /** No exact stop asked: the planner may blend into the next move (G64, the power-up mode). */
    BLEND,
    /** G09: the block's last motion ends at rest. */
    BLOCK_END,
    /** G61 in force: every motion of the block ends at rest. */
    EVERY_MOTION
}
