package gcnc.cli;

import gcnc.sim.SimReport;
import java.math.BigDecimal;
import java.math.RoundingMode;

/** The simulator's summary as printed after a run. */
final class SimSummary {
    private SimSummary() {
    }

    static String format(SimReport r, Phrases phrases) {
        String envelope = Double.isNaN(r.xMinMm()) ? phrases.get("simulation.no_motion")
                : phrases.get("simulation.envelope", millis(r.xMinMm()) + ".." + millis(r.xMaxMm()),
                        millis(r.zMinMm()) + ".." + millis(r.zMaxMm()));
        long s = Math.round(r.cycleSeconds());
        return phrases.get("simulation.summary", phrases.count(r.sequences(), "sequence"),
                phrases.count(r.segments(), "segment"), phrases.count(r.findings(), "finding"), envelope,
                s / 3600 + ":" + two(s / 60 % 60) + ":" + two(s % 60));
    }

    /**
     * A length with three decimals, as {@code %.3f} writes it (half up); BigDecimal rather than
     * String.format, which loads the locale data (10 ms of every run) even for Locale.ROOT.
     */
    static String millis(double mm) {
        return BigDecimal.valueOf(mm).setScale(3, RoundingMode.HALF_UP).toPlainString();
    }

    private static String two(long v) {
        return v < 10 ? "0" + v : Long.toString(v);
    }
}
