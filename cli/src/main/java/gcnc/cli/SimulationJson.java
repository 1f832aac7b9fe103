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
            boolean moved = !Double.isNaN(r.xMinMm());
            ProgramEnvelope p = r.program();
            if (moved && p != null) {
                int decimals = p.units() == gcnc.machine.Units.INCH ? 4 : 3;
                json.name("program").beginObject();
                json.name("units").value(p.unit());
                json.name("x").value(p.xMode());
                json.name("xMin").value(round(p.xMin(), decimals));
                json.name("xMax").value(round(p.xMax(), decimals));
                json.name("zMin").value(round(p.zMin(), decimals));
                json.name("zMax").value(round(p.zMax(), decimals));
                json.endObject();
            }
            if (moved) {
                json.name("machine").beginObject();
                json.name("xMinMm").value(round(r.xMinMm(), 3));
                json.name("xMaxMm").value(round(r.xMaxMm(), 3));
                json.name("zMinMm").value(round(r.zMinMm(), 3));
                json.name("zMaxMm").value(round(r.zMaxMm(), 3));
                json.endObject();
            }
            json.endObject();
        }
        json.endArray();
    }

    private static double round(double v, int decimals) {
        return new java.math.BigDecimal(v).setScale(decimals, java.math.RoundingMode.HALF_UP).doubleValue();
    }
}
