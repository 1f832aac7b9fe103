package gcnc.cli;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Messages;
import gcnc.output.DmcOutputs;
import gcnc.output.FormOutputs;
import gcnc.send.BlockTable;
import gcnc.send.CompiledRun;
import gcnc.send.DmcProgram;
import gcnc.send.Event;
import gcnc.send.EventSink;
import gcnc.send.JsonEvents;
import gcnc.send.Link;
import gcnc.send.Operator;
import gcnc.send.ProgramForm;
import gcnc.send.ResumePoint;
import gcnc.send.RunFault;
import gcnc.send.Sender;
import gcnc.send.StreamForm;
import gcnc.sim.SimOptions;
import gcnc.tables.TableException;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code gcnc run}: the thesis's MEMORY mode. Compiles and simulates the program as {@code compile}
 * does (writing FILE.dmc and its map), refuses it unless clean, then runs it on a Galil over a
 * serial port or Ethernet ({@link Sender}; docs/run.md).
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Check, compile and simulate a program, then run it on a Galil controller (the thesis's MEMORY mode).",
                "Refuses any program that is not clean. Keys while it runs: Enter = next step / end a hold,"
                        + " + and - = feed override by 10%%, h = feed hold, q = stop; Ctrl-C holds, a second Ctrl-C stops."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:the program ran to its end (--dry-run: everything but motion was done)",
                "1:the program is not clean: nothing was sent", "2:usage or connection problem (no port, port held, wrong"
                        + " controller, too little memory, not ready): nothing moved",
                "3:stopped by a fault or the operator; the command that resumes is printed"})
final class SendCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Mixin
    StockOptions stock;

    @Mixin
    WayBackOptions wayBack;

    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "FILE", description = "The G-code program.")
    Path file;

    @ArgGroup(exclusive = true, multiplicity = "1")
    ControllerTarget.Where target;

    @Mixin
    ControllerTarget connection;

    @Option(names = "--step", description = "One G-code block at a time: each runs on Enter (the thesis's Trace).")
    boolean step;

    @Option(names = "--resume-at", paramLabel = "N[:K]",
            description = "Continue an interrupted run at G-code line N (K: its K-th motion), as the stop message printed.")
    String resumeAt;

    @Option(names = "--form", paramLabel = "program|stream", converter = FormConverter.class,
            description = "program: downloaded whole; stream: a resident program, the rest fed through the command line."
                    + " Default: program when it fits the profile's Galil model, else stream (as gcnc compile chooses).")
    gcnc.dmc.Form form;

    @Option(names = "--optional-stop", paramLabel = "on|off",
            description = "The optional stop switch: on, M01 stops as M00 (waits for Enter or cycle start); off, it runs"
                    + " through. Default: the control's stop.optional (off for the shipped controls).")
    OnOff optionalStop;

    /** A switch's two positions, as the command line writes them. */
    enum OnOff { on, off }

    @Option(names = "--dry-run", description = "Everything but motion: connect, pre-flight, download and read back.")
    boolean dryRun;

    @Option(names = {"-q", "--quiet"}, description = "No status line: findings and the outcome only.")
    boolean quiet;

    @Option(names = "--format", paramLabel = "text|json", defaultValue = "text",
            description = "text (default): a status line; json: one event object per line on standard output (docs/run.md).")
    String format;

    @Option(names = "--poll", paramLabel = "MS", defaultValue = "100", description = "How often to ask where the program is (default: ${DEFAULT-VALUE} ms).")
    int pollMs;

    @Option(names = "--probe-report", paramLabel = "FILE",
            description = "The report gcnc controller probe wrote for this controller: refuse the run when the unit"
                    + " contradicts a fact the run relies on, unless the profile's galil.deviations names it.")
    Path probeReport;

    @Option(names = "--stall", paramLabel = "SECONDS", defaultValue = "10",
            description = "Stop the run when the axes stand still this long inside a motion that has not ended (default: ${DEFAULT-VALUE}).")
    double stallSeconds;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (!format.equals("text") && !format.equals("json")) {
            throw new ParameterException(spec.commandLine(), "--format takes text or json, not '" + format + "'");
        }
        ResumePoint resume;
        try {
            resume = resumeAt == null ? null : ResumePoint.parse(resumeAt);
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (wayBack.feed != null && resume == null) {
            throw new ParameterException(spec.commandLine(), "--way-back goes with --resume-at: the way back is to a resume point");
        }
        if (SourceFiles.isStdin(file)) {
            throw new ParameterException(spec.commandLine(), "run reads the keyboard on standard input: name the program's file");
        }
        boolean json = format.equals("json");
        Reporter reporter = new Reporter(Reporter.Format.GNU, quiet, json ? err : out, err, common.language());
        int status;
        try {
            CommonOptions.Setup setup = common.load(reporter);
            if (optionalStop != null) {
                setup = new CommonOptions.Setup(setup.session().withProfile(
                        setup.profile().withOptionalStop(optionalStop == OnOff.on)), setup.reporter());
            }
            status = send(setup, reporter, resume, json, out, err);
        } catch (TableException e) {
            status = reporter.tableFault(e);
        }
        out.flush();
        err.flush();
        return status;
    }

    private int send(CommonOptions.Setup setup, Reporter reporter, ResumePoint resume, boolean json, PrintWriter out,
                     PrintWriter err) throws TableException {
        String name = SourceFiles.display(file);
        Messages messages = setup.tables().messages().in(common.language());
        EventSink events = json ? new JsonEvents(out) : new StatusText(out, err, name, quiet, System.console() != null, reporter.phrases());
        Optional<SimOptions> sim = Optional.of(stock.options(setup.profile(), file, reporter.phrases(), spec, err::println));
        // 0. a bus card (ISA, PCI) answers on the computer's bus only: refused before anything is compiled
        // or opened (the profile still compiles for it with gcnc compile)
        gcnc.machine.GalilModel busModel = setup.profile().galilModel();
        if (busModel.busOnly()) {
            return refuse(events, messages, Code.E830_BUS_ONLY_MODEL, setup.profile().name(), busModel.name(),
                    busModel.family().startsWith("DMC-17") ? "ISA" : "PCI");
        }
        // 1. the compile, as `gcnc compile` does it: FILE.dmc (and FILE.stream in the stream form) with their
        // maps, written only when clean; what the run needs of it (the lines as the simulator replayed them,
        // with its clock; the checker's state at each block) taken as the compile publishes it
        // (CompiledRun), so that what is sent is what the compiler made and the time left is its cycle time
        Optional<gcnc.dmc.Form> asked = Optional.ofNullable(form);
        Path dmc = DmcOutputs.defaultOutput(file);
        CompiledRun seen = new CompiledRun();
        DmcProgram program;
        BlockTable blocks;
        gcnc.dmc.Form chosen;
        try (FormOutputs outputs = FormOutputs.open(file, dmc, true, gcnc.output.AtomicOutput.Name.DERIVED)) {
            String text;
            try (Reader in = SourceFiles.open(file)) {
                text = CompiledRun.text(in); // read once: the compile's input and the comments a stop shows
            }
            Session session = setup.session().withPrograms(SourceFiles.programsFolder(file));
            // blended as the profile plans it; step mode runs one block at a time, so every motion
            // stops at its end there (docs/run.md, "Step mode")
            // a program form asked for that does not fit is E238, a finding of the compile's
            Compiler.Result r = session.compileInto(outputs, file.getFileName().toString(), file, new StringReader(text), sim,
                    false, asked, step, seen);
            chosen = r.ok() ? outputs.form() : null;
            if (!r.ok()) {
                if (json) {
                    for (Diagnostic d : r.diagnostics().sorted()) {
                        events.accept(new Event.Finding(d.code().id(), d.severity().label(), d.span().line(),
                                messages.render(d.code(), d.args())));
                    }
                } else {
                    reporter.report(name, r.diagnostics());
                }
                err.println(reporter.phrases().get("run.not_clean", name,
                        reporter.phrases().count(r.diagnostics().errorCount(), "error")));
                return Sender.REFUSED;
            }
            program = seen.program(setup.profile());
            // 2. the checker's state at each block, for the status line
            blocks = seen.blocks(text);
            outputs.commit();
        } catch (DmcOutputs.Failed e) {
            return reporter.ioFault(e.path(), gcnc.diag.Phrase.IO_CANNOT_WRITE, e.problem());
        } catch (IOException e) {
            return reporter.ioFault(name, gcnc.diag.Phrase.IO_CANNOT_READ, e);
        }
        // 3. the controller the profile names: reachable (a serial port or Ethernet, not a bus card) and,
        // with a probe report, not known to contradict what the run relies on
        gcnc.machine.GalilModel model = setup.profile().galilModel();
        if (probeReport != null) {
            java.util.Optional<RunFault> bad = probed(model, program, target.port != null);
            if (bad.isPresent()) {
                return refuse(events, messages, bad.get().code(), bad.get().args().toArray(new Object[0]));
            }
        }
        // 4. the link
        Link link;
        try {
            link = connection.open(target);
        } catch (RunFault f) {
            events.accept(new Event.Finding(f.code().id(), "error", 0, messages.render(f.code(), f.args())));
            return Sender.CONNECTION;
        }
        // 5. the run, with the operator's keys and Ctrl-C
        Operator operator = new Operator();
        Sender sender = new Sender(setup.profile(), program, blocks, events, messages, operator,
                new Sender.Options(step, dryRun, resume, pollMs, wayBack.ask(operator, json ? err : out, seen.onBlank(),
                        sim.get())), chosen == gcnc.dmc.Form.STREAM
                        ? new StreamForm(pollMs, Sender.tolerance(setup.profile()), stallSeconds)
                        : new ProgramForm(pollMs, Sender.tolerance(setup.profile()), stallSeconds), this::resumeCommand);
        Keys keys = new Keys(operator, ((Main) spec.root().userObject()).streams().in());
        try (keys) {
            return sender.run(link, connection.timeoutMs);
        }
    }

    private static int refuse(EventSink events, Messages messages, Code code, Object... args) {
        List<String> a = new ArrayList<>();
        for (Object o : args) {
            a.add(String.valueOf(o));
        }
        events.accept(new Event.Finding(code.id(), "error", 0, messages.render(code, a)));
        return Sender.CONNECTION;
    }

    /**
     * The probe report held against the run: E833 when it cannot be read or the profile's
     * galil.deviations names no probe row, E832 when the unit contradicts a row the run relies on
     * (over this link, with or without AV in the program) that the profile does not state.
     */
    private java.util.Optional<RunFault> probed(gcnc.machine.GalilModel model, DmcProgram program, boolean serial) {
        gcnc.send.ProbeReport report;
        try {
            report = gcnc.send.ProbeReport.read(probeReport);
        } catch (IOException e) {
            return java.util.Optional.of(new RunFault(Code.E833_PROBE_REPORT, 0, false, probeReport.toString(),
                    e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage()));
        }
        for (String d : model.deviations()) {
            if (gcnc.machine.ProbeRow.byId(d).isEmpty()) {
                return java.util.Optional.of(new RunFault(Code.E833_PROBE_REPORT, 0, false, probeReport.toString(),
                        "the profile's galil.deviations names '" + d + "', no probe row"));
            }
        }
        boolean usesAv = program.usesAfterVector();
        List<String> bad = new ArrayList<>();
        for (gcnc.send.ProbeReport.Result r : report.rows()) {
            if (r.status() == gcnc.send.ProbeReport.Status.CONTRADICTED && r.row().reliedOn(serial, usesAv)
                    && !model.deviations().contains(r.row().id())) {
                bad.add(r.row().id() + " (expected " + r.expected() + "; the unit answered " + r.observed() + ")");
            }
        }
        return bad.isEmpty() ? java.util.Optional.empty() : java.util.Optional.of(new RunFault(Code.E832_PROBE_CONTRADICTS,
                0, false, probeReport.toString(), String.join("; ", bad)));
    }

    /** The command line that resumes at {@code at}: this one with {@code --resume-at} set (and no --dry-run). */
    String resumeCommand(ResumePoint at) {
        List<String> args = new ArrayList<>(spec.commandLine().getParseResult().originalArgs());
        List<String> outArgs = new ArrayList<>();
        outArgs.add("gcnc");
        for (int i = 0; i < args.size(); i++) {
            String a = args.get(i);
            if (a.equals("--resume-at")) {
                i++;
                continue;
            }
            if (a.startsWith("--resume-at=")) {
                continue;
            }
            outArgs.add(quote(a));
        }
        outArgs.add("--resume-at");
        outArgs.add(at.toString());
        return String.join(" ", outArgs);
    }

    private static String quote(String a) {
        return a.matches("[A-Za-z0-9_@%+=:,./-]+") ? a : "'" + a.replace("'", "'\\''") + "'";
    }

    /**
     * The keyboard and Ctrl-C while a program runs: SIGINT is taken from the JVM for the run (the
     * first holds, the second stops; the default handler is back afterwards) and standard input is
     * read line by line (Enter, +, -, h, q).
     */
    static final class Keys implements AutoCloseable {
        private final sun.misc.Signal interrupt = new sun.misc.Signal("INT");
        private sun.misc.SignalHandler previous;
        private final Thread reader;

        Keys(Operator operator, java.io.InputStream in) {
            try {
                previous = sun.misc.Signal.handle(interrupt, s -> operator.interrupt());
            } catch (IllegalArgumentException e) {
                previous = null; // no SIGINT here (a JVM started with -Xrs): Ctrl-C ends the JVM as usual
            }
            reader = new Thread(() -> read(operator, in), "gcnc-run-keys");
            reader.setDaemon(true);
            reader.start();
        }

        private static void read(Operator operator, java.io.InputStream in) {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                for (String l = r.readLine(); l != null; l = r.readLine()) {
                    String k = l.strip();
                    switch (k) {
                        case "" -> operator.enter();
                        case "+" -> operator.override(Math.min(2, Math.round((operator.override() + 0.1) * 10) / 10.0));
                        case "-" -> operator.override(Math.max(0.1, Math.round((operator.override() - 0.1) * 10) / 10.0));
                        case "h" -> operator.interrupt();
                        case "q" -> operator.stop();
                        default -> {
                            if (k.matches("\\d{1,3}%?")) {
                                operator.override(Math.max(0.1, Math.min(2, Integer.parseInt(k.replace("%", "")) / 100.0)));
                            } else {
                                operator.typed(k); // a word the run asks for (the way back's)
                            }
                        }
                    }
                }
            } catch (IOException e) {
                // standard input closed: the keys are gone, Ctrl-C still works
            }
            operator.typed(Operator.END);
        }

        @Override
        public void close() {
            if (previous != null) {
                sun.misc.Signal.handle(interrupt, previous);
            }
        }
    }
}
