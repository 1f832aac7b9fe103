package gcnc.cli;

import gcnc.sim.SimReport;
import java.util.Locale;

/** The simulator's summary as printed after a run. */
final class SimSummary {
    private SimSummary() {
    }

    static String format(SimReport r) {
        String envelope = Double.isNaN(r.xMinMm()) ? "no motion"
                : String.format(Locale.ROOT, "X %.3f..%.3f mm (radius), Z %.3f..%.3f mm", r.xMinMm(), r.xMaxMm(), r.zMinMm(), r.zMaxMm());
        long s = Math.round(r.cycleSeconds());
        return String.format(Locale.ROOT, "simulation: %d sequences, %d segments, %s; envelope %s; cycle time about %d:%02d:%02d",
                r.sequences(), r.segments(), Reporter.plural(r.findings(), "finding"), envelope, s / 3600, s / 60 % 60, s % 60);
    }
}
