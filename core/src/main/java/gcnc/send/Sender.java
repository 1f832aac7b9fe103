package gcnc.send;

import gcnc.diag.Code;
import gcnc.diag.Messages;
import gcnc.machine.MachineProfile;
import java.io.IOException;
import java.util.List;
import java.util.function.Function;

/**
 * {@code gcnc run} after the compile: pre-flight against the controller, the program's capacity
 * checked against what the controller has, then the {@link Delivery} that sends and follows it, and
 * one outcome: 0 ran to the end, 2 a connection or controller problem before anything moved, 3
 * stopped by a fault or the operator once it had started (with the command that resumes it).
 * Every fault is a diagnostic (E815-E829) at the G-code line it concerns.
 */
public final class Sender {
    /** Exit statuses of {@code gcnc run} (docs/run.md). */
    public static final int RAN = 0;
    public static final int REFUSED = 1;
    public static final int CONNECTION = 2;
    public static final int STOPPED = 3;

    /**
     * How to run.
     *
     * @param step     one G-code block at a time, on Enter
     * @param dryRun   everything but motion (connect, pre-flight, download, read back)
     * @param resumeAt where to continue an interrupted run, or null
     * @param pollMs   how often the controller is asked where it is
     * @param wayBack  with a resume: make the way back E827 advises first, at its feed ({@link WayBackRun}; a dry
     *                 run checks it and does not make it), or null
     */
    public record Options(boolean step, boolean dryRun, ResumePoint resumeAt, int pollMs, WayBackRun.Ask wayBack) {
        public Options(boolean step, boolean dryRun, ResumePoint resumeAt, int pollMs) {
            this(step, dryRun, resumeAt, pollMs, null);
        }
    }

    private final MachineProfile profile;
    private final DmcProgram program;
    private final BlockTable blocks;
    private final EventSink events;
    private final Messages messages;
    private final Operator operator;
    private final Options options;
    private final Delivery form;
    private final Function<ResumePoint, String> resumeCommand;

    public Sender(MachineProfile profile, DmcProgram program, BlockTable blocks, EventSink events, Messages messages,
                  Operator operator, Options options, Delivery form, Function<ResumePoint, String> resumeCommand) {
        this.profile = profile;
        this.program = program;
        this.blocks = blocks;
        this.events = events;
        this.messages = messages;
        this.operator = operator;
        this.options = options;
        this.form = form;
        this.resumeCommand = resumeCommand;
    }

    /** How far (counts) the axes may be from a point and still be at it: 3 counts, or 5 µm. */
    public double tolerance() {
        return tolerance(profile);
    }

    /** {@link #tolerance()} of a machine. */
    public static double tolerance(MachineProfile profile) {
        return Math.max(3, Math.max(profile.x().countsPerMm(), profile.z().countsPerMm()) * 0.005);
    }

    /** Runs the program over {@code link} (which it closes); returns the exit status. */
    public int run(Link link, int timeoutMs) {
        Progress progress = new Progress(program, blocks, events, tolerance());
        GalilClient client = new GalilClient(link, timeoutMs, m -> {
            events.accept(new Event.Message(m));
            progress.heard(m);
        });
        MachineLink c = new MachineLink(client, profile, program.plane());
        // closed in finally, not by try-with-resources: the catches below still talk to the controller
        try {
            Download piece = preflight(c, link.name());
            events.accept(new Event.Started(form.name(), piece.lines().size(), blocks.blocksFrom(
                    options.resumeAt() == null ? 0 : options.resumeAt().line()),
                    resumed == null ? program.totalSeconds() : progress.secondsLeft(resumed.resumedAt(), resumed.axes()),
                    options.dryRun(),
                    options.step(), options.resumeAt() == null ? null : options.resumeAt().toString()));
            form.run(piece, c, progress, operator, options.step(), options.dryRun());
            events.accept(new Event.Finished(progress.seconds(), options.dryRun()));
            return RAN;
        } catch (RunFault f) {
            if (f.moved()) {
                readAxes(c, progress); // where the stop left them: the resume point is where they are
            }
            return stopped(f, progress);
        } catch (GalilClient.Rejected r) {
            RunFault f = c.refused(r.command(), progress.executingLine(), progress.hasStarted()); // TC1 before the stop
            if (progress.hasStarted()) {
                c.stopAll();
                readAxes(c, progress);
                // at the block where the machine stopped, which the report and the resume name
                f = new RunFault(f.code(), progress.executingLine(), true, f.args().toArray());
            }
            return stopped(f, progress);
        } catch (LinkFault lf) {
            if (progress.hasStarted() && lf.kind() != LinkFault.Kind.DROPPED) {
                client.resync(300);
                c.stopAll();
                readAxes(c, progress);
            }
            String done = block(progress.completedLine());
            String now = block(progress.executingLine());
            RunFault f = switch (lf.kind()) {
                case DROPPED -> dropped(progress, lf.detail());
                case TIMEOUT -> new RunFault(Code.E822_NO_REPLY, progress.executingLine(), progress.hasStarted(),
                        "'" + GalilClient.printable(lf.command()) + "'", lf.detail(), done, now);
                case GARBAGE -> new RunFault(Code.E823_GARBAGE, progress.executingLine(), progress.hasStarted(),
                        "'" + GalilClient.printable(lf.command()) + "'", lf.detail(), done, now);
            };
            return stopped(f, progress);
        } catch (IOException e) {
            return stopped(dropped(progress, String.valueOf(e.getMessage())), progress);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            c.stopAll();
            return stopped(new RunFault(Code.E828_STOPPED_BY_OPERATOR, progress.executingLine(), true,
                    progress.executingLine()), progress);
        } finally {
            client.close();
        }
    }

    /**
     * A link that dropped: before the program started nothing moved (E821); after, the controller may run
     * on without its host, so the fault says so and never that it stopped (E851).
     */
    private static RunFault dropped(Progress progress, String detail) {
        return new RunFault(progress.hasStarted() ? Code.E851_LINK_DROPPED_RUNNING : Code.E821_CONNECTION_DROPPED,
                progress.executingLine(), progress.hasStarted(), detail, block(progress.completedLine()),
                block(progress.executingLine()));
    }

    /**
     * The axes read after a stop and the block they stand in ({@link Progress#settle}), for the report
     * and the resume point; a link that no longer answers leaves the last poll's.
     */
    private static void readAxes(MachineLink c, Progress progress) {
        try {
            progress.settle(c.position());
        } catch (IOException | RuntimeException e) {
            // the last poll's position stands
        }
    }

    private static String block(int line) {
        return line == 0 ? "none" : "line " + line;
    }

    /** The G-code line of the program's first motion (the frame its start was verified in), 0 when it has none. */
    private int firstMotionLine() {
        return program.sequences().isEmpty() ? 0 : program.sourceLine(program.sequences().get(0).first());
    }

    /** The resume planned (null: a run from the start): where it takes the program up, for the estimate. */
    private Resume resumed;
    /** The way back the resume makes first (null: none), and the first compiled line of the sequence it goes back to. */
    private WayBack wayBack;
    private int cut;

    /** Pre-flight; returns what to download (the program, or the resume program built from where the axes are). */
    private Download preflight(MachineLink c, String link) throws IOException, RunFault {
        MachineLink.Facts f = c.preflight();
        events.accept(new Event.Connected(link, f.revision()));
        gcnc.machine.GalilModel model = model(f);
        Download piece = options.resumeAt() == null ? Download.whole(program) : resume(c, f);
        int needLines = form.linesNeeded(piece, program, options.step());
        int needSlots = program.mostSegments();
        int programLines = (int) model.range(gcnc.machine.GalilModel.Limit.PROGRAM_LINES).max();
        announce(f, programLines, needLines, needSlots);
        fits(f, model, programLines, needLines);
        ready(c, f, model, needSlots);
        if (wayBack != null) {
            WayBackRun back = new WayBackRun(program, blocks, profile, messages, options.wayBack());
            if (options.dryRun()) {
                back.verify(wayBack, options.resumeAt(), events, cut);
            } else {
                back.make(wayBack, options.resumeAt(), c, events, operator, cut);
            }
        }
        if (options.resumeAt() == null) {
            double[] home = program.sequences().isEmpty() ? f.position() : program.sequences().get(0).start();
            if (Math.hypot(f.position()[0] - home[0], f.position()[1] - home[1]) > tolerance()) {
                // in the terms of the first motion's block (the frame the home was verified in), then the counts
                int line = firstMotionLine();
                PositionText where = new PositionText(program, blocks);
                throw new RunFault(Code.E826_NOT_AT_START, 0, false, where.at(line, f.position()), where.at(line, home));
            }
        }
        return piece;
    }

    /**
     * The profile's Galil model, which the controller must be (E818), with the memory of the firmware it
     * reported (tables/galil_models.csv; a profile that counted on firmware 1.2a's, on an older one, gets the older).
     */
    private gcnc.machine.GalilModel model(MachineLink.Facts f) throws RunFault {
        gcnc.machine.GalilModel model = profile.galilModel();
        if (f.model().isEmpty() || !MachineLink.sameModel(f.model(), model.name())) {
            String what = f.model().isEmpty() ? "the controller did not name a Galil model ('"
                    + GalilClient.printable(f.revision()) + "' to ^R^V)" : "the controller is a " + f.revision();
            throw new RunFault(Code.E818_WRONG_CONTROLLER, 0, false, what, profile.name(), model.name());
        }
        return model.newFirmware() && !f.firmware12a() ? model.withOlderFirmware() : model;
    }

    /**
     * The resume program, from the position read again on this connection (the preflight's TP, after
     * _XQ0 and _BGS said it is at rest: a controller that ran on after a dropped link is resumed from
     * where it really is), or from the block's start once a way back has brought the axes there; what
     * the controller holds against what the program needs there, and what the resume changes, said.
     */
    private Download resume(MachineLink c, MachineLink.Facts f) throws IOException, RunFault {
        Resume resume = new Resume(program, blocks, tolerance()).spindle(profile);
        Download piece;
        try {
            piece = resume.plan(options.resumeAt(), f.position());
        } catch (RunFault e) {
            if (options.wayBack() == null || resume.wayBack().isEmpty()) {
                throw e;
            }
            wayBack = resume.wayBack().get();
            cut = resume.wayBackFrom();
            piece = resume.plan(options.resumeAt(), wayBack.legs().get(wayBack.legs().size() - 1).to());
        }
        resumed = resume;
        resume.ranOn().ifPresent(what -> events.accept(new Event.Message(what)));
        int line = options.resumeAt().line();
        for (String said : ResumeState.changes(c, profile, resume.restored(), line, blocks.at(line))) {
            events.accept(new Event.Message(said));
        }
        return piece;
    }

    /** The pre-flight's facts against the program's needs, and the wear the DMC was compiled with (docs/run.md). */
    private void announce(MachineLink.Facts f, int programLines, int needLines, int needSlots) {
        events.accept(new Event.Preflight(f.model(), programLines, needLines, f.labelsLeft(), program.labels(),
                f.variablesLeft(), program.variables().size(), f.arraySpace(), f.vectorSlots(), needSlots,
                f.pendingError(), f.limits(),
                f.motorsOff().stream().map(String::valueOf).collect(java.util.stream.Collectors.joining()), f.position(),
                new PositionText(program, blocks).at(options.resumeAt() != null ? options.resumeAt().line()
                        : firstMotionLine(), f.position())));
        // the operator sees which file's wear moves the tools
        for (int n : blocks.toolOffsets()) {
            profile.wear().of(n).ifPresent(w -> events.accept(new Event.Wear(w.file(), n, w.x(), w.z(),
                    profile.wear().unit(), profile.diameterX())));
        }
    }

    /** E819 when the program's lines, labels or variables do not fit the controller. */
    private void fits(MachineLink.Facts f, gcnc.machine.GalilModel model, int programLines, int needLines)
            throws RunFault {
        int maxLabels = (int) model.range(gcnc.machine.GalilModel.Limit.LABELS).max();
        List<String> vars = program.variables();
        if (needLines > programLines) {
            throw new RunFault(Code.E819_CAPACITY, 0, false, needLines + " program lines", programLines
                    + " (" + f.revision() + ")", form.name().equals("program") ? "run it in the stream form (--form stream)"
                    : "the resident program does not fit: fewer threads per program, or a controller with more memory");
        }
        if (program.labels() > maxLabels) {
            throw new RunFault(Code.E819_CAPACITY, 0, false, program.labels() + " labels", Integer.toString(maxLabels),
                    "the program has too many labels");
        }
        if (f.variablesLeft() >= 0 && vars.size() > f.variablesLeft()) {
            throw new RunFault(Code.E819_CAPACITY, 0, false, vars.size() + " variables " + vars,
                    f.variablesLeft() + " free", "clear the controller's variables (reset) and run again");
        }
    }

    /**
     * Whether the controller is ready to take the program: no program running, nothing moving, the
     * vector buffer emptied (CS S) and large enough, no limit switch active (E825, E831, E819); motors
     * off are a finding (E829), and an error it had pending is said.
     */
    private void ready(MachineLink c, MachineLink.Facts f, gcnc.machine.GalilModel model, int needSlots)
            throws IOException, RunFault {
        if (!f.pendingError().isEmpty()) {
            events.accept(new Event.Message("the controller had an error pending, read and cleared with TC1: "
                    + f.pendingError()));
        }
        if (f.programRunning()) {
            // a program left running (an earlier run whose link dropped goes on without it): HX would cut it off
            throw new RunFault(Code.E825_NOT_READY, 0, false, "a program is running in thread 0 (_XQ0 >= 0): let it end,"
                    + " or halt it (HX) and stop the axes (ST) at the controller, then run or resume again");
        }
        if (f.moving()) {
            throw new RunFault(Code.E825_NOT_READY, 0, false, "a vector sequence is moving (_BGS = 1): stop it first");
        }
        // nothing moves: segments an interrupted sequence left in the buffer would run first, from the new
        // origin (COMALL CS); CS S removes them, and the buffer must then read empty (_LMS = the model's buffer)
        int free = c.clearSequence();
        int whole = (int) model.range(gcnc.machine.GalilModel.Limit.BUFFER_SEGMENTS).max();
        if (free != whole) {
            throw new RunFault(Code.E831_BUFFER_NOT_EMPTY, 0, false, Integer.toString(free), Integer.toString(whole));
        }
        if (needSlots > free) {
            throw new RunFault(Code.E819_CAPACITY, 0, false, needSlots + " vector buffer slots", free
                    + " free (_LMS)", "a controller with a larger buffer");
        }
        if (!f.limits().isEmpty()) {
            throw new RunFault(Code.E825_NOT_READY, 0, false, f.limits() + " is active: move the axis off the switch");
        }
        if (!f.motorsOff().isEmpty()) {
            StringBuilder axes = new StringBuilder();
            f.motorsOff().forEach(axes::append);
            finding(Code.E829_MOTORS_OFF, 0, List.of(axes.toString()));
        }
    }

    private int stopped(RunFault f, Progress progress) {
        finding(f.code(), f.line(), f.args());
        if (!f.moved()) {
            return CONNECTION;
        }
        ResumePoint at = progress.resumePoint();
        events.accept(new Event.Stopped(f.code().id(), progress.completedLine(), progress.executingLine(),
                progress.where(), progress.wherePolled(), at == null ? null : at.toString(), at == null ? null : resumeCommand.apply(at)));
        return STOPPED;
    }

    private void finding(Code code, int line, List<String> args) {
        String severity = code == Code.E828_STOPPED_BY_OPERATOR || code == Code.E829_MOTORS_OFF ? "warning" : "error";
        events.accept(new Event.Finding(code.id(), severity, line, messages.render(code, args)));
    }
}
