package gcnc;

import static gcnc.sim.SvgWriter.escape;

import gcnc.diag.Finding;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.sim.ProgramEnvelope;
import gcnc.sim.SetupFacts;
import gcnc.sim.SimReport;
import gcnc.sim.StockSize;
import gcnc.sim.ToolUse;
import java.io.IOException;
import java.io.Writer;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.List;
import java.util.Locale;

/**
 * A program's setup sheet, one self-contained HTML page (no script, no external style) in the
 * order a setup person works: the program (O number, file), the machine and its control, the
 * units, the blank and its stick-out from the jaws, where the work zero stands, the tool table
 * (station, kind, insert, nose radius, geometry and wear offsets, first and last line that moved it,
 * its share of the cycle),
 * the cycle time and the top spindle speed, every finding with its line, the envelope as the
 * program writes coordinates (and in the machine frame), and the drawing. No date: the same run
 * writes the same bytes. The Gradle plugin's {@code gcncSimulate} writes one per program, {@code gcnc
 * sheet FILE} one for FILE.
 */
public final class SetupSheet {
    private final String file;
    private final String number;
    private final MachineProfile profile;
    private final SimReport sim;
    private final List<Finding> findings;
    /** The program's spindle clamps (G50 S, G92 S on Fanuc system B) with their lines, in the program's order. */
    private final List<Clamp> clamps;

    /** One spindle clamp of the program: {@code G50 S3500} at line 3. */
    public record Clamp(String word, double rpm, int line) {
    }

    /**
     * @param file     the program as the reader knows it (a path relative to the project)
     * @param number   its O number ("O1201"), null when it has none
     * @param findings every finding of the run, in the program's order
     */
    public SetupSheet(String file, String number, MachineProfile profile, SimReport sim, List<Finding> findings) {
        this(file, number, profile, sim, findings, List.of());
    }

    private SetupSheet(String file, String number, MachineProfile profile, SimReport sim, List<Finding> findings,
                       List<Clamp> clamps) {
        this.file = file;
        this.number = number;
        this.profile = profile;
        this.sim = sim;
        this.findings = List.copyOf(findings);
        this.clamps = List.copyOf(clamps);
    }

    /**
     * This sheet with the spindle clamps the program sets, shown beside the top spindle speed: read
     * from the modal states its own compile saw ({@link ModalStates#view} as the compile's observer,
     * the checker's state after each block), so the program is not read and checked again.
     */
    public SetupSheet withClamps(java.util.Map<Integer, ModalStates.Snapshot> seen) {
        gcnc.machine.GFunction f = profile.control().gFor(gcnc.machine.GRole.REGISTER_AND_CLAMP).orElse(null);
        String g = f == null ? "G50" : "G" + f.code();
        java.util.Map<Integer, ModalStates.Snapshot> states = new java.util.TreeMap<>(seen);
        List<Clamp> found = new java.util.ArrayList<>();
        double last = Double.NaN;
        for (java.util.Map.Entry<Integer, ModalStates.Snapshot> e : states.entrySet()) {
            double c = e.getValue().state().rpmClamp();
            if (!Double.isNaN(c) && !(c == last)) {
                found.add(new Clamp(g + " S" + BigDecimal.valueOf(c).stripTrailingZeros().toPlainString(), c, e.getKey()));
            }
            last = c;
        }
        return new SetupSheet(file, number, profile, sim, findings, found);
    }

    /**
     * The sheet of one run: every finding of {@code diagnostics} in the program's order, its
     * message in {@code messages}' language (as the run's report prints it).
     */
    public static SetupSheet of(String file, String number, MachineProfile profile, SimReport sim,
                                gcnc.diag.Diagnostics diagnostics, gcnc.diag.Messages messages) {
        List<Finding> lines = new java.util.ArrayList<>();
        for (gcnc.diag.Diagnostic d : diagnostics.sorted()) {
            lines.add(Finding.of(file, d, messages));
        }
        return new SetupSheet(file, number, profile, sim, lines);
    }

    /**
     * One line for a build's log: "O1201, cycle about 0:00:15; part X -1.600..44.000 (diameter), Z
     * -25.001..2.000 mm from work zero; 2 tools; no findings" (the part: the feed moves; every
     * move's envelope, home moves too, when nothing fed).
     */
    public String summary() {
        String where = sim.feeds() == null ? envelope() : "part " + envelope(sim.feeds());
        return (number == null ? "" : number + ", ") + "cycle about " + clock(sim.cycleSeconds()) + "; " + where
                + "; " + plural(sim.setup().tools().stream().filter(t -> t.station() != 0).count(), "tool") + "; "
                + (findings.isEmpty() ? "no findings" : plural(findings.size(), "finding"));
    }

    /** The envelope in program terms (the machine frame when the program frame is not known). */
    public String envelope() {
        ProgramEnvelope p = sim.program();
        if (Double.isNaN(sim.xMinMm())) {
            return "no motion";
        }
        if (p == null) {
            return machineEnvelope();
        }
        return envelope(p);
    }

    private static String envelope(ProgramEnvelope p) {
        return "X " + programmed(p.xMin(), p.units()) + ".." + programmed(p.xMax(), p.units()) + " (" + p.xMode()
                + "), Z " + programmed(p.zMin(), p.units()) + ".." + programmed(p.zMax(), p.units()) + " " + p.unit()
                + " from work zero";
    }

    private String machineEnvelope() {
        return String.format(Locale.ROOT, "X %.3f..%.3f mm (radius), Z %.3f..%.3f mm", sim.xMinMm(), sim.xMaxMm(),
                sim.zMinMm(), sim.zMaxMm());
    }

    /** The page, with {@code svg} (gcnc's own drawing of the run) as its last section. */
    public void write(String svg, Writer w) throws IOException {
        SetupFacts s = sim.setup();
        w.write("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Setup sheet: "
                + escape(title()) + "</title>\n<style>body{font-family:sans-serif;margin:2em}"
                + "table{border-collapse:collapse;margin-bottom:1em}td,th{text-align:left;padding:.2em 1em .2em 0;"
                + "vertical-align:top}table.grid td,table.grid th{border:1px solid #ccc;padding:2px 8px}"
                + ".error{color:#b00}.warning{color:#a60}svg{max-width:100%;height:auto}</style></head><body>\n");
        w.write("<h1>Setup sheet: " + escape(title()) + "</h1>\n<table>\n");
        for (String[] r : rows()) {
            row(w, r[0], r[1]);
        }
        w.write("</table>\n");
        tools(w, s);
        findings(w);
        w.write("<h2>Drawing</h2>\n");
        // The drawing is gcnc's own SVG; its XML declaration-free markup embeds as it is.
        w.write(svg);
        w.write("\n</body></html>\n");
    }

    /** The sheet's head, each row {name, value}, as the HTML page and the PNG show it. */
    public List<String[]> rows() {
        SetupFacts s = sim.setup();
        List<String[]> r = new java.util.ArrayList<>();
        r.add(new String[] {"Program", number == null ? "(no O number)" : number});
        r.add(new String[] {"File", file});
        r.add(new String[] {"Machine / control", profile.name() + " / " + profile.control().name()});
        r.add(new String[] {"Units", units()});
        r.add(new String[] {"Blank", blank(s)});
        r.add(new String[] {"Work zero", workZero(s)});
        r.add(new String[] {"Cycle time (estimate)", clock(sim.cycleSeconds())});
        r.add(new String[] {"Cycle time stopping at every move", clock(sim.exactStopSeconds())});
        r.add(new String[] {"Maximum spindle speed", (Double.isNaN(s.maxRpm()) ? "not known" : Math.round(s.maxRpm()) + " rpm")
                + clampText()});
        r.add(new String[] {"Part (feed moves, as programmed)", sim.feeds() == null ? "no feed move" : envelope(sim.feeds())});
        r.add(new String[] {"Envelope (every move, as programmed)", envelope()});
        r.add(new String[] {"Envelope (machine frame)", Double.isNaN(sim.xMinMm()) ? "no motion" : machineEnvelope()});
        r.add(new String[] {"Findings", findings.isEmpty() ? "none" : Integer.toString(findings.size())});
        return r;
    }

    /** "; the program's limit G50 S3500 (line 3)" (each clamp it sets), or nothing. */
    private String clampText() {
        if (clamps.isEmpty()) {
            return "";
        }
        StringBuilder b = new StringBuilder("; the program's limit ");
        for (int i = 0; i < clamps.size(); i++) {
            b.append(i == 0 ? "" : ", ").append(clamps.get(i).word()).append(" (line ").append(clamps.get(i).line()).append(')');
        }
        return b.toString();
    }

    /** The tool table's rows as text, for the PNG: "T1 turn CNMG 432, nose 0.8 mm, ..." . */
    public List<String> toolLines() {
        List<String> out = new java.util.ArrayList<>();
        for (ToolUse t : sim.setup().tools()) {
            String nose = t.station() == 0 ? "" : length(profile.nose(t.station()).radius() / profile.x().countsPerMm());
            String insert = t.described() ? t.insert() : t.insert() + " (assumed: not described in the profile)";
            out.add((t.station() == 0 ? "none selected" : "T" + t.station()) + "  "
                    + t.kind().name().toLowerCase(Locale.ROOT).replace('_', ' ') + "  " + insert
                    + (nose.isEmpty() ? "" : "  nose " + nose) + (t.station() == 0 ? "" : "  geometry " + geometry(t.station())
                    + "  wear " + wear(t.station())) + "  lines " + t.firstLine() + "-" + t.lastLine() + "  " + clock(t.seconds()));
        }
        return out;
    }

    /** Each finding as one line, "12:5 error E305 message", in the program's order. */
    public List<String> findingLines() {
        List<String> out = new java.util.ArrayList<>();
        for (Finding f : findings) {
            out.add(f.diagnostic().span().line() + ":" + f.diagnostic().span().column() + " "
                    + f.diagnostic().severity().label() + " " + f.diagnostic().code().id() + " " + f.message());
        }
        return out;
    }

    /** The sheet's title: "O1201 (part.nc)". */
    public String heading() {
        return "Setup sheet: " + title();
    }

    /** The run the sheet is of. */
    public SimReport report() {
        return sim;
    }

    private String title() {
        return number == null ? file : number + " (" + file + ")";
    }

    private String units() {
        ProgramEnvelope p = sim.program();
        if (p == null) {
            return "not known (no program frame)";
        }
        return (p.units() == Units.INCH ? "inch (G20)" : "mm (G21)") + "; X is a " + p.xMode();
    }

    private String blank(SetupFacts s) {
        if (s.blank().isEmpty()) {
            return "none (the stock checks were skipped)";
        }
        StockSize b = s.blank().get();
        return "diameter " + length(b.diameter()) + (b.bore() > 0 ? ", bore " + length(b.bore()) : "")
                + ", length " + length(b.length()) + "; sticks out " + length(b.stickout()) + " from the jaws' face";
    }

    private String workZero(SetupFacts s) {
        if (Double.isNaN(s.workZeroZMm())) {
            return "not known";
        }
        String face = Double.isNaN(s.chuckFaceMm()) ? "" : length(s.workZeroFromFaceMm()) + " in front of the jaws' face; ";
        return "Z0 " + face + "machine X " + mm(s.workZeroXMm()) + " Z " + mm(s.workZeroZMm())
                + " mm (work offset + tool offset of the first cut)";
    }

    /** A length in the program's units first: "2 in (50.8 mm)" for an inch program, "50.8 mm" otherwise. */
    private String length(double mm) {
        ProgramEnvelope p = sim.program();
        if (p == null || p.units() != Units.INCH) {
            return mm(mm) + " mm";
        }
        return BigDecimal.valueOf(mm / 25.4).setScale(4, RoundingMode.HALF_UP).stripTrailingZeros().toPlainString()
                + " in (" + mm(mm) + " mm)";
    }

    private void tools(Writer w, SetupFacts s) throws IOException {
        w.write("<h2>Tools</h2>\n");
        if (s.tools().isEmpty()) {
            w.write("<p>No tool moved.</p>\n");
            return;
        }
        w.write("<table class=\"grid\">\n<tr><th>station</th><th>kind</th><th>insert</th><th>nose radius</th>"
                + "<th>geometry (offset N)</th><th>wear (offset N)</th>"
                + "<th>first line</th><th>last line</th><th>time</th></tr>\n");
        for (ToolUse t : s.tools()) {
            String nose = t.station() == 0 ? "" : length(profile.nose(t.station()).radius() / profile.x().countsPerMm());
            String insert = t.described() ? t.insert() : t.insert() + " (assumed: not described in the profile)";
            w.write("<tr><td>" + (t.station() == 0 ? "none selected" : "T" + t.station()) + "</td><td>"
                    + t.kind().name().toLowerCase(Locale.ROOT).replace('_', ' ') + "</td><td>" + escape(insert)
                    + "</td><td>" + nose + "</td><td>" + escape(geometry(t.station())) + "</td><td>"
                    + escape(wear(t.station())) + "</td><td>" + t.firstLine() + "</td><td>" + t.lastLine() + "</td><td>"
                    + clock(t.seconds()) + "</td></tr>\n");
        }
        w.write("</table>\n");
    }

    /**
     * Tool offset {@code n}'s geometry as the profile writes it (mm, X a radius in the machine
     * frame): the offset of the same number as the station, as T0N0N selects it.
     */
    private String geometry(int n) {
        if (n == 0) {
            return "";
        }
        return profile.toolOffset(n).map(g -> "X " + mm(g.x() / profile.x().countsPerMm()) + " Z "
                + mm(g.z() / profile.z().countsPerMm()) + " mm (tool." + n + ", X a radius)").orElse("none");
    }

    /** Tool offset {@code n}'s wear ({@code wear.N}: X as the program writes it) and the file it is in, or "none". */
    private String wear(int n) {
        if (n == 0) {
            return "";
        }
        return profile.wear().of(n).map(w -> profile.wear().describe(n, profile.diameterX()).substring(4) + " from "
                + w.file()).orElse("none");
    }

    private void findings(Writer w) throws IOException {
        w.write("<h2>Findings</h2>\n");
        if (findings.isEmpty()) {
            w.write("<p>None.</p>\n");
            return;
        }
        w.write("<table class=\"grid\">\n<tr><th>line</th><th>severity</th><th>code</th><th>message</th></tr>\n");
        for (Finding f : findings) {
            String severity = f.diagnostic().severity().label();
            w.write("<tr><td>" + f.diagnostic().span().line() + ":" + f.diagnostic().span().column() + "</td><td class=\""
                    + severity + "\">" + severity + "</td><td>" + f.diagnostic().code().id() + "</td><td>"
                    + escape(f.message()) + "</td></tr>\n");
        }
        w.write("</table>\n");
    }

    private static void row(Writer w, String name, String value) throws IOException {
        w.write("<tr><th>" + escape(name) + "</th><td>" + escape(value) + "</td></tr>\n");
    }

    /** h:mm:ss */
    static String clock(double seconds) {
        long s = Math.round(seconds);
        return String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60);
    }

    private static String programmed(double v, Units u) {
        return BigDecimal.valueOf(v).setScale(u == Units.INCH ? 4 : 3, RoundingMode.HALF_UP).toPlainString();
    }

    /** Up to 3 decimals, no trailing zeros. */
    private static String mm(double v) {
        return BigDecimal.valueOf(v).setScale(3, RoundingMode.HALF_UP).stripTrailingZeros().toPlainString();
    }

    private static String plural(long n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }
}
