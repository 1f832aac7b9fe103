package gcnc.cli;

import com.google.gson.stream.JsonWriter;
import gcnc.sim.ProgramEnvelope;
import gcnc.sim.SimReport;
import java.io.IOException;
import java.util.List;

/**
 * The {@code "simulations"} array of the JSON report (docs/command-line.md): per simulated file,
 * the envelope as the program writes it ({@code program}: X as written, Z from work zero, its
 * units) and in the machine frame ({@code machine}: mm, X a radius), the counts and the cycle
 * time. Written only when something was simulated, so a {@code check} document is as it was.
 */
final class SimulationJson {
    record Run(String file, SimReport report) {
    }

    private SimulationJson() {
    }

    static void write(List<Run> runs, JsonWriter json) throws IOException {
        if (runs.isEmpty()) {
            return;
        }
        json.name("simulations").beginArray();
        for (Run run : runs) {
            SimReport r = run.report();
            json.beginObject();
            json.name("file").value(run.file());
            json.name("sequences").value(r.sequences());
            json.name("segments").value(r.segments());
            json.name("findings").value(r.findings());
            json.name("cycleSeconds").value(round(r.cycleSeconds(), 3));
            json.name("exactStopSeconds").value(round(r.exactStopSeconds(), 3)); // every move stopped: what blending gains
            if (r.programStops() > 0) {
                json.name("programStops").value(r.programStops()); // M00/M01 waits, not in cycleSeconds
            }
            boolean moved = !Double.isNaN(r.xMinMm());
            if (moved && r.program() != null) {
                envelope(json, "program", r.program());
            }
            if (moved && r.feeds() != null) {
                envelope(json, "part", r.feeds()); // the feed moves alone: where the part is cut
            }
            if (moved) {
                json.name("machine").beginObject();
                json.name("xMinMm").value(round(r.xMinMm(), 3));
                json.name("xMaxMm").value(round(r.xMaxMm(), 3));
                json.name("zMinMm").value(round(r.zMinMm(), 3));
                json.name("zMaxMm").value(round(r.zMaxMm(), 3));
                json.endObject();
            }
            if (!r.stops().isEmpty()) {
                // why the machine stops where each sequence ends: the count per reason (the source map has each place)
                json.name("stops").beginObject();
                for (var e : r.stops().entrySet()) {
                    json.name(e.getKey()).value(e.getValue());
                }
                json.endObject();
            }
            corners(run, json);
            json.endObject();
        }
        json.endArray();
    }

    /** An envelope in program terms: its units, what X is, and the extremes with the units' decimals. */
    private static void envelope(JsonWriter json, String name, ProgramEnvelope p) throws IOException {
        int decimals = p.units() == gcnc.machine.Units.INCH ? 4 : 3;
        json.name(name).beginObject();
        json.name("units").value(p.unit());
        json.name("x").value(p.xMode());
        json.name("xMin").value(round(p.xMin(), decimals));
        json.name("xMax").value(round(p.xMax(), decimals));
        json.name("zMin").value(round(p.zMin(), decimals));
        json.name("zMax").value(round(p.zMax(), decimals));
        json.endObject();
    }

    /**
     * {@code "corners"}: the slowest corners asked for ({@code --corners N}), slowest first, each
     * with where it is, its speed and the moves' (mm/min), and why ({@code junction} with the angle
     * and deviation, {@code arc} with the radius, {@code acceleration} with the short segment's
     * length, {@code reversal}). Written only when asked for.
     */
    private static void corners(Run run, JsonWriter json) throws IOException {
        if (run.report().corners().isEmpty()) {
            return;
        }
        json.name("corners").beginArray();
        for (gcnc.sim.Corner c : run.report().corners()) {
            json.beginObject();
            json.name("file").value(c.file() == null ? run.file() : c.file());
            json.name("line").value(c.line());
            if (c.number() != null) {
                json.name("number").value(c.number());
            }
            json.name("speedMmMin").value(round(c.speedMmMin(), 1));
            json.name("feedMmMin").value(round(c.feedMmMin(), 1));
            json.name("why").value(c.why().key());
            json.name("angleDeg").value(round(c.angleDeg(), 1));
            if (!Double.isNaN(c.deviationMm())) {
                json.name("deviationMm").value(round(c.deviationMm(), 4));
            }
            if (!Double.isNaN(c.radiusMm())) {
                json.name("radiusMm").value(round(c.radiusMm(), 3));
            }
            if (!Double.isNaN(c.lengthMm())) {
                json.name("lengthMm").value(round(c.lengthMm(), 3));
            }
            json.endObject();
        }
        json.endArray();
    }

    private static double round(double v, int decimals) {
        return new java.math.BigDecimal(v).setScale(decimals, java.math.RoundingMode.HALF_UP).doubleValue();
    }
}
