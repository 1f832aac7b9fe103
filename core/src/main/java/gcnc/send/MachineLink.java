package gcnc.send;

import gcnc.diag.Code;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The Galil controller as the sender uses it: pre-flight questions, program download and read-back,
 * execution, polling, and the ways to stop. Each method is one or a few commands of the Galil
 * command reference (COMALL; docs/run.md gives the page of each).
 */
public final class MachineLink {
    private final GalilClient client;
    private final MachineProfile profile;
    private final Plane plane;

    public MachineLink(GalilClient client, MachineProfile profile, Plane plane) {
        this.client = client;
        this.profile = profile;
        this.plane = plane;
    }

    public GalilClient client() {
        return client;
    }

    /** What pre-flight found. */
    public record Facts(String revision, String model, boolean firmware12a, int labelsLeft, int variablesLeft,
                        int arraySpace, int vectorSlots, String pendingError, String limits, List<Character> motorsOff,
                        double[] position, boolean programRunning, boolean moving, boolean echoed) {
    }

    /** {@code ^R^V}: the revision report, "DMC4040 Rev 1.2c" (gclib's address list shows the same). */
    public String revision() throws IOException {
        GalilClient.Reply r = client.query("\u0012\u0016");
        return r.ok() ? r.data().strip() : "";
    }

    /**
     * The pre-flight: model and firmware, memory, the vector buffer, a pending error, limit switches,
     * motors, where the axes are, whether a program or a sequence runs. Asks, and changes only how the
     * controller talks to this host: {@code EO 0} first on a serial link (a factory unit echoes until
     * then), {@code CW 1}, which marks unsolicited output, {@code CF I}, which sends it to this port,
     * and TC1, which reads and clears the last error. ({@code CS S}, which empties the vector buffer,
     * is {@link #clearSequence}, once the sender knows nothing moves.)
     */
    public Facts preflight() throws IOException {
        boolean echoed = client.link().serial() && client.disableEcho();
        String rev = revision();
        // unsolicited output with the high bit set, to tell it from replies (COMALL CW; gclib sets it too)
        client.command("CW 1");
        // unsolicited messages (the handlers' MG) to the port this command came in on: the power-up
        // port is the main serial port (COMALL CF, default S), so over Ethernet they would never arrive.
        // COMALL recommends a second Ethernet handle for them; gcnc uses one handle with CW 1 to tell
        // them apart (docs/galil.md, "Unsolicited messages")
        require("CF I");
        GalilClient.Reply tc = client.query("TC1");
        String pending = tc.ok() ? tc.data().strip() : "";
        int labels = (int) optional("_DL", -1);
        int variables = (int) optional("_UL", -1);
        int arrays = (int) optional("_DA", -1);
        int slots = (int) optional("_LMS", -1);
        StringBuilder limits = new StringBuilder();
        List<Character> off = new ArrayList<>();
        for (int ch : new int[] {plane.first(), plane.second()}) {
            char a = letter(ch);
            // CN -1 (the default): _LF/_LR read 0 while the switch is active (COMALL LF/LR, CN)
            if (optional("_LF" + a, 1) == 0) {
                limits.append(limits.length() > 0 ? ", " : "").append("forward limit of ").append(a);
            }
            if (optional("_LR" + a, 1) == 0) {
                limits.append(limits.length() > 0 ? ", " : "").append("reverse limit of ").append(a);
            }
            if (optional("_MO" + a, 0) == 1) {
                off.add(a);
            }
        }
        double[] pos = position();
        boolean running = optional("_XQ0", -1) >= 0;
        boolean moving = optional("_BGS", 0) != 0;
        return new Facts(rev, model(rev), firmware12a(rev), labels, variables, arrays, slots,
                pending.isEmpty() || pending.startsWith("0") ? "" : pending, limits.toString(), off, pos, running, moving,
                echoed);
    }

    /**
     * {@code CS S}, then {@code MG _LMS}: empties the vector buffer of segments an interrupted sequence
     * left (COMALL CS: "will remove VP, CR or LI commands stored in a motion sequence"; "Not Valid while in
     * motion", so only when nothing moves) and returns the free slots it reports, the model's whole
     * buffer when it is empty (COMALL LI: "511 returned means the buffer is empty").
     */
    public int clearSequence() throws IOException {
        require("CS S");
        return (int) client.number("_LMS");
    }

    /** The model in a revision report, "DMC4040" of "DMC4040 Rev 1.2c", upper case, or "" when there is none. */
    public static String model(String revision) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?i)\\b(DMC-?[0-9A-Z]+)").matcher(revision);
        return m.find() ? m.group(1).toUpperCase(Locale.ROOT) : "";
    }

    /** Whether two model names are the same controller: "DMC-4040" is "DMC4040". */
    public static boolean sameModel(String a, String b) {
        return normal(a).equals(normal(b));
    }

    private static String normal(String m) {
        return m.toUpperCase(Locale.ROOT).replaceAll("[^A-Z0-9]", "");
    }

    /**
     * Whether a revision report names firmware 1.2a or later ("DMC4040 Rev 1.2d"), which raises the
     * program lines from 2,000 to 4,000 (COMALL XQ, DL argument ranges). A revision the sender cannot
     * read counts as older.
     */
    public static boolean firmware12a(String revision) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?i)Rev\\s*(\\d+)\\.(\\d+)([a-z]?)").matcher(revision);
        if (!m.find()) {
            return false;
        }
        int major = Integer.parseInt(m.group(1));
        int minor = Integer.parseInt(m.group(2));
        return major > 1 || major == 1 && minor >= 2;
    }

    /** An operand's value, or {@code fallback} when the controller does not know it ({@code ?}). */
    private double optional(String operand, double fallback) throws IOException {
        GalilClient.Reply r = client.query("MG " + operand);
        if (!r.ok()) {
            client.query("TC1"); // clears the error the question left
            return fallback;
        }
        try {
            return Double.parseDouble(r.data().strip());
        } catch (NumberFormatException e) {
            throw new LinkFault(LinkFault.Kind.GARBAGE, "MG " + operand, "'" + GalilClient.printable(r.data()) + "' where a number belongs");
        }
    }

    /** {@code TP}: the plane's two positions, Galil counts. */
    public double[] position() throws IOException {
        double[] all = client.numbers("TP");
        if (all.length <= plane.second()) {
            throw new LinkFault(LinkFault.Kind.GARBAGE, "TP", all.length + " positions where " + (plane.second() + 1) + " belong");
        }
        return new double[] {all[plane.first()], all[plane.second()]};
    }

    public static char letter(int channel) {
        return "XYZWEFGH".charAt(channel);
    }

    /** {@code HX}: halts every thread (DL is refused while a program runs, TC 17). */
    public void halt() throws IOException {
        require("HX");
    }

    /** {@code XQ #GCNC,0}: runs the downloaded program in thread 0. */
    public void execute() throws IOException {
        require("XQ #GCNC,0");
    }

    /** {@code MG _XQ0}: the program line thread 0 is executing (0-based), -1 when it runs no more. */
    public int executing() throws IOException {
        return (int) client.number("_XQ0");
    }

    /**
     * Where thread 0 and the vector sequence are, in one question: {@code MG _XQ0,_CSS} gives the
     * program line thread 0 executes (-1 when it ended) and the segment of the sequence executing,
     * read together, so that the segment is the one of the sequence at that line (two questions
     * could straddle the start of the next sequence, whose {@code BGS} sets {@code _CSS} back).
     */
    public int[] executingAndSegment() throws IOException {
        String cmd = "MG _XQ0,_CSS";
        double[] v = client.numbers(cmd);
        if (v.length != 2) {
            throw new LinkFault(LinkFault.Kind.GARBAGE, cmd, v.length + " numbers where 2 belong");
        }
        return new int[] {(int) v[0], (int) v[1]};
    }

    /**
     * {@code MG _CSS}: the segment counter of the running vector sequence, from zero: 0 during its first
     * segment, 1 during the second (DMC-40x0 User Manual p.86, "Segment counter - returns number of the
     * segment in the sequence, starting at zero", with its worked example; the same in the DMC-2x00 and
     * DMC-13X8 manuals; COMALL CS only says "the segment number in the sequence"). After the sequence
     * ended the manuals do not say what it reads; {@link Download.Segments#segment} names the last segment
     * for either reading. EPICS counts the segments processed from it.
     */
    public int segment() throws IOException {
        return (int) client.number("_CSS");
    }

    /** {@code MG _TC}: the last error's code without clearing it; 0 for none. */
    public int errorCode() throws IOException {
        return (int) client.number("_TC");
    }

    /** {@code MG _ED}: the program line of the last error. */
    public int errorLine() throws IOException {
        return (int) client.number("_ED");
    }

    /** {@code MG _SC} of the plane's first channel: why its motion ended (COMALL SC). */
    public int stopCode() throws IOException {
        return (int) client.number("_SC" + letter(plane.first()));
    }

    /** The meaning of a stop code (COMALL SC; the codes a lathe program meets). */
    public static String stopReason(int code) {
        return switch (code) {
            case 1 -> "stopped at the commanded position";
            case 2, 3 -> "a limit switch";
            case 4 -> "ST";
            case 6 -> "the abort input";
            case 7 -> "AB";
            case 8 -> "off on error";
            case 99 -> "MC timeout";
            case 100 -> "a vector sequence still running";
            case 101 -> "stopped at the end of a vector sequence";
            default -> "see the command reference, SC";
        };
    }

    /** {@code VR n}: the vector speed ratio, 0 (a feed hold, decelerating at VD) to 10 (COMALL VR). */
    public void ratio(double r) throws IOException {
        require("VR " + String.format(Locale.ROOT, "%.4f", r).replaceAll("\\.?0+$", ""));
    }

    /** Sends a command that must be accepted; a {@code ?} is {@link GalilClient.Rejected}. */
    public void require(String command) throws IOException {
        if (!client.command(command).ok()) {
            throw new GalilClient.Rejected(command);
        }
    }

    /**
     * Stops motion and spindle: {@code ST} (a decelerating stop that also ends the program threads
     * when sent from the host; COMALL ST), {@code AB} only when ST is refused or unanswered; then the
     * spindle reference to 0 V ({@code OF}) and the outputs of M05 and M09 from the profile. Best
     * effort: every command is tried even when one fails; returns what could not be done.
     */
    public List<String> stopAll() {
        List<String> failed = new ArrayList<>();
        boolean stopped = tryCommand("ST");
        if (!stopped && !tryCommand("AB")) {
            failed.add("ST/AB");
        }
        long until = System.currentTimeMillis() + 3000;
        try {
            while (System.currentTimeMillis() < until && client.number("_BGS") != 0) {
                Thread.sleep(50);
            }
        } catch (IOException | InterruptedException e) {
            // the link is gone or the wait was cut short: the spindle is still switched off below
        }
        if (!tryCommand(spindleZero())) {
            failed.add(spindleZero());
        }
        for (int m : new int[] {5, 9}) {
            for (String out : profile.outputsFor(m)) {
                if (!tryCommand(out)) {
                    failed.add(out);
                }
            }
        }
        return failed;
    }

    /** {@code OF} with 0 V in the spindle channel's place ({@code OF ,,0} for C). */
    public String spindleZero() {
        return "OF " + ",".repeat(profile.spindleChannel()) + "0";
    }

    private boolean tryCommand(String c) {
        try {
            GalilClient.Reply r = client.command(c);
            if (!r.ok()) {
                client.query("TC1");
            }
            return r.ok();
        } catch (IOException e) {
            return false;
        }
    }

    /** A {@code ?} reply turned into E820: TC1's code and text, at G-code line {@code line}. */
    public RunFault refused(String command, int line, boolean moved) {
        String tc;
        try {
            tc = client.lastError();
        } catch (IOException e) {
            tc = "";
        }
        String[] f = tc.split("\\s+", 2);
        return new RunFault(Code.E820_CONTROLLER_ERROR, line, moved, command, f[0].isEmpty() ? "?" : f[0],
                f.length > 1 ? f[1] : "no text");
    }
}
