package gcnc.studio;

import com.google.gson.JsonObject;

/**
 * The operator's keys of the run going on, as the Run screen's buttons send them (docs/studio.md): feed
 * hold, its end, the next block in step mode, Start at a program stop, the feed override, stop; each as
 * {@code gcnc run}'s keys do it, through the run's {@link gcnc.send.Operator}, and each answers the run's state.
 */
final class RunKeys {
    private RunKeys() {
    }

    /** POST /api/run/hold: feed hold (VR 0; the spindle keeps turning), as the first Ctrl-C. */
    static JsonObject hold(LiveRun r) throws Http.Fail {
        synchronized (r) {
            if (r.operator.held()) {
                throw new Http.Fail(409, "the run is already held");
            }
            r.operator.interrupt(); // one interrupt holds; a second would stop, hence held() first
        }
        return state(r);
    }

    /** POST /api/run/resume: the end of a feed hold (in step mode the next block still waits for Step). */
    static JsonObject resume(LiveRun r) throws Http.Fail {
        synchronized (r) {
            if (!r.operator.held()) {
                throw new Http.Fail(409, "the run is not held");
            }
            r.operator.resume();
        }
        return state(r);
    }

    /** POST /api/run/step: the next block in step mode, as Enter. */
    static JsonObject step(LiveRun r) throws Http.Fail {
        if (!r.arm.step()) {
            throw new Http.Fail(409, "the run is not in step mode");
        }
        r.stepWaiting = false;
        r.operator.enter();
        return state(r);
    }

    /** POST /api/run/continue: Start at a program stop (M00; M01 with the switch on), as Enter. */
    static JsonObject continueStop(LiveRun r) throws Http.Fail {
        if (!r.stopWaiting) {
            throw new Http.Fail(409, "the program is not at a program stop");
        }
        r.operator.enter();
        return state(r);
    }

    /** POST /api/run/override {percent}: the feed override, 10 to 200 % (VR), as the keys + and -. */
    static JsonObject override(LiveRun r, int percent) {
        r.operator.override(percent / 100.0);
        return state(r);
    }

    /** POST /api/run/stop: stop now (ST, spindle and coolant off), as q or the second Ctrl-C. */
    static JsonObject stop(LiveRun r) throws Http.Fail {
        r.operator.stop();
        return state(r);
    }

    static JsonObject state(LiveRun r) {
        JsonObject o = new JsonObject();
        o.addProperty("running", true);
        o.addProperty("held", r.operator.held());
        o.addProperty("stopping", r.operator.stopped());
        o.addProperty("override", r.operator.override());
        return o;
    }
}
