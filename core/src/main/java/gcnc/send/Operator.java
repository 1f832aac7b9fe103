package gcnc.send;

import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * What the operator asks of a running program, from other threads (Ctrl-C, the keyboard): feed
 * hold and resume, stop, the feed override, and Enter for the next step. The run reads it between
 * polls of the controller. The first Ctrl-C holds, a second one stops (a held machine's Enter
 * resumes it).
 */
public final class Operator {
    private volatile int interrupts;
    private volatile boolean stop;
    private volatile double override = 1;
    private final LinkedBlockingQueue<Boolean> enters = new LinkedBlockingQueue<>();

    /** Ctrl-C. */
    public void interrupt() {
        interrupts++;
        if (interrupts >= 2) {
            stop = true;
        }
        enters.offer(Boolean.FALSE); // wakes a step wait: it then sees the hold or stop
    }

    /** Enter: the next step, or the end of a feed hold. */
    public void enter() {
        if (interrupts == 1 && !stop) {
            interrupts = 0; // resumes from the hold
        }
        enters.offer(Boolean.TRUE);
    }

    /**
     * The end of a feed hold alone (the studio's Resume): unlike {@link #enter} it queues no Enter,
     * so in step mode the next block still waits for its own.
     */
    public void resume() {
        if (interrupts == 1 && !stop) {
            interrupts = 0;
            enters.offer(Boolean.FALSE); // wakes a step wait: it sees the hold ended and waits on
        }
    }

    /** Stop now (a second Ctrl-C, or {@code q}). */
    public void stop() {
        stop = true;
        enters.offer(Boolean.FALSE);
    }

    /** The feed override as a fraction of the programmed feed (Galil VR 0..10; the keyboard keeps it within 0.1..2). */
    public void override(double fraction) {
        override = Math.max(0, Math.min(10, fraction));
    }

    public double override() {
        return override;
    }

    public boolean held() {
        return interrupts == 1 && !stop;
    }

    public boolean stopped() {
        return stop;
    }

    /** The word the operator types before gcnc moves the axes on its own (the way back, the probe's motion test). */
    public static final String MOTION_WORD = "move";

    /** The lines typed that are no key (a confirmation word), and {@link #END} once the keyboard is closed. */
    private final LinkedBlockingQueue<String> words = new LinkedBlockingQueue<>();
    /** What {@link #word} gives once standard input has ended. */
    public static final String END = "\0";

    /** A line typed that is no key: a confirmation word, or {@link #END}. */
    public void typed(String line) {
        words.offer(line);
    }

    /** The next line typed that is no key, waiting up to {@code ms}; null when none came. */
    public String word(long ms) throws InterruptedException {
        return words.poll(ms, TimeUnit.MILLISECONDS);
    }

    /** Forgets the Enters pressed before now: a program stop waits for one pressed after it began. */
    public void forgetEnters() {
        enters.clear();
    }

    /**
     * Waits up to {@code ms} for Enter (a program stop's continue, which polls the controller between
     * waits); false when none came, or for a stop.
     */
    public boolean enterWithin(long ms) throws InterruptedException {
        if (stop) {
            return false;
        }
        Boolean e = enters.poll(ms, TimeUnit.MILLISECONDS);
        return e != null && e && !stop;
    }

    /** Waits for Enter; false when the wait ended for a hold or a stop instead. */
    public boolean awaitEnter() throws InterruptedException {
        while (true) {
            if (stop) {
                return false;
            }
            Boolean e = enters.poll(200, TimeUnit.MILLISECONDS);
            if (e != null) {
                return e && !stop;
            }
        }
    }
}
