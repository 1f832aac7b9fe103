package gcnc.send;

import java.io.IOException;

/**
 * The operator's feed hold and override as the controller has them: between polls, a hold asked
 * for or ended and an override changed become {@code VR} (0 for a hold) and a {@link Event.Hold}.
 * Both forms follow the run through one of these.
 */
final class FeedHold {
    private boolean held;
    private double ratio = 1;

    /** Brings the controller's {@code VR} to what the operator asks now. */
    void apply(MachineLink c, Progress progress, Operator op) throws IOException {
        if (op.held() != held) {
            held = op.held();
            ratio = held ? 0 : op.override();
            c.ratio(ratio);
            progress.events().accept(new Event.Hold(held, op.override()));
        } else if (!held && op.override() != ratio) {
            ratio = op.override();
            c.ratio(ratio);
            progress.events().accept(new Event.Hold(false, ratio));
        }
    }

    /** Whether a feed hold is on at the controller. */
    boolean held() {
        return held;
    }
}
