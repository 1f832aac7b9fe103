package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.sun.net.httpserver.HttpExchange;
import gcnc.output.AtomicOutput;
import gcnc.output.DmcOutputs;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The studio's JSON API (docs/studio.md lists each endpoint with its request and answer). Reads
 * are GET, everything else POST with a JSON body; every answer is JSON, an error
 * {@code {"error": message, "status": n}}. Checks and simulations take the page's text, never a
 * file, so the page checks what the user sees, saved or not; compile takes the saved file, so the
 * DMC and its map always belong to a program on disk.
 */
final class Api implements AutoCloseable {
    private final Workspace workspace;
    private final Analysis analysis;
    private final Studio.Config config;
    /** The open event streams, closed when the studio stops. */
    private final Set<OutputStream> streams = ConcurrentHashMap.newKeySet();
    private volatile boolean closed;
    /** Each stream holds one of the server's threads: a few pages, and the rest keep answering. */
    static final int MAX_STREAMS = 3;

    Api(Workspace workspace, Analysis analysis, Studio.Config config) {
        this.workspace = workspace;
        this.analysis = analysis;
        this.config = config;
    }

    Path root() {
        return workspace.root();
    }

    void handle(String endpoint, HttpExchange ex) throws IOException, Http.Fail {
        switch (endpoint) {
            case "info" -> Http.json(ex, 200, info(get(ex)));
            case "files" -> Http.json(ex, 200, files(get(ex)));
            case "file" -> Http.json(ex, 200, open(get(ex)));
            case "events" -> events(get(ex));
            case "save" -> Http.json(ex, 200, save(post(ex)));
            case "check" -> timed(ex, () -> check(post(ex)));
            case "simulate" -> timed(ex, () -> simulate(post(ex)));
            case "compile" -> timed(ex, () -> compile(post(ex)));
            default -> throw new Http.Fail(404, "no endpoint /api/" + Workspace.shown(endpoint));
        }
    }

    private interface Work {
        JsonObject run() throws IOException, Http.Fail;
    }

    /**
     * Answers with the work's JSON and, in a Server-Timing header ({@code gcnc;dur=12.3}), how long
     * the studio took for it in milliseconds: the browser's developer tools and bench/studio-recheck.sh
     * show it apart from the time on the wire.
     */
    private static void timed(HttpExchange ex, Work work) throws IOException, Http.Fail {
        long start = System.nanoTime();
        JsonObject answer = work.run();
        ex.getResponseHeaders().set("Server-Timing", String.format(Locale.ROOT, "gcnc;dur=%.1f", (System.nanoTime() - start) / 1e6));
        Http.json(ex, 200, answer);
    }

    private static HttpExchange get(HttpExchange ex) throws Http.Fail {
        if (!ex.getRequestMethod().equals("GET")) {
            throw new Http.Fail(405, "use GET for " + ex.getRequestURI().getRawPath());
        }
        return ex;
    }

    /** The JSON body of a POST (a page's fetch sends it as application/json). */
    private static JsonObject post(HttpExchange ex) throws IOException, Http.Fail {
        if (!ex.getRequestMethod().equals("POST")) {
            throw new Http.Fail(405, "use POST for " + ex.getRequestURI().getRawPath());
        }
        return Http.body(ex);
    }

    /** GET /api/info: what this studio serves: folder, machine, control, dialect, language, versions. */
    private JsonObject info(HttpExchange ex) {
        JsonObject o = new JsonObject();
        o.addProperty("folder", workspace.root().getFileName() == null ? "/" : workspace.root().getFileName().toString());
        o.addProperty("machine", config.session().profile().name());
        o.addProperty("control", config.session().profile().control().name());
        o.addProperty("dialect", config.session().options().dialect());
        o.addProperty("lang", config.lang().name().toLowerCase(Locale.ROOT));
        o.addProperty("version", config.version());
        JsonArray ext = new JsonArray();
        gcnc.ProgramFiles.EXTENSIONS.forEach(ext::add);
        o.add("extensions", ext);
        return o;
    }

    /** GET /api/files: the programs under the folder. */
    private JsonObject files(HttpExchange ex) throws IOException {
        JsonArray a = new JsonArray();
        for (Workspace.Entry e : workspace.list()) {
            JsonObject f = new JsonObject();
            f.addProperty("name", e.name());
            f.addProperty("size", e.size());
            f.addProperty("modified", e.modified());
            a.add(f);
        }
        JsonObject o = new JsonObject();
        o.add("files", a);
        return o;
    }

    /** GET /api/file?name=NAME: a program's text and version. */
    private JsonObject open(HttpExchange ex) throws IOException, Http.Fail {
        Workspace.Program p = refusing(() -> workspace.read(Guard.query(ex.getRequestURI(), "name")));
        return program(p);
    }

    /** POST /api/save {name, text, version?, force?}: written as one step; 409 when it changed on disk. */
    private JsonObject save(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        String text = Http.required(req, "text");
        String version = Http.string(req, "version");
        boolean force = Http.flag(req, "force");
        try {
            return program(refusing(() -> workspace.save(name, text, version, force)));
        } catch (AtomicOutput.Refused e) {
            throw new Http.Fail(403, "gcnc refuses to write " + name + " (" + e.code().id() + ")");
        } catch (IOException e) {
            throw new Http.Fail(500, "could not save " + name + ": " + reason(e));
        }
    }

    /** POST /api/check {name, text}: the diagnostics, as gcnc check --format json. */
    private JsonObject check(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        return analysis.check(name, Http.required(req, "text"), folder(name));
    }

    /** POST /api/simulate {name, text}: diagnostics, DMC, path, summary. */
    private JsonObject simulate(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        return analysis.simulate(name, Http.required(req, "text"), folder(name));
    }

    /** POST /api/compile {name}: the saved program compiled to NAME.dmc and NAME.dmc.map beside it. */
    private JsonObject compile(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        Path program = refusing(() -> workspace.existing(name));
        Path dmc = DmcOutputs.defaultOutput(program);
        String dmcName = workspace.name(dmc);
        refusing(() -> workspace.writable(dmc, dmcName, false));
        refusing(() -> workspace.writable(DmcOutputs.mapFile(dmc), dmcName + ".map", false));
        JsonObject o;
        try {
            o = analysis.compile(name, program, dmc);
        } catch (AtomicOutput.Refused e) {
            throw new Http.Fail(403, "gcnc refuses to write " + dmcName + " (" + e.code().id() + ")");
        } catch (IOException e) {
            throw new Http.Fail(500, "could not write " + dmcName + ": " + reason(e));
        }
        if (o.get("ok").getAsBoolean()) {
            o.addProperty("dmc", dmcName);
            o.addProperty("map", dmcName + ".map");
        }
        return o;
    }

    /**
     * GET /api/events: server-sent events. {@code files} whenever the list of programs changes
     * (a program made or removed outside the studio), so the page's list stays true; a comment
     * every few seconds keeps the stream open. The page's EventSource reconnects by itself.
     */
    private void events(HttpExchange ex) throws IOException, Http.Fail {
        if (streams.size() >= MAX_STREAMS) {
            throw new Http.Fail(503, "too many event streams open (" + MAX_STREAMS + "); close another studio tab");
        }
        ex.getResponseHeaders().set("Content-Type", "text/event-stream; charset=utf-8");
        ex.getResponseHeaders().set("Cache-Control", "no-store");
        ex.sendResponseHeaders(200, 0);
        OutputStream out = ex.getResponseBody();
        streams.add(out);
        try {
            String last = null;
            for (int beat = 0; !closed; beat++) {
                String now = files(ex).toString();
                if (!now.equals(last)) {
                    out.write(("event: files\ndata: " + now + "\n\n").getBytes(StandardCharsets.UTF_8));
                    last = now;
                } else if (beat % 10 == 0) {
                    out.write(": still here\n\n".getBytes(StandardCharsets.UTF_8));
                }
                out.flush();
                Thread.sleep(1000);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            streams.remove(out);
        }
    }

    @Override
    public void close() {
        closed = true;
        for (OutputStream s : List.copyOf(streams)) {
            try {
                s.close();
            } catch (IOException e) {
                // already gone
            }
        }
    }

    /** The folder a program's calls (M98) are looked for in: its own, when the name is a sound one. */
    private Optional<Path> folder(String name) {
        try {
            return Optional.ofNullable(workspace.resolve(name).getParent());
        } catch (Workspace.Refused e) {
            return Optional.of(workspace.root());
        }
    }

    private static JsonObject program(Workspace.Program p) {
        JsonObject o = new JsonObject();
        o.addProperty("name", p.name());
        o.addProperty("text", p.text());
        o.addProperty("version", p.version());
        return o;
    }

    private interface WorkspaceCall<T> {
        T call() throws Workspace.Refused, IOException;
    }

    /** A workspace call whose refusal becomes the answer (its status, its reason). */
    private static <T> T refusing(WorkspaceCall<T> call) throws IOException, Http.Fail {
        try {
            return call.call();
        } catch (Workspace.Refused r) {
            throw new Http.Fail(r.status(), r.getMessage());
        }
    }

    private static String reason(IOException e) {
        String m = e.getMessage();
        return e.getClass().getSimpleName() + (m == null ? "" : " " + m);
    }
}
