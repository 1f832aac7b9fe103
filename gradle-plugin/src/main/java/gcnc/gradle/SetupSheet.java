package gcnc.gradle;

import gcnc.sim.SimReport;
import java.io.IOException;
import java.io.Writer;
import java.util.List;
import java.util.Locale;

/**
 * A program's setup sheet for the operator, as one self-contained HTML page: the machine, the
 * travel envelope (the extents the setup must allow), the estimated cycle time, the simulator's
 * findings and the tool path drawing.
 */
final class SetupSheet {
    private final String program;
    private final String machine;
    private final SimReport sim;
    private final List<String> findings;

    SetupSheet(String program, String machine, SimReport sim, List<String> findings) {
        this.program = program;
        this.machine = machine;
        this.sim = sim;
        this.findings = List.copyOf(findings);
    }

    /** "cycle about 0:01:05; X 0.000..25.000 mm (radius), Z -40.000..2.000 mm; 12 segments; no findings" */
    String summary() {
        return "cycle about " + cycle() + "; " + extents() + "; " + GcncTask.plural(sim.segments(), "segment") + "; "
                + (findings.isEmpty() ? "no findings" : GcncTask.plural(findings.size(), "finding"));
    }

    String cycle() {
        long s = Math.round(sim.cycleSeconds());
        return String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
    }

    String extents() {
        return Double.isNaN(sim.xMinMm()) ? "no motion" : String.format(Locale.ROOT,
                "X %.3f..%.3f mm (radius), Z %.3f..%.3f mm", sim.xMinMm(), sim.xMaxMm(), sim.zMinMm(), sim.zMaxMm());
    }

    void write(String svg, Writer w) throws IOException {
        w.write("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Setup sheet: "
                + escape(program) + "</title>\n<style>body{font-family:sans-serif;margin:2em}"
                + "td,th{text-align:left;padding:.2em 1em .2em 0}svg{max-width:100%;height:auto}</style></head><body>\n");
        w.write("<h1>Setup sheet: " + escape(program) + "</h1>\n<table>\n");
        row(w, "Machine", machine);
        row(w, "Travel envelope (machine coordinates)", extents());
        row(w, "Cycle time (estimate)", cycle());
        row(w, "Motions", sim.sequences() + " sequences, " + sim.segments() + " segments");
        row(w, "Findings", findings.isEmpty() ? "none" : Integer.toString(findings.size()));
        w.write("</table>\n");
        if (!findings.isEmpty()) {
            w.write("<h2>Findings</h2>\n<ul>\n");
            for (String f : findings) {
                w.write("<li><code>" + escape(f) + "</code></li>\n");
            }
            w.write("</ul>\n");
        }
        w.write("<h2>Tool path</h2>\n");
        // The drawing is gcnc's own SVG; its XML declaration-free markup embeds as it is.
        w.write(svg);
        w.write("\n</body></html>\n");
    }

    private static void row(Writer w, String name, String value) throws IOException {
        w.write("<tr><th>" + escape(name) + "</th><td>" + escape(value) + "</td></tr>\n");
    }

    static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
