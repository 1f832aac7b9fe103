package gcnc.send;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Galil's command protocol over a {@link Link}, one command in flight at a time (Application Note
 * 4413: Galil's own drivers send nothing new until the last reply is in). Each command is sent with
 * a CR; the controller answers {@code :} (accepted) or {@code ?} (rejected), data before the colon
 * ending in CR LF (DMC-40x0 manual p.71, DMC-2x00 p.65). Every reply is checked:
 * a reply that does not come within the timeout, bytes that are not the protocol's, data where the
 * command returns none, and a closed link are each a {@link LinkFault}; a {@code ?} is a
 * {@link Reply} the caller must act on.
 *
 * <p>Unsolicited output (MG of a running program, the controller's own error messages) comes with
 * the high bit of every character set once {@code CW 1} is in force (COMALL CW); those bytes are
 * taken out of the reply stream and handed to {@code unsolicited} line by line.
 */
public final class GalilClient implements AutoCloseable {
    /** A reply: accepted ({@code :}) or rejected ({@code ?}), with the data that came before it. */
    public record Reply(boolean ok, String data) {
    }

    /** GCNC_RUN_TRACE set: every command and reply on standard error (for a bench session). */
    private static final boolean TRACE = System.getenv("GCNC_RUN_TRACE") != null;

    /**
     * Forgets what is in flight after a reply that could not be read (garbage, a timeout): what is
     * pending is dropped and what arrives within {@code ms} is read and dropped too, so that the
     * next command's reply is its own.
     */
    public void resync(int ms) {
        pending.setLength(0);
        long until = System.currentTimeMillis() + ms;
        try {
            while (System.currentTimeMillis() < until) {
                int n = link.read(buffer, (int) Math.max(1, until - System.currentTimeMillis()));
                if (n < 0) {
                    return;
                }
            }
        } catch (IOException e) {
            // the link is gone: the next command says so
        }
    }

    private final Link link;
    private final int timeoutMs;
    private final Consumer<String> unsolicited;
    private final StringBuilder pending = new StringBuilder();
    private final StringBuilder unsolicitedLine = new StringBuilder();
    private final byte[] buffer = new byte[4096];
    private long commands;

    public GalilClient(Link link, int timeoutMs, Consumer<String> unsolicited) {
        this.link = link;
        this.timeoutMs = timeoutMs;
        this.unsolicited = unsolicited;
    }

    public Link link() {
        return link;
    }

    /** How many commands have been sent (each exactly once: nothing is ever re-sent). */
    public long commands() {
        return commands;
    }

    /** How long a serial line is read and its bytes dropped before its first command (a quiet line costs this once). */
    static final int STALE_MS = 200;

    /**
     * {@code EO 0} on a serial link: turns the port's echo off (COMALL EO: "This command is defaulted to
     * EO1. Galil software upon connection will set EO0. The EO command is accepted over the serial port
     * only"). Sent first, before any other command, so that it is the only command whose reply may carry
     * the echo: the echo of {@code EO 0} and its CR (and an LF, should a unit add one) is taken off before
     * the reply is read. Before it, what the line held from before this connection (an operator's
     * terminal session, the replies of a host that went away, a program's messages) is read for
     * {@link #STALE_MS} and dropped, so that the first reply read is its own. Returns whether the
     * controller echoed it; a {@code ?} is {@link Rejected}.
     */
    public boolean disableEcho() throws IOException {
        resync(STALE_MS);
        String cmd = "EO 0";
        String sent = cmd + "\r";
        write(cmd, sent);
        long deadline = System.currentTimeMillis() + timeoutMs;
        int matched = 0;
        while (matched < sent.length()) {
            if (pending.length() == 0) {
                fill(cmd, deadline);
                continue;
            }
            if (pending.charAt(0) != sent.charAt(matched)) {
                if (matched == 0) {
                    break; // no echo: what came is the reply
                }
                throw new LinkFault(LinkFault.Kind.GARBAGE, cmd, "'" + printable(sent.substring(0, matched))
                        + printable(pending.toString()) + "' where the echo of EO 0 or its reply belongs");
            }
            pending.deleteCharAt(0);
            matched++;
        }
        if (matched == sent.length()) {
            while (pending.length() == 0) {
                fill(cmd, deadline);
            }
            if (pending.charAt(0) == '\n') {
                pending.deleteCharAt(0);
            }
        }
        Reply r = readReply(cmd, false, deadline);
        if (!r.ok()) {
            throw new Rejected(cmd);
        }
        return matched == sent.length();
    }

    /** Sends a command that returns no data; its reply must be {@code :} or {@code ?} alone. */
    public Reply command(String command) throws IOException {
        return exchange(command, false);
    }

    /** Sends an interrogation ({@code MG}, {@code TP}, {@code TC1}, ...) whose reply carries data. */
    public Reply query(String command) throws IOException {
        return exchange(command, true);
    }

    /** {@code TC1}: "code text" of the last error (and clears it); "" when TC1 itself is refused. */
    public String lastError() throws IOException {
        Reply r = query("TC1");
        return r.ok() ? r.data().strip() : "";
    }

    /** {@code MG operand}: the operand's value; anything but a number is not the protocol. */
    public double number(String operand) throws IOException {
        String cmd = "MG " + operand;
        Reply r = query(cmd);
        if (!r.ok()) {
            throw new Rejected(cmd);
        }
        return parseNumber(cmd, r.data());
    }

    /** The numbers of a reply such as {@code TP}'s " 100, -20, 0, 0". */
    public double[] numbers(String command) throws IOException {
        Reply r = query(command);
        if (!r.ok()) {
            throw new Rejected(command);
        }
        String[] f = r.data().strip().split("[,\\s]+");
        double[] v = new double[f.length];
        for (int i = 0; i < f.length; i++) {
            v[i] = parseNumber(command, f[i]);
        }
        return v;
    }

    /** A {@code ?} where the sender needs {@code :}: the caller asks {@code TC1} and stops. */
    public static final class Rejected extends IOException {
        private final String command;

        public Rejected(String command) {
            super("'" + command + "' rejected");
            this.command = command;
        }

        public String command() {
            return command;
        }
    }

    private static double parseNumber(String cmd, String text) throws LinkFault {
        try {
            return Double.parseDouble(text.strip());
        } catch (NumberFormatException e) {
            throw new LinkFault(LinkFault.Kind.GARBAGE, cmd, "'" + printable(text) + "' where a number belongs");
        }
    }

    /**
     * {@code DL}: downloads {@code lines} as the controller's program, terminated by {@code \}
     * (COMALL DL). The controller is silent while the lines stream and answers after the
     * terminator; firmware differs in how many colons it sends then (one for the terminator and
     * one deferred for DL, as tmtsoftware's galil-io and motorapp/Galil read), so the download is
     * closed by a marker query, {@code MG 20261127}, and every reply before the marker must be a
     * colon: a {@code ?} means a line was refused (TC 60, line too long or too many lines).
     */
    public Reply download(List<String> lines) throws IOException {
        StringBuilder b = new StringBuilder("DL\r");
        for (String l : lines) {
            b.append(l).append('\r');
        }
        b.append('\\');
        write("DL", b.toString());
        String marker = "MG 20261127";
        write(marker, marker + "\r");
        StringBuilder before = new StringBuilder();
        long deadline = System.currentTimeMillis() + Math.max(timeoutMs, 2000L + lines.size() * 2L);
        while (true) {
            Reply r = readReply(marker, true, deadline);
            if (r.data().strip().startsWith("20261127")) {
                boolean refused = before.indexOf("?") >= 0;
                return new Reply(!refused && r.ok(), before.toString());
            }
            if (!r.data().isBlank()) {
                throw new LinkFault(LinkFault.Kind.GARBAGE, "DL", "'" + printable(r.data()) + "' during a download");
            }
            before.append(r.ok() ? ':' : '?');
        }
    }

    /**
     * {@code UL}: the program the controller holds, line by line. The text ends with Ctrl-Z or
     * {@code \} and then a colon (COMALL UL).
     */
    public List<String> upload() throws IOException {
        String cmd = "UL";
        write(cmd, "UL\r");
        long deadline = System.currentTimeMillis() + Math.max(timeoutMs, 5000);
        StringBuilder text = new StringBuilder();
        while (true) {
            int end = endOfUpload();
            if (end >= 0) {
                text.append(pending, 0, end);
                pending.delete(0, end + 1);
                Reply colon = readReply(cmd, false, deadline);
                if (!colon.ok()) {
                    throw new Rejected(cmd);
                }
                break;
            }
            if (pending.length() > 0 && (pending.charAt(0) == '?') && text.length() == 0) {
                pending.deleteCharAt(0);
                throw new Rejected(cmd);
            }
            fill(cmd, deadline);
        }
        List<String> lines = new ArrayList<>();
        for (String l : text.toString().split("\r\n|\r|\n", -1)) {
            lines.add(l);
        }
        while (!lines.isEmpty() && lines.get(lines.size() - 1).isEmpty()) {
            lines.remove(lines.size() - 1);
        }
        return lines;
    }

    private int endOfUpload() {
        for (int i = 0; i < pending.length(); i++) {
            char c = pending.charAt(i);
            if (c == 26 || c == '\\') {
                return i;
            }
        }
        return -1;
    }

    /** Sends raw bytes that need no reply: Ctrl-R Ctrl-V is sent through {@link #query} instead. */
    private void write(String command, String text) throws IOException {
        commands++;
        if (TRACE) {
            System.err.println("gcnc run > " + printable(text));
        }
        try {
            link.write(text.getBytes(StandardCharsets.ISO_8859_1));
        } catch (IOException e) {
            throw new LinkFault(LinkFault.Kind.DROPPED, command, e.getMessage() == null ? "write failed" : e.getMessage());
        }
    }

    private Reply exchange(String command, boolean data) throws IOException {
        write(command, command + "\r");
        return readReply(command, data, System.currentTimeMillis() + timeoutMs);
    }

    /**
     * The next reply: text up to a {@code :} or {@code ?} standing at the start of the reply or of
     * a line (a colon inside data, as in a program's text, is not an end).
     */
    private Reply readReply(String command, boolean data, long deadline) throws IOException {
        while (true) {
            for (int i = 0; i < pending.length(); i++) {
                char c = pending.charAt(i);
                boolean atLineStart = i == 0 || pending.charAt(i - 1) == '\n';
                if ((c == ':' || c == '?') && atLineStart) {
                    String text = pending.substring(0, i);
                    pending.delete(0, i + 1);
                    String body = text.strip();
                    if (TRACE) {
                        System.err.println("gcnc run < " + printable(text) + c);
                    }
                    if (!data && !body.isEmpty()) {
                        throw new LinkFault(LinkFault.Kind.GARBAGE, command, "'" + printable(text) + "' where only : or ? belongs");
                    }
                    return new Reply(c == ':', body);
                }
            }
            fill(command, deadline);
        }
    }

    /** The deadline whose one look past it {@link #fill} has taken (0: none yet): fill's own state. */
    private long lookedPast;

    /**
     * Reads more bytes into {@link #pending}; unsolicited ones (high bit) go to their own stream. Past
     * the deadline the link is still read once (a wait of 1 ms) before the reply is called late: a
     * host that was not scheduled for a while (a busy shop PC, a long pause of its own) finds the
     * reply that came in time waiting for it, and does not stop a run for it.
     */
    private void fill(String command, long deadline) throws IOException {
        long left = deadline - System.currentTimeMillis();
        if (left <= 0 && lookedPast == deadline) {
            throw late(command); // the one look past the deadline was taken: a stream of bytes does not keep it open
        }
        if (left <= 0) {
            lookedPast = deadline;
        }
        int n;
        try {
            n = link.read(buffer, (int) Math.max(1, Math.min(left, 200)));
        } catch (IOException e) {
            throw new LinkFault(LinkFault.Kind.DROPPED, command, e.getMessage() == null ? "read failed" : e.getMessage());
        }
        if (n < 0) {
            throw new LinkFault(LinkFault.Kind.DROPPED, command, "the link closed");
        }
        if (n == 0 && left <= 0) {
            throw late(command);
        }
        for (int i = 0; i < n; i++) {
            int b = buffer[i] & 0xff;
            if (b >= 0x80) {
                unsolicitedByte(b & 0x7f);
            } else if (b >= 0x20 && b < 0x7f || b == '\r' || b == '\n' || b == 26) {
                pending.append((char) b);
            } else {
                pending.append((char) b);
                throw new LinkFault(LinkFault.Kind.GARBAGE, command, "'" + printable(pending.toString()) + "'");
            }
        }
    }

    private LinkFault late(String command) {
        return new LinkFault(LinkFault.Kind.TIMEOUT, command, pending.length() == 0 ? "nothing"
                : "'" + printable(pending.toString()) + "' and no : or ?");
    }

    private void unsolicitedByte(int c) {
        if (c == '\n' || c == '\r') {
            if (unsolicitedLine.length() > 0) {
                unsolicited.accept(unsolicitedLine.toString());
                unsolicitedLine.setLength(0);
            }
        } else if (unsolicitedLine.length() < 200) {
            unsolicitedLine.append((char) c);
        }
    }

    /** Text from the controller as a message can show it: control bytes as \xNN, at most 60 characters. */
    public static String printable(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length() && b.length() < 60; i++) {
            char c = s.charAt(i);
            if (c == '\r') {
                b.append("\\r");
            } else if (c == '\n') {
                b.append("\\n");
            } else if (c < 0x20 || c >= 0x7f) {
                b.append(String.format("\\x%02x", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }

    @Override
    public void close() {
        link.close();
    }
}
