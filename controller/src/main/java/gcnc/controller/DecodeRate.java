package gcnc.controller;

import java.util.List;

/**
 * How many statements each running thread executes in a step of controller time: Galil decodes a
 * command in about 0.05 ms (DMC-40x0 user manual), 20 a millisecond per thread, unless a
 * {@code slow-thread=MS} fault gives each statement MS milliseconds (then the fraction owed carries on).
 */
final class DecodeRate {
    /** A slow-thread fault's milliseconds of controller time per statement; 0: the decode rate of 20 a millisecond. */
    private final double statementMillis;
    /** Under a slow-thread fault, the statements each thread is owed from the steps so far (its fraction). */
    private double statementsOwed;

    DecodeRate(List<InjectedFault> faults) {
        statementMillis = faults.stream().filter(f -> f.kind() == InjectedFault.Kind.SLOW_THREAD)
                .mapToDouble(InjectedFault::n).max().orElse(0);
    }

    /** The statements each thread runs in the next {@code seconds} of controller time. */
    int statements(double seconds) {
        if (statementMillis <= 0) {
            return Math.max(1, (int) Math.round(seconds * 20_000));
        }
        statementsOwed += seconds * 1000 / statementMillis;
        int budget = (int) (statementsOwed + 1e-9); // ten steps of 0.1 owed are one statement, not 0.999...
        statementsOwed -= budget;
        return budget;
    }
}
