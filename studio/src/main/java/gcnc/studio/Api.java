package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.sun.net.httpserver.HttpExchange;
import gcnc.Session;
import gcnc.diag.Messages;
import gcnc.output.AtomicOutput;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;

/**
 * The studio's JSON API (docs/studio.md lists each endpoint with its request and answer). Reads
 * are GET, everything else POST with a JSON body; every answer is JSON, an error
 * {@code {"error": message, "status": n}}. Checks and simulations take the page's text, never a
 * file, so the page checks what the user sees, saved or not; compile takes the saved file, so the
 * DMC and its map always belong to a program on disk.
 */
final class Api implements AutoCloseable {
    private final Workspace workspace;
    private final Studio.Config config;
    private final Messages messages;
    /**
     * Everything that depends on the machine profile: replaced as a whole when Configure saves an
     * edited profile, so that a request sees one profile from start to end.
     */
    private record Engine(Session session, Analysis analysis, Modal modal, ProfileEdit profile, String profileFile) {
    }

    private volatile Engine engine;
    /** What the event streams carry besides the list of files: a run's events. */
    private final EventHub hub = new EventHub();
    /** The Run screen: MEMORY mode on a controller. */
    private final Runs runs;
    /** The test-cut form after a run. */
    private final TestCuts testCuts;
    /** GET /api/events: the open event streams, closed when the studio stops. */
    private final EventStreams events;
    Api(Workspace workspace, Studio.Config config) {
        this.workspace = workspace;
        this.config = config;
        this.messages = config.session().tables().messages().in(config.lang());
        this.engine = engine(config.session(), null, null);
        this.runs = new Runs(workspace, () -> {
            Engine e = engine;
            return new Runs.Context(e.session(), e.analysis(), e.profileFile());
        }, messages, hub, config.running());
        this.testCuts = new TestCuts(workspace, messages);
        this.events = new EventStreams(hub, ex -> files(ex).toString());
    }

    private Engine engine(Session session, ProfileEdit profile, String profileFile) {
        return new Engine(session, analysis(session), new Modal(session, config.lang()), profile, profileFile);
    }

    private Analysis analysis(Session session) {
        return new Analysis(session, messages, config.version(), workspace::nameOf);
    }

    Path root() {
        return workspace.root();
    }

    void handle(String endpoint, HttpExchange ex) throws IOException, Http.Fail {
        switch (endpoint) {
            case "info" -> Http.json(ex, 200, info(Http.get(ex)));
            case "files" -> Http.json(ex, 200, files(Http.get(ex)));
            case "file" -> Http.json(ex, 200, open(Http.get(ex)));
            case "events" -> events.serve(Http.get(ex));
            case "save" -> Http.json(ex, 200, save(Http.post(ex)));
            case "check" -> Http.timed(ex, () -> check(Http.post(ex)));
            case "simulate" -> Http.timed(ex, () -> simulate(Http.post(ex)));
            case "compile" -> Http.timed(ex, () -> compile(Http.post(ex)));
            case "hover" -> Http.timed(ex, () -> hover(Http.post(ex)));
            case "stock" -> Http.timed(ex, () -> stock(Http.post(ex)));
            case "profile" -> Http.json(ex, 200, profile(Http.get(ex)));
            case "profile/impact" -> Http.timed(ex, () -> impact(Http.post(ex)));
            case "profile/save" -> Http.json(ex, 200, saveProfile(Http.post(ex)));
            case "wear" -> Http.timed(ex, () -> testCuts.form(engine.session(), Http.post(ex)));
            case "wear/cut" -> Http.timed(ex, () -> testCut(Http.post(ex)));
            case "run", "run/arm", "run/start", "run/hold", "run/resume", "run/step", "run/continue", "run/override", "run/stop" ->
                    runs.handle(endpoint, ex);
            default -> throw new Http.Fail(404, "no endpoint /api/" + Workspace.shown(endpoint));
        }
    }

    /**
     * POST /api/wear/cut: the test cut ({@link TestCuts#cut}); a saved wear is in force from then on for
     * every check, simulation, compile and run of this studio.
     */
    private JsonObject testCut(JsonObject req) throws IOException, Http.Fail {
        TestCuts.Cut cut;
        synchronized (testCuts) { // one test cut at a time: each reads the wear the last one saved
            Engine e = engine;
            cut = testCuts.cut(e.session(), req);
            if (cut.profile().isPresent()) {
                Session session = e.session().withProfile(cut.profile().get());
                synchronized (this) {
                    engine = engine(session, e.profile(), e.profileFile());
                }
            }
        }
        return cut.answer();
    }

    /** GET /api/info: what this studio serves: folder, machine, control, dialect, language, versions. */
    private JsonObject info(HttpExchange ex) {
        JsonObject o = new JsonObject();
        o.addProperty("folder", workspace.root().getFileName() == null ? "/" : workspace.root().getFileName().toString());
        Engine e = engine;
        o.addProperty("machine", e.session().profile().name());
        o.addProperty("control", e.session().profile().control().name());
        if (e.profileFile() != null) {
            o.addProperty("profileFile", e.profileFile());
        }
        o.addProperty("dialect", config.session().options().dialect().label());
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
        Workspace.Program p = Workspace.refusing(() -> workspace.read(Guard.query(ex.getRequestURI(), "name")));
        return program(p);
    }

    /** POST /api/save {name, text, version?, force?}: written as one step; 409 when it changed on disk. */
    private JsonObject save(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        String text = Http.required(req, "text");
        String version = Http.string(req, "version");
        boolean force = Http.flag(req, "force");
        try {
            return program(Workspace.refusing(() -> workspace.save(name, text, version, force)));
        } catch (AtomicOutput.Refused e) {
            throw new Http.Fail(403, "gcnc refuses to write " + name + " (" + e.code().id() + ")");
        } catch (IOException e) {
            throw new Http.Fail(500, "could not save " + name + ": " + reason(e));
        }
    }

    /** POST /api/check {name, text}: the diagnostics, as gcnc check --format json; its modal states kept for the hover. */
    private JsonObject check(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        String text = Http.required(req, "text");
        Engine e = engine;
        Optional<Path> folder = folder(name);
        java.util.Map<Integer, gcnc.ModalStates.Snapshot> states = new java.util.HashMap<>();
        JsonObject o = e.analysis().check(name, text, folder, gcnc.ModalStates.view(states));
        e.modal().seen(name, text, folder, states);
        return o;
    }

    /** POST /api/simulate {name, text}: diagnostics, DMC, path, summary. */
    private JsonObject simulate(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        return engine.analysis().simulate(name, Http.required(req, "text"), folder(name));
    }

    /** POST /api/compile {name}: the saved program compiled to NAME.dmc and NAME.dmc.map beside it. */
    private JsonObject compile(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        Path program = Workspace.refusing(() -> workspace.existing(name));
        Workspace.CompileOutputs outputs = Workspace.refusing(() -> workspace.compileOutputs(program));
        Path dmc = outputs.dmc();
        String dmcName = outputs.dmcName();
        String streamName = outputs.streamName();
        JsonObject o;
        try {
            o = engine.analysis().compile(name, program, dmc);
        } catch (AtomicOutput.Refused e) {
            throw new Http.Fail(403, "gcnc refuses to write " + dmcName + " (" + e.code().id() + ")");
        } catch (IOException e) {
            throw new Http.Fail(500, "could not write " + dmcName + ": " + reason(e));
        }
        if (o.get("ok").getAsBoolean()) {
            o.addProperty("dmc", dmcName);
            o.addProperty("map", dmcName + ".map");
            if (o.has("streamLines")) {
                o.addProperty("stream", streamName);
            }
        }
        return o;
    }

    /** POST /api/hover {name, text, line, word?}: what a G or M word does here, and the modal state after the line's block. */
    private JsonObject hover(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        String text = Http.required(req, "text");
        int line = Http.integer(req, "line", 1, Integer.MAX_VALUE);
        String word = Http.string(req, "word");
        if (word != null && word.length() > 40) {
            throw new Http.Fail(400, "\"word\" is one word of a block (at most 40 characters)");
        }
        return engine.modal().hover(name, text, line, word, folder(name));
    }

    /** POST /api/stock {name, text, line}: the stock before and after the line's block, and the tool there. */
    private JsonObject stock(JsonObject req) throws IOException, Http.Fail {
        String name = Http.required(req, "name");
        String text = Http.required(req, "text");
        int line = Http.integer(req, "line", 1, Integer.MAX_VALUE);
        return engine.analysis().scrub(name, text, line, folder(name));
    }

    /** A request's edits in the file's terms ({@link ProfileEdit#edits}); a profile that cannot be read is the studio's fault. */
    private static java.util.Map<String, String> edits(ProfileEdit edit, JsonObject req) throws Http.Fail {
        try {
            return edit.edits(req);
        } catch (ProfileEdit.Invalid i) {
            throw new Http.Fail(500, "the machine profile cannot be read: " + i.getMessage());
        }
    }

    /** The profile being configured: the one the studio was started with, or the one last saved. */
    private ProfileEdit profileEdit() throws IOException, Http.Fail {
        Engine e = engine;
        if (e.profile() != null) {
            return e.profile();
        }
        ProfileEdit p;
        try {
            p = ProfileEdit.of(e.session(), messages);
        } catch (IOException x) {
            throw new Http.Fail(500, "could not read the machine profile: " + reason(x));
        }
        synchronized (this) {
            if (engine == e) {
                engine = new Engine(e.session(), e.analysis(), e.modal(), p, e.profileFile());
            }
        }
        return p;
    }

    /**
     * GET /api/profile[?units=in|mm]: Configure's fields (travel, work and tool offsets, tool geometry) as
     * written and as in force, and in the terms of a program in those units (default: the profile's).
     */
    private JsonObject profile(HttpExchange ex) throws IOException, Http.Fail {
        try {
            ProfileEdit edit = profileEdit();
            JsonObject o = edit.form(edit.units(Guard.query(ex.getRequestURI(), "units")));
            if (engine.profileFile() != null) {
                o.addProperty("profileFile", engine.profileFile());
            }
            return o;
        } catch (ProfileEdit.Invalid i) {
            throw new Http.Fail(500, "the machine profile cannot be read: " + i.getMessage());
        }
    }

    /**
     * POST /api/profile/impact {values, program?, units?, name?, text?}: the edited profile read as the
     * loader reads it ({"valid": false, "key", "error"} when refused; else {@code written}: each edited
     * key's value in the file's terms); with a program, which of its lines become errors or
     * collisions with it and which stop being.
     */
    private JsonObject impact(JsonObject req) throws IOException, Http.Fail {
        ProfileEdit edit = profileEdit();
        java.util.Map<String, String> values = edits(edit, req);
        String name = Http.string(req, "name");
        String text = Http.string(req, "text");
        if ((name == null) != (text == null)) {
            throw new Http.Fail(400, "give both \"name\" and \"text\" (the program to judge), or neither");
        }
        JsonObject o = new JsonObject();
        gcnc.machine.MachineProfile edited;
        try {
            edited = edit.load(edit.edited(values));
        } catch (ProfileEdit.Invalid i) {
            o.addProperty("valid", false);
            o.addProperty("key", i.key());
            o.addProperty("error", i.getMessage());
            return o;
        }
        o.addProperty("valid", true);
        JsonObject written = new JsonObject(); // what would be written for each key, in the file's own terms
        values.forEach(written::addProperty);
        o.add("written", written);
        if (name != null) {
            Engine e = engine;
            Analysis then = analysis(e.session().withProfile(edited));
            JsonObject impact = e.analysis().impact(then, name, text, folder(name));
            o.add("became", impact.get("became"));
            o.add("gone", impact.get("gone"));
        }
        return o;
    }

    /**
     * POST /api/profile/save {file, values, program?, units?, force?}: the edited profile written under DIR as one step
     * (a NAME.machine file; an existing one only with force), and used from then on by every check,
     * simulation and compile of this studio.
     */
    private JsonObject saveProfile(JsonObject req) throws IOException, Http.Fail {
        String file = Http.required(req, "file");
        boolean force = Http.flag(req, "force");
        ProfileEdit edit = profileEdit();
        java.util.Map<String, String> values = edits(edit, req);
        Path target = Workspace.refusing(() -> workspace.writableProfile(file));
        String text = edit.edited(values);
        gcnc.machine.MachineProfile edited;
        try {
            edited = edit.load(text);
        } catch (ProfileEdit.Invalid i) {
            throw new Http.Fail(400, (i.key() == null ? "" : i.key() + ": ") + i.getMessage());
        }
        if (!force && java.nio.file.Files.exists(target, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
            throw new Http.Fail(409, file + " already exists");
        }
        try (AtomicOutput out = new AtomicOutput(target)) {
            java.io.Writer w = out.writer();
            w.write(text);
            w.flush();
            out.commit();
        } catch (AtomicOutput.Refused e) {
            throw new Http.Fail(403, "gcnc refuses to write " + file + " (" + e.code().id() + ")");
        } catch (IOException e) {
            throw new Http.Fail(500, "could not save " + file + ": " + reason(e));
        }
        Session session = engine.session().withProfile(edited);
        synchronized (this) {
            engine = engine(session, ProfileEdit.saved(session, target, text, messages), workspace.name(target));
        }
        JsonObject o = new JsonObject();
        o.addProperty("file", workspace.name(target));
        o.addProperty("machine", edited.name());
        return o;
    }

    @Override
    public void close() {
        events.stop();
        runs.close();
        events.close();
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

    private static String reason(IOException e) {
        String m = e.getMessage();
        return e.getClass().getSimpleName() + (m == null ? "" : " " + m);
    }
}
