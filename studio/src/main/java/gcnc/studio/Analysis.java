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
import gcnc.sim.Shape;
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

    /** The program's diagnostics, as {@code gcnc check --format json} prints them. */
    JsonObject check(String name, String text, Optional<Path> folder) throws IOException {
        Compiler.Result r = session.withPrograms(folder).check(new StringReader(text));
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
                doc.add("drawing", drawing(s.drawing(), fileNames));
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
            outputs.mapSource(program.getFileName().toString(), program); // its name and SHA-256, as gcnc compile writes them
            try (Reader in = Session.decode(Files.newInputStream(program))) {
                // the form that fits the profile's controller, as gcnc compile chooses it
                r = session.withPrograms(Optional.ofNullable(program.getParent())).compile(in,
                        Optional.of(session.simulation()), false, outputs.sink(Optional.empty(), session.profile().controllerLimits()));
            }
            if (r.ok()) {
                outputs.finish(r.diagnostics());
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
        Frame f = new Frame(d.program());
        o.addProperty("tool", s.tool());
        o.addProperty("first", s.first());
        o.addProperty("last", s.last());
        o.add("before", outline(s.beforeZ(), s.beforeR(), f));
        o.add("after", outline(s.afterZ(), s.afterR(), f));
        if (s.insert() != null) {
            o.add("insert", shape(s.insert(), f));
        }
        if (s.holder() != null) {
            o.add("holder", shape(s.holder(), f));
        }
        o.addProperty("programFrame", d.program() != null);
        return o;
    }

    /** A stock outline with the points of each flat stretch but its ends left out: the same steps, a much shorter answer. */
    private static JsonObject outline(double[] z, double[] r, Frame f) {
        List<Integer> keep = new ArrayList<>();
        for (int i = 0; i < z.length; i++) {
            if (i == 0 || i == z.length - 1 || r[i] != r[i - 1] || r[i] != r[i + 1]) {
                keep.add(i);
            }
        }
        double[] zs = new double[keep.size()];
        double[] rs = new double[keep.size()];
        for (int k = 0; k < zs.length; k++) {
            zs[k] = z[keep.get(k)];
            rs[k] = r[keep.get(k)];
        }
        JsonObject o = new JsonObject();
        o.add("z", f.zs(zs));
        o.add("x", f.xs(rs));
        return o;
    }

    private static JsonObject shape(Shape s, Frame f) {
        JsonObject o = new JsonObject();
        o.add("z", f.zs(java.util.Arrays.copyOf(s.z(), s.size())));
        o.add("x", f.xs(java.util.Arrays.copyOf(s.r(), s.size())));
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
            if (d.severity() == gcnc.diag.Severity.ERROR || d.code().name().contains("_SIM_")) {
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

    /** The diagnostics of a result as {@code gcnc check --format json} writes them, each finding's file being {@code name}. */
    JsonObject report(String name, Compiler.Result r) throws IOException {
        List<Finding> findings = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            findings.add(Finding.of(name, d, messages));
        }
        StringWriter w = new StringWriter();
        JsonRenderer.write(findings, toolVersion, w);
        return JsonParser.parseString(w.toString()).getAsJsonObject();
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
        return o;
    }

    /** NaN and infinities are not JSON: null instead (nothing moved). */
    private static Double finite(double v) {
        return Double.isFinite(v) ? v : null;
    }

    /**
     * The drawing in the program's coordinates: z along the spindle as the program writes Z, x as the
     * program writes X (a diameter on a lathe whose control reads one). Without a program frame (no
     * move), machine millimetres with x as twice the radius.
     */
    private static JsonObject drawing(Drawing d, java.util.function.Function<String, Optional<String>> fileNames) {
        Frame f = new Frame(d.program());
        JsonObject o = new JsonObject();
        JsonArray moves = new JsonArray();
        for (Drawing.Move m : d.moves()) {
            JsonObject mv = new JsonObject();
            mv.addProperty("line", m.line());
            if (m.file() != null) { // a called program's line: the page opens that file to show it
                Optional<String> named = fileNames.apply(m.file());
                if (named.isPresent()) {
                    mv.addProperty("file", named.get());
                } else {
                    mv.addProperty("elsewhere", true);
                }
            }
            mv.addProperty("rapid", m.rapid());
            mv.add("z", f.zs(m.z()));
            mv.add("x", f.xs(m.r()));
            moves.add(mv);
        }
        o.add("moves", moves);
        o.add("chuck", shapes(d.chuck(), f));
        o.add("tailstock", shapes(d.tailstock(), f));
        if (!Double.isNaN(d.stockRadius())) {
            JsonObject stock = new JsonObject();
            stock.addProperty("zBack", f.z(d.stockBack()));
            stock.addProperty("zFace", f.z(d.stockFace()));
            stock.addProperty("x", f.x(d.stockRadius()));
            stock.addProperty("xAxis", f.x(0));
            JsonObject part = new JsonObject();
            part.add("z", f.zs(d.finalZ()));
            part.add("x", f.xs(d.finalR()));
            stock.add("final", part);
            o.add("stock", stock);
        }
        JsonArray marks = new JsonArray();
        for (Drawing.Mark m : d.marks()) {
            JsonObject mk = new JsonObject();
            mk.addProperty("code", m.code());
            mk.addProperty("block", m.block());
            mk.addProperty("z", f.z(m.z()));
            mk.addProperty("x", f.x(m.r()));
            marks.add(mk);
        }
        o.add("marks", marks);
        o.addProperty("programFrame", d.program() != null);
        return o;
    }

    private static JsonArray shapes(List<Shape> shapes, Frame f) {
        JsonArray a = new JsonArray();
        for (Shape s : shapes) {
            JsonObject o = new JsonObject();
            o.add("z", f.zs(s.z()));
            o.add("x", f.xs(s.r()));
            a.add(o);
        }
        return a;
    }

    /** From the drawing's (z, r) millimetres to the program's (Z, X). */
    private record Frame(Drawing.ProgramAxes axes) {
        double z(double z) {
            return round(axes == null ? z : (z - axes.z0()) / axes.zPer());
        }

        double x(double r) {
            return round(axes == null ? 2 * r : (r - axes.r0()) / axes.xPer());
        }

        JsonArray zs(double[] v) {
            JsonArray a = new JsonArray();
            for (double d : v) {
                a.add(z(d));
            }
            return a;
        }

        JsonArray xs(double[] v) {
            JsonArray a = new JsonArray();
            for (double d : v) {
                a.add(x(d));
            }
            return a;
        }

        /** Micrometres are plenty for a drawing, and keep the JSON short. */
        private static double round(double v) {
            if (!Double.isFinite(v)) {
                return v > 0 ? 1e9 : -1e9;
            }
            return Math.round(v * 1000) / 1000.0;
        }
    }
}
