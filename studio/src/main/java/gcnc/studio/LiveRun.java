package gcnc.studio;

import gcnc.send.Operator;

/** The run going on in the studio: what it was armed with, its operator's keys, what it waits for. */
final class LiveRun {
    final RunArm arm;
    final Operator operator = new Operator();
    volatile boolean stepWaiting;
    /** The program waits at a program stop (M00; M01 with the switch on) for Start. */
    volatile boolean stopWaiting;

    LiveRun(RunArm arm) {
        this.arm = arm;
    }
}
