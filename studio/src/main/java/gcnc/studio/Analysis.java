package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.diag.Finding;
import gcnc.diag.JsonRenderer;
import gcnc.diag.Messages;
import gcnc.dmc.DmcPrinter;
import gcnc.output.DmcOutputs;
import gcnc.output.FormOutputs;
import gcnc.sim.Drawing;
import gcnc.sim.SimReport;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * What the studio asks of gcnc, all through the one {@link Session} the command line also uses, so
 * the page never disagrees with {@code gcnc check} or {@code gcnc compile}: diagnostics in the
 * {@code --format json} document (JsonRenderer), the simulated path with the G-code line of each
 * move, the DMC with the G-code line of each of its lines, and the compile that writes the DMC and
 * its map beside the program.
 */
final class Analysis {
    private final Session session;
    private final Messages messages;
    private final String toolVersion;
    /** A called program's file as the page names it (relative to DIR), empty when it is not under DIR. */
    private final java.util.function.Function<String, Optional<String>> fileNames;

    Analysis(Session session, Messages messages, String toolVersion,
             java.util.function.Function<String, Optional<String>> fileNames) {
        this.session = session;
        this.messages = messages;
        this.toolVersion = toolVersion;
        this.fileNames = fileNames;
    }

    /** The program's diagnostics, as {@code gcnc check --format json} prints them; what the check saw goes to {@code observer}. */
    JsonObject check(String name, String text, Optional<Path> folder, gcnc.CompileObserver observer) throws IOException {
        Compiler.Result r = session.withPrograms(folder).check(new StringReader(text), observer);
        JsonObject doc = report(name, r);
        doc.addProperty("blocks", r.blocks());
        return doc;
    }

    /**
     * Check, translate and simulate the text: the diagnostics, the DMC lines with their G-code lines,
     * the tool path as polylines in the program's coordinates (Z along, X as the program gives it,
     * a diameter on a lathe) each with its G-code line, the blank, chuck and tailstock, the summary.
     */
    JsonObject simulate(String name, String text, Optional<Path> folder) throws IOException {
        JsonArray dmc = new JsonArray();
        // the lines packed as gcnc compile packs its program form; each command keeps its G-code line
        gcnc.dmc.LinePacker packer = new gcnc.dmc.LinePacker(session.profile().controllerLimits().lineWidth(), packed -> {
            JsonObject l = new JsonObject();
            l.addProperty("text", packed.text());
            JsonArray parts = new JsonArray();
            for (gcnc.dmc.Instruction i : packed.instructions()) {
                JsonObject c = new JsonObject();
                c.addProperty("text", DmcPrinter.print(i.command()));
                c.addProperty("line", i.source().line());
                if (i.source().file() != null) { // a called program's line: named as the page names files
                    Optional<String> named = fileNames.apply(i.source().file());
                    if (named.isPresent()) {
                        c.addProperty("file", named.get());
                    } else {
                        c.addProperty("elsewhere", true);
                    }
                }
                parts.add(c);
            }
            l.addProperty("line", parts.get(0).getAsJsonObject().get("line").getAsInt());
            l.add("parts", parts);
            dmc.add(l);
        });
        Compiler.Result r = session.withPrograms(folder).compile(new StringReader(text),
                Optional.of(session.simulation().withPath()), false, packer);
        packer.flush();
        JsonObject doc = new JsonObject();
        doc.add("diagnostics", report(name, r));
        doc.addProperty("blocks", r.blocks());
        // after an error the DMC is void (nothing after it is translated): the page shows none
        doc.add("dmc", r.ok() ? dmc : new JsonArray());
        r.simulation().ifPresent(s -> {
            doc.add("summary", summary(s));
            if (s.drawing() != null) {
                doc.add("drawing", DrawingJson.drawing(s.drawing(), fileNames));
            }
        });
        return doc;
    }

    /**
     * Compiles a saved program as {@code gcnc compile FILE} does: the DMC and its map written beside
     * it as one step, only when there is no error. {@code dmc} and {@code map} are the outputs,
     * already checked by the {@link Workspace} (inside DIR, never a link or a device).
     */
    JsonObject compile(String name, Path program, Path dmc) throws IOException {
        JsonObject doc = new JsonObject();
        Compiler.Result r;
        try (FormOutputs outputs = FormOutputs.open(program, dmc, true, gcnc.output.AtomicOutput.Name.DERIVED)) {
            try (Reader in = Session.decode(Files.newInputStream(program))) {
                // the form that fits the profile's controller, as gcnc compile chooses it; the maps name the
                // program and its SHA-256, as gcnc compile writes them
                r = session.withPrograms(Optional.ofNullable(program.getParent())).compileInto(outputs,
                        program.getFileName().toString(), program, in, Optional.of(session.simulation()), false,
                        Optional.empty(), false, gcnc.CompileObserver.NONE);
            }
            doc.add("diagnostics", report(name, r));
            doc.addProperty("ok", r.ok());
            doc.addProperty("blocks", r.blocks());
            if (r.ok()) {
                outputs.commit();
                doc.addProperty("dmcLines", outputs.dmcLines());
                doc.addProperty("form", outputs.form().key());
                if (outputs.streamLines() > 0) {
                    doc.addProperty("streamLines", outputs.streamLines());
                }
            }
        } catch (DmcOutputs.Failed e) {
            throw e.problem();
        }
        r.simulation().ifPresent(s -> doc.add("summary", summary(s)));
        return doc;
    }

    /**
     * The scrub: the stock as it stood before and after the first run of {@code line}'s moves, and
     * the insert and holder where the run ended, in the program's coordinates as the drawing's.
     * {@code found} is false when that line moved nothing (or the program has an error).
     */
    JsonObject scrub(String name, String text, int line, Optional<Path> folder) throws IOException {
        Compiler.Result r = session.withPrograms(folder).compile(new StringReader(text),
                Optional.of(session.simulation().withScrub(line)), false, l -> { });
        JsonObject o = new JsonObject();
        o.addProperty("line", line);
        Drawing d = r.simulation().map(SimReport::drawing).orElse(null);
        Drawing.Scrub s = d == null ? null : d.scrub();
        o.addProperty("found", s != null);
        if (s == null) {
            o.addProperty("errors", r.diagnostics().sorted().stream().filter(x -> x.severity() == gcnc.diag.Severity.ERROR).count());
            return o;
        }
        DrawingJson.Frame f = new DrawingJson.Frame(d.program());
        o.addProperty("tool", s.tool());
        o.addProperty("first", s.first());
        o.addProperty("last", s.last());
        o.add("before", DrawingJson.outline(s.beforeZ(), s.beforeR(), f));
        o.add("after", DrawingJson.outline(s.afterZ(), s.afterR(), f));
        if (s.insert() != null) {
            o.add("insert", DrawingJson.shape(s.insert(), f));
        }
        if (s.holder() != null) {
            o.add("holder", DrawingJson.shape(s.holder(), f));
        }
        o.addProperty("programFrame", d.program() != null);
        return o;
    }

    /**
     * What an edited profile changes for a program: the findings (errors, and the simulator's
     * findings: travel, collisions, cuts into the stock) at a line with {@code edited} that this
     * studio's profile does not give there ({@code became}), and those it gives that the edited one
     * does not ({@code gone}). A finding is its file, line and code: a message that only quotes
     * the new limit is the same finding.
     */
    JsonObject impact(Analysis edited, String name, String text, Optional<Path> folder) throws IOException {
        Map<String, Finding> now = findings(name, text, folder);
        Map<String, Finding> then = edited.findings(name, text, folder);
        JsonObject o = new JsonObject();
        o.add("became", only(then, now));
        o.add("gone", only(now, then));
        return o;
    }

    private Map<String, Finding> findings(String name, String text, Optional<Path> folder) throws IOException {
        Compiler.Result r = session.withPrograms(folder).compile(new StringReader(text), Optional.of(session.simulation()),
                false, l -> { });
        Map<String, Finding> out = new java.util.LinkedHashMap<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            if (d.severity() == gcnc.diag.Severity.ERROR || simulator(d)) {
                Finding f = Finding.of(name, d, messages);
                out.putIfAbsent(f.file() + ':' + d.span().line() + ':' + d.code().id(), f);
            }
        }
        return out;
    }

    private static JsonArray only(Map<String, Finding> in, Map<String, Finding> notIn) {
        JsonArray a = new JsonArray();
        for (Map.Entry<String, Finding> e : in.entrySet()) {
            if (!notIn.containsKey(e.getKey())) {
                Finding f = e.getValue();
                JsonObject o = new JsonObject();
                o.addProperty("file", f.file());
                o.addProperty("line", f.diagnostic().span().line());
                o.addProperty("column", f.diagnostic().span().column());
                o.addProperty("code", f.diagnostic().code().id());
                o.addProperty("severity", f.diagnostic().severity().name().toLowerCase(java.util.Locale.ROOT));
                o.addProperty("message", f.message());
                a.add(o);
            }
        }
        return a;
    }

    /**
     * The simulator's findings among a report's diagnostics marked {@code "simulator": true}: the
     * page keeps them in its error list while the next simulation of an edited text runs (the check
     * that comes first does not make them). The report lists the diagnostics in the result's order.
     */
    private static void markSimulator(Compiler.Result r, JsonObject report) {
        JsonArray listed = report.getAsJsonArray("diagnostics");
        List<Diagnostic> all = r.diagnostics().sorted();
        for (int i = 0; i < listed.size() && i < all.size(); i++) {
            if (simulator(all.get(i))) {
                listed.get(i).getAsJsonObject().addProperty("simulator", true);
            }
        }
    }

    /** A finding of the simulator (gcnc.sim: travel, collisions, cuts into the stock ...), not of the check. */
    static boolean simulator(Diagnostic d) {
        return d.code().name().contains("_SIM_");
    }

    /**
     * The diagnostics of a result as {@code gcnc check --format json} writes them, each finding's file
     * being {@code name}; the simulator's marked (a check has none).
     */
    JsonObject report(String name, Compiler.Result r) throws IOException {
        List<Finding> findings = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            findings.add(Finding.of(name, d, messages));
        }
        StringWriter w = new StringWriter();
        JsonRenderer.write(findings, toolVersion, w);
        JsonObject report = JsonParser.parseString(w.toString()).getAsJsonObject();
        markSimulator(r, report);
        return report;
    }

    private static JsonObject summary(SimReport s) {
        JsonObject o = new JsonObject();
        o.addProperty("cycleSeconds", finite(s.cycleSeconds()));
        o.addProperty("exactStopSeconds", finite(s.exactStopSeconds()));
        o.addProperty("sequences", s.sequences());
        o.addProperty("segments", s.segments());
        o.addProperty("findings", s.findings());
        JsonObject extents = new JsonObject();
        extents.addProperty("xMinMm", finite(s.xMinMm()));
        extents.addProperty("xMaxMm", finite(s.xMaxMm()));
        extents.addProperty("zMinMm", finite(s.zMinMm()));
        extents.addProperty("zMaxMm", finite(s.zMaxMm()));
        o.add("machineExtents", extents);
        // the envelopes in the program's terms, as gcnc simulate prints them first: the part's (the feed
        // moves) apart from every move's (the rapids and home moves too)
        if (s.feeds() != null) {
            o.add("part", envelope(s.feeds()));
        }
        if (s.program() != null) {
            o.add("program", envelope(s.program()));
        }
        return o;
    }

    /** An envelope as the program writes coordinates: its unit, whether X is a diameter, the limits. */
    private static JsonObject envelope(gcnc.sim.ProgramEnvelope e) {
        JsonObject o = new JsonObject();
        o.addProperty("unit", e.unit());
        o.addProperty("diameter", e.diameter());
        o.addProperty("xMin", finite(e.xMin()));
        o.addProperty("xMax", finite(e.xMax()));
        o.addProperty("zMin", finite(e.zMin()));
        o.addProperty("zMax", finite(e.zMax()));
        return o;
    }

    /** NaN and infinities are not JSON: null instead (nothing moved). */
    private static Double finite(double v) {
        return Double.isFinite(v) ? v : null;
    }

}
