package gcnc.cli;

import gcnc.controller.InjectedFault;
import gcnc.controller.Model;
import gcnc.controller.VirtualController;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code gcnc controller --virtual}: a virtual Galil on loopback TCP or a pty (gcnc.controller,
 * docs/virtual-controller.md); runs until stopped.
 */
@Command(name = "controller", mixinStandardHelpOptions = true, subcommands = ProbeCommand.class,
        description = {"Run a virtual Galil controller: it answers Galil's command protocol and runs the vector"
                + " motion in time, for gcnc run, tests and demos.",
                "TCP listens on 127.0.0.1 only; a pty is one end of a pair made with socat. Ctrl+C stops it."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:stopped", "2:usage, a bad --fault or --model, the port is taken or the pty cannot be opened"})
final class ControllerCommand extends StreamsCommand {
    @Option(names = "--virtual",
            description = "The virtual controller (gcnc controller probe asks a real one).")
    boolean virtual;

    @ArgGroup(exclusive = true, multiplicity = "0..1")
    Link link;

    static final class Link {
        @Option(names = "--tcp", paramLabel = "PORT", required = true,
                description = "Listen on 127.0.0.1:PORT (0: a free port, printed); Galil's own port is 23.")
        Integer tcp;

        @Option(names = "--pty", paramLabel = "PATH", required = true,
                description = "Serve the pty at PATH, one end of: socat -d -d pty,raw,echo=0,link=PATH pty,raw,echo=0,link=OTHER")
        Path pty;
    }

    @Option(names = "--model", paramLabel = "NAME", defaultValue = "DMC-4040",
            description = "The model it answers as (^R^V) and whose memory and outputs it has, a model of tables/galil_models.csv (default: ${DEFAULT-VALUE}).")
    String model;

    @Option(names = "--speed", paramLabel = "X", defaultValue = "1",
            description = "Run the motion X times faster than real time (default: ${DEFAULT-VALUE}).")
    double speed;

    @Option(names = "--fault", paramLabel = "SPEC",
            description = "A fault to inject, repeatable: garbage-after=BYTES, reject=COMMAND, disconnect-after=BYTES,"
                    + " slow=MS, slow-thread=MS, stall=SEGMENT, limit-at=SEGMENT.")
    List<String> faults = new ArrayList<>();

    @Option(names = "--trace", paramLabel = "FILE",
            description = "Write one line per executed segment: sequence, segment, kind, end position in counts, free slots, time.")
    Path trace;

    @Option(names = "--spindle", paramLabel = "RPM_PER_VOLT,COUNTS_PER_REV", defaultValue = "410,4096",
            description = "The lathe's spindle drive (r/min per volt of OF) and encoder (counts per revolution) wired to"
                    + " the controller, which thread passes are geared to (default: ${DEFAULT-VALUE}, the haas profile's).")
    String spindle;

    @Mixin
    LanguageOption lang;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        ErrorMessages.Lang language = lang.language(spec);
        Phrases say = new Phrases(language);
        if (!virtual || link == null) {
            err.println("gcnc: " + say.get("controller.what"));
            return ExitCode.USAGE;
        }
        Model m = Model.named(model).orElse(null);
        if (m == null) {
            err.println("gcnc: " + say.get("controller.bad_model", model, Model.names()));
            return ExitCode.USAGE;
        }
        if (m.galil.busOnly()) {
            // an ISA/PCI card answers on the computer's bus, never on a serial port or Ethernet (galil_models.csv host_link)
            err.println("gcnc: " + say.get("controller.bus_model", m.galil.name()));
            return ExitCode.USAGE;
        }
        if (!(speed > 0) || speed > 10_000) {
            err.println("gcnc: " + say.get("controller.bad_speed", speed));
            return ExitCode.USAGE;
        }
        List<InjectedFault> parsed = new ArrayList<>();
        for (String f : faults) {
            try {
                parsed.add(InjectedFault.parse(f));
            } catch (IllegalArgumentException e) {
                err.println("gcnc: " + say.get("controller.bad_fault", f));
                return ExitCode.USAGE;
            }
        }
        if (link.pty != null && !java.nio.file.Files.exists(link.pty)) {
            err.println("gcnc: " + say.get("controller.no_pty", link.pty));
            return ExitCode.USAGE;
        }
        String[] sp = spindle.split(",", -1);
        double rate;
        try {
            rate = VirtualController.Options.spindleRate(Double.parseDouble(sp[0]), Integer.parseInt(sp[sp.length - 1]));
        } catch (NumberFormatException e) {
            rate = -1;
        }
        if (sp.length != 2 || !(rate > 0)) {
            err.println("gcnc: " + say.get("controller.bad_spindle", spindle));
            return ExitCode.USAGE;
        }
        VirtualController.Options options = new VirtualController.Options(m, speed, parsed, trace, rate);
        VirtualController vc;
        try {
            vc = link.tcp != null ? VirtualController.tcp(link.tcp, options) : VirtualController.pty(link.pty, options);
        } catch (IOException e) {
            err.println("gcnc: " + say.get("controller.cannot_start", link.tcp != null ? "127.0.0.1:" + link.tcp : link.pty,
                    SourceFiles.reason(e, language)));
            return ExitCode.USAGE;
        }
        serveUntilStopped(vc::close, () -> {
            out.println(say.get("controller.serving", m.revision, link.tcp != null ? "127.0.0.1:" + vc.port() : link.pty,
                    speed, parsed.isEmpty() ? "-" : parsed.toString()));
            out.flush();
        });
        return ExitCode.CLEAN;
    }
}
