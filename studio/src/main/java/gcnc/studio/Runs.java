package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import com.sun.net.httpserver.HttpExchange;
import gcnc.Session;
import gcnc.diag.Messages;
import gcnc.send.Event;
import gcnc.send.EventSink;
import gcnc.send.JsonEvents;
import gcnc.send.Link;
import gcnc.send.Operator;
import gcnc.send.ResumePoint;
import gcnc.send.Sender;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;

/**
 * The Run screen's server side: the thesis's MEMORY mode from the page, as {@code gcnc run} does it.
 * A run has two steps, because motion needs an explicit arm: <b>arm</b> compiles the saved program as
 * {@code gcnc run} does (a program that is not clean is refused, nothing is connected) and does
 * {@code gcnc run --dry-run} against the chosen controller (connect, pre-flight, download, read
 * back: everything but motion), and answers what would move; <b>start</b>, given that arm, runs it
 * ({@link Sender} with {@link gcnc.send.ProgramForm}, the command line's own, made by {@link RunControllers}), once. The run's events
 * ({@link Event}, exactly the lines {@code gcnc run --format json} prints) go to every page over the
 * event stream as {@code run} events; hold, resume, step, override and stop reach the run through its
 * {@link Operator}. One run at a time, and one arm: a new arm replaces the last.
 */
final class Runs implements AutoCloseable {
    /** What the studio runs with at the moment of a request: Configure may have saved another profile. */
    record Context(Session session, Analysis analysis, String profileFile) {
    }

    /** The events of one run kept for a page that opens (or reloads) while it goes on; status aside. */
    static final int LOG = 1000;

    private final Workspace workspace;
    private final Supplier<Context> context;
    private final EventHub hub;
    private final RunControllers controllers;
    private final ReentrantLock arming = new ReentrantLock();
    private final SecureRandom random = new SecureRandom();
    // guarded by this
    private RunArm arm;
    private LiveRun run;
    private Thread thread;
    private final List<JsonElement> log = new ArrayList<>();
    private JsonElement lastStatus;
    private Integer ended;

    Runs(Workspace workspace, Supplier<Context> context, Messages messages, EventHub hub, Studio.Running settings) {
        this.workspace = workspace;
        this.context = context;
        this.hub = hub;
        this.controllers = new RunControllers(settings, messages);
    }

    /** {@code run} (GET) and {@code run/arm|start|hold|resume|step|override|stop} (POST). */
    void handle(String endpoint, HttpExchange ex) throws IOException, Http.Fail {
        if (endpoint.equals("run")) {
            if (!ex.getRequestMethod().equals("GET")) {
                throw new Http.Fail(405, "use GET for /api/run");
            }
            Http.json(ex, 200, snapshot());
            return;
        }
        if (!ex.getRequestMethod().equals("POST")) {
            throw new Http.Fail(405, "use POST for /api/" + endpoint);
        }
        JsonObject req = Http.body(ex);
        JsonObject answer = switch (endpoint) {
            case "run/arm" -> arm(req);
            case "run/start" -> start(req);
            case "run/hold" -> RunKeys.hold(running());
            case "run/resume" -> RunKeys.resume(running());
            case "run/step" -> RunKeys.step(running());
            case "run/continue" -> RunKeys.continueStop(running());
            case "run/override" -> {
                int percent = Http.integer(req, "percent", 10, 200); // a bad request is 400, run or no run
                yield RunKeys.override(running(), percent);
            }
            case "run/stop" -> RunKeys.stop(running());
            default -> throw new Http.Fail(404, "no endpoint /api/" + Workspace.shown(endpoint));
        };
        Http.json(ex, 200, answer);
    }

    // ---- arm --------------------------------------------------------------------------------------------

    /**
     * What an arm asks for, read once from its request.
     *
     * @param optionalStop the optional stop switch (M01 stops as M00 when on): the page's toggle; null, the control's default
     * @param resumeAt     null: from the start
     */
    private record ArmRequest(String name, RunTarget target, boolean step, Boolean optionalStop, ResumePoint resumeAt) {
        static ArmRequest of(JsonObject req) throws Http.Fail {
            String name = Http.required(req, "name");
            RunTarget target = RunTarget.of(req.get("target"));
            boolean step = Http.flag(req, "step");
            Boolean optionalStop = req.has("optionalStop") && !req.get("optionalStop").isJsonNull()
                    ? Http.flag(req, "optionalStop") : null;
            String at = Http.string(req, "resumeAt");
            try {
                return new ArmRequest(name, target, step, optionalStop,
                        at == null || at.isBlank() ? null : ResumePoint.parse(at));
            } catch (IllegalArgumentException e) {
                throw new Http.Fail(400, "\"resumeAt\" is a G-code line, N or N:K (K: the block's K-th motion)");
            }
        }
    }

    /**
     * POST /api/run/arm {name, target, step?, resumeAt?}: the saved program compiled as gcnc run does
     * and tried on the controller without motion. Answers {@code armed} and, when armed, the
     * {@code arm} to start with.
     */
    private JsonObject arm(JsonObject json) throws IOException, Http.Fail {
        ArmRequest req = ArmRequest.of(json);
        String name = req.name();
        RunTarget target = req.target();
        boolean step = req.step();
        Boolean optionalStop = req.optionalStop();
        ResumePoint resumeAt = req.resumeAt();
        if (target instanceof RunTarget.Serial && !controllers.serial()) {
            throw new Http.Fail(400, "this studio cannot open serial ports (start it with gcnc studio, from gcnc.jar)");
        }
        Path file = Workspace.refusing(() -> workspace.existing(name));
        Workspace.CompileOutputs outputs = Workspace.refusing(() -> workspace.compileOutputs(file));
        Path dmc = outputs.dmc();
        String dmcName = outputs.dmcName();
        String streamName = outputs.streamName();
        if (!arming.tryLock()) {
            throw new Http.Fail(409, "another arm is under way");
        }
        try {
            synchronized (this) {
                if (run != null) {
                    throw new Http.Fail(409, "a run is going on (" + run.arm.name() + "): stop it or let it end first");
                }
                arm = null; // a new arm replaces the last, whatever comes of it
            }
            String version = Workspace.version(Files.readAllBytes(file));
            Context ctx = context.get();
            RunProgram program;
            try {
                gcnc.Session session = optionalStop == null ? ctx.session()
                        : ctx.session().withProfile(ctx.session().profile().withOptionalStop(optionalStop));
                program = RunProgram.prepare(session, ctx.analysis(), name, file, dmc, step);
            } catch (gcnc.output.AtomicOutput.Refused e) {
                throw new Http.Fail(403, "gcnc refuses to write " + dmcName + " (" + e.code().id() + ")");
            }
            JsonObject o = new JsonObject();
            o.addProperty("name", name);
            o.addProperty("target", target.shown());
            o.addProperty("step", step);
            o.addProperty("optionalStop", optionalStop != null ? optionalStop
                    : ctx.session().profile().control().stop().optional());
            o.addProperty("resumeAt", resumeAt == null ? null : resumeAt.toString());
            o.add("diagnostics", program.report());
            if (!program.clean()) {
                // the same refusal as gcnc run's exit 1: nothing was connected, nothing sent
                o.addProperty("armed", false);
                o.addProperty("refused", "the program is not clean: " + program.errors() + " error(s); nothing was sent");
                return o;
            }
            o.addProperty("form", program.form().name().toLowerCase(java.util.Locale.ROOT));
            o.addProperty("dmc", dmcName);
            if (program.form() == gcnc.dmc.Form.STREAM) {
                o.addProperty("stream", streamName);
            }
            o.addProperty("dmcLines", program.dmcLines());
            String address = target instanceof RunTarget.Virtual ? controllers.virtual(ctx.session().profile(), resumeAt == null) : null;
            if (address != null) {
                o.addProperty("address", address);
            }
            tryWithoutMotion(new RunArm(newId(), name, version, target, address, step, resumeAt, program, ctx, o), o);
            return o;
        } finally {
            arming.unlock();
        }
    }

    /** The dry run of an arm (gcnc run --dry-run): its events into {@code o}; when it ran, the arm to start with. */
    private void tryWithoutMotion(RunArm tried, JsonObject o) throws IOException {
        List<JsonElement> events = new ArrayList<>();
        int status = controllers.dryRun(tried, e -> events.add(JsonParser.parseString(JsonEvents.json(e))));
        JsonArray list = new JsonArray();
        events.forEach(list::add);
        o.add("events", list);
        o.addProperty("armed", status == Sender.RAN);
        if (status == Sender.RAN) {
            o.addProperty("arm", tried.id());
            synchronized (this) {
                arm = tried;
            }
        }
    }

    // ---- the run ----------------------------------------------------------------------------------------

    /** POST /api/run/start {arm}: runs what that arm armed, once. */
    private JsonObject start(JsonObject req) throws IOException, Http.Fail {
        String id = Http.required(req, "arm");
        LiveRun r;
        synchronized (this) {
            if (run != null) {
                throw new Http.Fail(409, "a run is going on (" + run.arm.name() + "): one at a time");
            }
            if (arm == null || !java.security.MessageDigest.isEqual(arm.id().getBytes(), id.getBytes())) {
                throw new Http.Fail(409, "nothing is armed with this arm: arm the program first (motion needs it)");
            }
            RunArm a = arm;
            arm = null; // an arm moves the machine once
            Path file = Workspace.refusing(() -> workspace.existing(a.name()));
            if (!Workspace.version(Files.readAllBytes(file)).equals(a.version())) {
                throw new Http.Fail(409, a.name() + " changed since it was armed: arm it again");
            }
            if (context.get().session() != a.context().session()) {
                throw new Http.Fail(409, "the machine profile changed since the program was armed: arm it again");
            }
            r = new LiveRun(a);
            run = r;
            log.clear();
            lastStatus = null;
            ended = null;
        }
        Thread t = new Thread(() -> follow(r), "gcnc-studio-run");
        t.setDaemon(true);
        synchronized (this) {
            thread = t;
        }
        t.start();
        JsonObject o = new JsonObject();
        o.addProperty("started", true);
        o.addProperty("name", r.arm.name());
        o.addProperty("target", r.arm.target().shown());
        o.addProperty("step", r.arm.step());
        return o;
    }

    /** The run's thread: the sender to its end, every event to the pages, then {@code run-ended}. */
    private void follow(LiveRun r) {
        EventSink events = e -> publish(r, e);
        int status;
        try {
            Link link = controllers.link(r.arm, events);
            status = link == null ? Sender.CONNECTION : controllers.sender(r.arm, r.operator, events, false).run(link, RunControllers.TIMEOUT_MS);
        } catch (RuntimeException e) {
            // a fault of gcnc itself: told as such, never a silent end of the run
            events.accept(new Event.Message("the run failed inside gcnc: " + e));
            status = Sender.STOPPED;
        }
        JsonObject end = new JsonObject();
        end.addProperty("event", "run-ended");
        end.addProperty("status", status);
        synchronized (this) {
            if (log.size() < LOG) {
                log.add(end);
            }
            ended = status;
            if (run == r) {
                run = null;
            }
        }
        hub.publish("run", end.toString());
    }

    private void publish(LiveRun r, Event e) {
        String json = JsonEvents.json(e);
        if (e instanceof Event.StepWait) {
            r.stepWaiting = true;
        }
        // whether the run waits at a program stop, decided for every event (a new one may end the wait)
        r.stopWaiting = switch (e.kind()) {
            case PROGRAM_STOP -> true;
            case PROGRAM_STOP_CONTINUED -> false;
            case CONNECTED, PREFLIGHT, WEAR, DOWNLOADED, STARTED, STATUS, BLOCK, STEP_WAIT, HOLD, FINDING, MESSAGE,
                    STOPPED, FINISHED -> r.stopWaiting;
        };
        synchronized (this) {
            if (e instanceof Event.Status) {
                lastStatus = JsonParser.parseString(json);
            } else if (log.size() < LOG) {
                log.add(JsonParser.parseString(json));
            }
        }
        hub.publish("run", json);
    }

    private synchronized LiveRun running() throws Http.Fail {
        if (run == null) {
            throw new Http.Fail(409, "no run is going on");
        }
        return run;
    }

    /**
     * GET /api/run: where the Run screen stands: {@code state} idle, armed or running; the arm's answer
     * when armed; the events of the last (or current) run and its last status; its exit status when
     * it ended.
     */
    private synchronized JsonObject snapshot() {
        JsonObject o = new JsonObject();
        o.addProperty("state", run != null ? "running" : arm != null ? "armed" : "idle");
        if (arm != null) {
            JsonObject a = arm.answer().deepCopy();
            a.remove("diagnostics");
            a.addProperty("arm", arm.id());
            o.add("armed", a);
        }
        if (run != null) {
            o.addProperty("name", run.arm.name());
            o.addProperty("step", run.arm.step());
            o.addProperty("held", run.operator.held());
            o.addProperty("stepWaiting", run.stepWaiting);
            o.addProperty("stopWaiting", run.stopWaiting);
        }
        JsonArray events = new JsonArray();
        log.forEach(events::add);
        o.add("events", events);
        if (lastStatus != null) {
            o.add("status", lastStatus);
        }
        if (ended != null) {
            o.addProperty("ended", ended);
        }
        return o;
    }

    private String newId() {
        byte[] b = new byte[12];
        random.nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    /** The studio stops: a run going on is stopped (ST, spindle off) before the virtual controller goes. */
    @Override
    public void close() {
        Thread t;
        synchronized (this) {
            if (run != null) {
                run.operator.stop();
            }
            t = thread;
        }
        if (t != null) {
            try {
                t.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        controllers.close();
    }

}
