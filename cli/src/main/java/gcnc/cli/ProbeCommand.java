package gcnc.cli;

import gcnc.diag.Code;
import gcnc.diag.Messages;
import gcnc.machine.GalilModel;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import gcnc.send.GalilClient;
import gcnc.send.LinkFault;
import gcnc.send.Probe;
import gcnc.send.ProbeReport;
import gcnc.send.RunFault;
import gcnc.tables.TableException;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code gcnc controller probe}: what a real Galil answers, held against the reference (gcnc.send.Probe,
 * docs/run.md "The probe"), written as a JSON report that {@code gcnc run --probe-report} reads.
 */
@Command(name = "probe", mixinStandardHelpOptions = true,
        description = {"Ask a Galil, without moving anything, what the command reference says it answers (echo, CF,"
                + " TC1, memory, the vector buffer, limits, IT), and write a report of the facts it confirmed and"
                + " contradicted. --allow-motion adds a motion test (three short VP segments) after a typed confirmation."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every fact asked was confirmed (or could not be asked)", "1:the unit contradicted a fact (named in"
                + " the report)", "2:usage, connection, no confirmation, or the motion test could not start"})
final class ProbeCommand extends StreamsCommand {
    /** The word the operator types to let the motion test move the axes. */
    static final String WORD = gcnc.send.Operator.MOTION_WORD;

    @Mixin
    CommonOptions common;

    @ArgGroup(exclusive = true, multiplicity = "1")
    ControllerTarget.Where target;

    @Mixin
    ControllerTarget connection;

    @Option(names = "--report", paramLabel = "FILE", required = true, description = "Where to write the report (JSON).")
    Path report;

    @Option(names = "--allow-motion", description = "Also run the motion test: three VP segments of --distance counts along"
            + " the profile's first plane axis and back, reading _CSS and _AVS; asks for the word '" + WORD + "' first.")
    boolean allowMotion;

    @Option(names = "--confirm-from-stdin", description = "Take the typed word from standard input even when it is not a"
            + " terminal (a script that has made sure the machine is clear).")
    boolean confirmFromStdin;

    @Option(names = "--distance", paramLabel = "COUNTS", defaultValue = "1000", description = "Length of each test segment (default: ${DEFAULT-VALUE}).")
    int distance;

    @Option(names = "--speed", paramLabel = "COUNTS/S", defaultValue = "1000", description = "Vector speed of the test (default: ${DEFAULT-VALUE}).")
    int speed;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        Reporter reporter = new Reporter(Reporter.Format.GNU, false, out, err, common.language());
        CommonOptions.Setup setup;
        try {
            setup = common.load(reporter);
        } catch (TableException e) {
            return reporter.tableFault(e);
        }
        Messages messages = setup.tables().messages().in(common.language());
        MachineProfile profile = setup.profile();
        GalilModel model = profile.galilModel();
        int status = probe(profile, model, messages, out, err);
        out.flush();
        err.flush();
        return status;
    }

    private int probe(MachineProfile profile, GalilModel model, Messages messages, PrintWriter out, PrintWriter err) {
        Plane plane = Plane.of(profile);
        char first = gcnc.send.MachineLink.letter(plane.first());
        char second = gcnc.send.MachineLink.letter(plane.second());
        Probe.Motion motion = null;
        if (allowMotion) {
            String why = confirmed();
            if (why != null) {
                return fault(err, messages, Code.E834_PROBE_NOT_CONFIRMED, WORD, why);
            }
            motion = new Probe.Motion(first, second, distance, speed);
        }
        gcnc.send.Link link;
        try {
            link = connection.open(target);
        } catch (RunFault f) {
            return fault(err, messages, f.code(), f.args().toArray());
        }
        ProbeReport r;
        Probe probe = null;
        try (GalilClient client = new GalilClient(link, connection.timeoutMs, m -> out.println("controller: " + m))) {
            probe = new Probe(client, model);
            try {
                r = probe.run(motion, new char[] {first, second});
            } catch (Probe.NotReady e) {
                write(probe.report(), out, err, messages);
                return fault(err, messages, Code.E835_PROBE_NOT_READY, e.getMessage());
            } catch (GalilClient.Rejected e) {
                moving(probe, err);
                return fault(err, messages, Code.E844_PROBE_REFUSED, "'" + GalilClient.printable(e.command()) + "'",
                        refusal(client));
            }
        } catch (LinkFault f) {
            moving(probe, err);
            Code code = switch (f.kind()) {
                case DROPPED -> Code.E841_PROBE_DROPPED;
                case TIMEOUT -> Code.E842_PROBE_NO_REPLY;
                case GARBAGE -> Code.E843_PROBE_GARBAGE;
            };
            return fault(err, messages, code, "'" + GalilClient.printable(f.command()) + "'", f.detail());
        } catch (IOException e) {
            return fault(err, messages, Code.E841_PROBE_DROPPED, "a question", String.valueOf(e.getMessage()));
        }
        Integer failed = write(r, out, err, messages);
        if (failed != null) {
            return failed;
        }
        return r.contradicted().isEmpty() ? ExitCode.CLEAN : ExitCode.PROGRAM_ERRORS;
    }

    /** After a fault in the motion test: where the axis may be, before the error line. */
    private static void moving(Probe probe, PrintWriter err) {
        if (probe != null && probe.moving() != null) {
            err.println("note: " + probe.moving());
        }
    }

    /** TC1's code and text for a command the unit refused, or why it could not be read. */
    private static String refusal(GalilClient client) {
        try {
            String tc = client.lastError();
            return tc.isEmpty() ? "TC1 refused too" : "TC1: " + tc;
        } catch (IOException e) {
            return "TC1 unanswered: " + e.getMessage();
        }
    }

    /** Prints each row, a warning per contradiction, and writes the file; an exit status when it cannot. */
    private Integer write(ProbeReport r, PrintWriter out, PrintWriter err, Messages messages) {
        if (r == null) {
            return null;
        }
        out.println("probe of " + (r.revision().isEmpty() ? "an unnamed controller" : r.revision()) + " over " + r.link());
        r.facts().forEach((k, v) -> out.println("  " + k + ": " + v));
        for (ProbeReport.Result row : r.rows()) {
            out.println("  " + row.row().id() + ": " + row.status().spelling() + " (" + row.observed() + ")");
            if (row.status() == ProbeReport.Status.CONTRADICTED) {
                err.println("warning[" + Code.E836_PROBE_CONTRADICTION.id() + "]: " + messages.render(
                        Code.E836_PROBE_CONTRADICTION, List.of(row.row().id(), row.expected(), row.observed())));
            }
        }
        try {
            r.write(report);
        } catch (IOException e) {
            return fault(err, messages, Code.E833_PROBE_REPORT, report.toString(), String.valueOf(e.getMessage()));
        }
        out.println("report written to " + report);
        return null;
    }

    /** Null when the operator typed the word; else why the motion test does not run. */
    private String confirmed() {
        if (System.console() == null && !confirmFromStdin) {
            return "standard input is not a terminal: give --confirm-from-stdin to take the word from it";
        }
        PrintWriter out = spec.commandLine().getOut();
        out.print("The motion test moves " + distance * 3 + " counts along the first plane axis and back."
                + " Type '" + WORD + "' to go on: ");
        out.flush();
        try {
            BufferedReader in = new BufferedReader(new InputStreamReader(((Main) spec.root().userObject()).streams().in(),
                    StandardCharsets.UTF_8));
            String line = in.readLine();
            return line != null && line.strip().equals(WORD) ? null : "'" + (line == null ? "" : line.strip())
                    + "' was typed";
        } catch (IOException e) {
            return "standard input could not be read";
        }
    }

    private static int fault(PrintWriter err, Messages messages, Code code, Object... args) {
        List<String> a = new java.util.ArrayList<>();
        for (Object o : args) {
            a.add(String.valueOf(o));
        }
        err.println("error[" + code.id() + "]: " + messages.render(code, a));
        return ExitCode.USAGE;
    }
}
