package gcnc.studio;

import gcnc.Session;
import gcnc.diag.Code;
import gcnc.diag.Messages;
import gcnc.machine.MachineProfile;
import gcnc.send.Event;
import gcnc.send.EventSink;
import gcnc.send.Link;
import gcnc.send.Operator;
import gcnc.send.ProgramForm;
import gcnc.send.ResumePoint;
import gcnc.send.RunFault;
import gcnc.send.Sender;
import gcnc.send.StreamForm;
import gcnc.send.TcpLink;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * How a studio run reaches its controller and what sends to it: the link (the studio's virtual
 * Galil, a controller's Ethernet port, a serial port through the command line's link), the
 * command line's {@link Sender} and its {@link ProgramForm} or {@link StreamForm} (as the compile
 * chose) with {@code gcnc run}'s defaults, the dry
 * run an arm is, and the command line that resumes a stopped run from a terminal.
 */
final class RunControllers implements AutoCloseable {
    /** As {@code gcnc run}'s defaults: poll every 100 ms, a reply within 2 s, a stall after 10 s. */
    static final int POLL_MS = 100;
    static final int TIMEOUT_MS = 2000;
    static final double STALL_SECONDS = 10;

    private final VirtualLathe virtual;
    private final Studio.SerialPorts serial;
    private final Messages messages;

    RunControllers(Studio.Running settings, Messages messages) {
        this.virtual = new VirtualLathe(settings.virtualSpeed());
        this.serial = settings.serial();
        this.messages = messages;
    }

    /** Whether this studio can open serial ports. */
    boolean serial() {
        return serial != null;
    }

    /** The studio's virtual controller for this machine; homed first for a run from the start (not a resume). */
    String virtual(MachineProfile profile, boolean home) throws Http.Fail {
        try {
            if (home) {
                virtual.home(profile);
            }
            return virtual.address(profile);
        } catch (IOException e) {
            throw new Http.Fail(500, "could not start the virtual controller: " + e.getMessage());
        }
    }

    /** {@code gcnc run --dry-run}: connect, pre-flight, download and read back, no motion. */
    int dryRun(RunArm a, EventSink events) {
        Operator operator = new Operator();
        if (a.step()) {
            // step mode downloads block by block, each after an Enter: all given in advance (nothing moves)
            for (int i = 0; i <= a.program().program().size(); i++) {
                operator.enter();
            }
        }
        Link link = link(a, events);
        return link == null ? Sender.CONNECTION : sender(a, operator, events, true).run(link, TIMEOUT_MS);
    }

    /** The command line's sender and program form, with gcnc run's defaults. */
    Sender sender(RunArm a, Operator operator, EventSink events, boolean dryRun) {
        Session s = a.context().session();
        return new Sender(s.profile(), a.program().program(), a.program().blocks(), events, messages, operator,
                new Sender.Options(a.step(), dryRun, a.resumeAt(), POLL_MS),
                a.program().form() == gcnc.dmc.Form.STREAM
                        ? new StreamForm(POLL_MS, Sender.tolerance(s.profile()), STALL_SECONDS)
                        : new ProgramForm(POLL_MS, Sender.tolerance(s.profile()), STALL_SECONDS), p -> resumeCommand(a, p));
    }

    /** The link to the arm's controller; a link that cannot be opened is told as a finding (and null). */
    Link link(RunArm a, EventSink events) {
        try {
            return open(a);
        } catch (RunFault f) {
            events.accept(new Event.Finding(f.code().id(), "error", 0, messages.render(f.code(), f.args())));
            return null;
        }
    }

    private Link open(RunArm a) throws RunFault {
        if (a.target() instanceof RunTarget.Serial p) {
            return serial.open(p.device(), p.baud(), p.hardwareHandshake());
        }
        return tcp(a.target() instanceof RunTarget.Tcp t ? t.address() : a.address());
    }

    private static Link tcp(String address) throws RunFault {
        try {
            return TcpLink.open(address, TIMEOUT_MS);
        } catch (IOException e) {
            throw new RunFault(Code.E817_NO_CONNECTION, 0, false, address,
                    e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage());
        }
    }

    /** The command line that does the same resume: {@code gcnc run NAME --machine M <target> [--step] --resume-at N}. */
    String resumeCommand(RunArm a, ResumePoint at) {
        List<String> args = new ArrayList<>(List.of("gcnc", "run", a.name(), "--machine",
                a.context().profileFile() != null ? a.context().profileFile() : a.context().session().profile().name()));
        if (a.target() instanceof RunTarget.Serial p) {
            args.addAll(List.of("--port", p.device(), "--baud", Integer.toString(p.baud())));
            if (!p.hardwareHandshake()) {
                args.addAll(List.of("--handshake", "none"));
            }
        } else {
            args.addAll(List.of("--tcp", a.target() instanceof RunTarget.Tcp t ? t.address() : a.address()));
        }
        if (a.step()) {
            args.add("--step");
        }
        args.addAll(List.of("--resume-at", at.toString()));
        return String.join(" ", args.stream().map(RunControllers::quote).toList());
    }

    private static String quote(String a) {
        return a.matches("[A-Za-z0-9_@%+=:,./-]+") ? a : "'" + a.replace("'", "'\\''") + "'";
    }

    @Override
    public void close() {
        virtual.close();
    }
}
