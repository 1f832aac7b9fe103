package gcnc.cli;

import gcnc.machine.Units;
import gcnc.sim.ProgramEnvelope;
import gcnc.sim.SimReport;
import java.math.BigDecimal;
import java.math.RoundingMode;

/**
 * The simulator's summary as printed after a run. Its envelopes are in the program's terms first
 * (X as the program writes it, Z from work zero, the program's units), the part's (the feed moves)
 * before every move's (rapids and home moves too), the machine frame last: {@code part X
 * -1.600..44.000 (diameter), Z -30.000..0.000 mm from work zero (feed moves); envelope X
 * -1.600..424.000 (diameter), Z -30.000..363.000 mm from work zero; machine X -0.800..212.000 mm
 * (radius), Z 120.000..513.000 mm}.
 */
final class SimSummary {
    private SimSummary() {
    }

    static String format(SimReport r, Phrases phrases) {
        String envelope = Double.isNaN(r.xMinMm()) ? phrases.get("simulation.no_motion") : envelope(r, phrases);
        long s = Math.round(r.cycleSeconds());
        long exact = Math.round(r.exactStopSeconds());
        // what blending gains: the same program with every move stopped at its end, when it differs
        String stops = exact > s ? phrases.get("simulation.exact_stop", clock(exact)) : "";
        // the operator's waits at M00/M01 are not the machine's time: said, not counted
        if (r.programStops() > 0) {
            stops += phrases.get("simulation.program_stops", phrases.count(r.programStops(), "program_stop"));
        }
        return phrases.get("simulation.summary", phrases.count(r.sequences(), "sequence"),
                phrases.count(r.segments(), "segment"), phrases.count(r.findings(), "finding"), envelope,
                clock(s)) + stops;
    }

    private static String clock(long s) {
        return s / 3600 + ":" + two(s / 60 % 60) + ":" + two(s % 60);
    }

    private static String envelope(SimReport r, Phrases phrases) {
        String machineX = millis(r.xMinMm()) + ".." + millis(r.xMaxMm());
        String machineZ = millis(r.zMinMm()) + ".." + millis(r.zMaxMm());
        ProgramEnvelope p = r.program();
        if (p == null) {
            return phrases.get("simulation.envelope_machine", machineX, machineZ);
        }
        ProgramEnvelope f = r.feeds();
        String part = f == null ? "" : phrases.get("simulation.part", programmed(f.xMin(), f.units()) + ".."
                + programmed(f.xMax(), f.units()), phrases.get(f.diameter() ? "simulation.diameter" : "simulation.radius"),
                programmed(f.zMin(), f.units()) + ".." + programmed(f.zMax(), f.units()), f.unit());
        return (part.isEmpty() ? "" : part + "; ") + phrases.get("simulation.envelope", programmed(p.xMin(), p.units()) + ".." + programmed(p.xMax(), p.units()),
                phrases.get(p.diameter() ? "simulation.diameter" : "simulation.radius"),
                programmed(p.zMin(), p.units()) + ".." + programmed(p.zMax(), p.units()), p.unit(), machineX, machineZ);
    }

    /** A program coordinate with the decimals its units are written with: 3 for mm, 4 for inches. */
    static String programmed(double v, Units u) {
        return BigDecimal.valueOf(v).setScale(u == Units.INCH ? 4 : 3, RoundingMode.HALF_UP).toPlainString();
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
