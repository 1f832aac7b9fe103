package gcnc.controller;

import java.util.ArrayDeque;
import java.util.function.BooleanSupplier;

/**
 * One of the eight program threads ({@code XQ #label,n}): where it is (line and statement), its JS return
 * stack (16 deep), and the trippoint it waits on (AM, WT, AI), if any. {@code _XQn} is {@link #line}, -1
 * when it is not running.
 */
final class ProgramThread {
    static final int DEPTH = 16;

    final int number;
    int line = -1;
    int statement;
    final ArrayDeque<int[]> stack = new ArrayDeque<>();
    /** True once the trippoint this thread waits on has passed; null when it does not wait. */
    BooleanSupplier waitingFor;
    boolean inErrorHandler;

    ProgramThread(int number) {
        this.number = number;
    }

    boolean running() {
        return line >= 0;
    }

    void start(int at) {
        line = at;
        statement = 0;
        stack.clear();
        waitingFor = null;
        inErrorHandler = false;
    }

    void halt() {
        line = -1;
        stack.clear();
        waitingFor = null;
        inErrorHandler = false;
    }

    /**
     * An automatic subroutine (#LIMSWI) takes the thread: a running thread's place is pushed, so RE goes
     * back to the statement after the one it was at (a trippoint it waited on is given up); a thread that
     * was not running starts there, and its RE ends it.
     */
    void interrupt(int handler) {
        if (running()) {
            stack.push(new int[] {line, statement});
            waitingFor = null;
            line = handler;
            statement = 0;
        } else {
            start(handler);
        }
    }

    void jump(int to) {
        line = to;
        statement = 0;
    }

    /** JS: the return place is the statement after the JS. */
    void call(int to) throws GalilException {
        if (stack.size() >= DEPTH) {
            throw new GalilException(Tc.SUBROUTINE_DEPTH);
        }
        stack.push(new int[] {line, statement});
        jump(to);
    }

    /** EN or RE: back to the caller, or the thread ends. */
    void back() {
        int[] r = stack.poll();
        if (r == null) {
            halt();
        } else {
            line = r[0];
            statement = r[1];
        }
    }
}
