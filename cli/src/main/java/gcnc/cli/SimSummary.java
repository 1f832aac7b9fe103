package gcnc.cli;

import gcnc.sim.SimReport;
import java.util.Locale;

/** The simulator's summary as printed after a run. */
final class SimSummary {
    private SimSummary() {
    }

    static String format(SimReport r, Phrases phrases) {
        String envelope = Double.isNaN(r.xMinMm()) ? phrases.get("simulation.no_motion")
                : phrases.get("simulation.envelope", String.format(Locale.ROOT, "%.3f..%.3f", r.xMinMm(), r.xMaxMm()),
                        String.format(Locale.ROOT, "%.3f..%.3f", r.zMinMm(), r.zMaxMm()));
        long s = Math.round(r.cycleSeconds());
        return phrases.get("simulation.summary", phrases.count(r.sequences(), "sequence"),
                phrases.count(r.segments(), "segment"), phrases.count(r.findings(), "finding"), envelope,
                String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60));
    }
}
