package gcnc.controller;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/**
 * One host link (a TCP connection or the pty): splits the bytes into commands and answers each one as a
 * Galil does (command reference and user manual, "Controller response to data"): a command ends at CR or
 * at {@code ;} outside quotes, LF is ignored; an accepted command answers its data, if any, then
 * {@code :}; a rejected one answers {@code ?} (TC1 then says why); an empty line answers {@code :}.
 * After {@code DL} every byte up to the end marker ({@code \}, or ^Z, ^D, ^Q) is program text; a good
 * download answers {@code ::} (one for the end marker, one for DL), a refused one {@code ?}.
 * Unsolicited output (a program's MG) is written between replies, never inside one, and only on the
 * link that is the CF port (COMALL CF: the main serial port unless told).
 *
 * <p>The link is a port: 'S', the main serial port (the pty), which echoes every byte it receives while
 * EO is 1, as a factory unit does from power-up (COMALL EO: "This command is defaulted to EO1"); or an
 * Ethernet handle 'A'..'H', which never echoes ("The ethernet port will not echo commands"; an
 * {@code echo-ethernet} fault makes it echo, as a unit that contradicted the reference would).
 */
final class Connection implements VirtualGalil.Listener {
    private final VirtualGalil controller;
    private final InputStream in;
    private final OutputStream out;
    private final Faults faults;
    private final Closeable link;
    private final char port;

    Connection(VirtualGalil controller, InputStream in, OutputStream out, Faults faults, Closeable link, char port) {
        this.controller = controller;
        this.port = port;
        // bytes are taken one at a time: buffered, so that each is not a system call of its own
        this.in = new java.io.BufferedInputStream(in);
        this.out = out;
        this.faults = faults;
        this.link = link;
    }

    /**
     * Serves the link until the host closes it, it fails, or a disconnect fault closes it; true in the
     * last case.
     */
    boolean serve() {
        controller.addListener(this);
        try {
            return loop();
        } catch (IOException e) {
            return false; // the host went away: nothing to answer
        } finally {
            controller.removeListener(this);
            controller.closeHandle(port);
            try {
                link.close();
            } catch (IOException e) {
                // already closed
            }
        }
    }

    private boolean loop() throws IOException {
        StringBuilder command = new StringBuilder();
        StringBuilder download = null;
        boolean append = false;
        boolean quoted = false;
        boolean lineEmpty = true;
        int b;
        while ((b = in.read()) >= 0) {
            if (faults.received()) {
                // the byte that reaches the count is the last one the controller takes
                link.close();
                return true;
            }
            char ch = (char) (b & 0xFF);
            if (port == 'S' ? controller.echoes() : faults.echoEthernet) {
                echo(b); // the echo comes as the byte arrives, before any reply to it
            }
            if (download != null) {
                if (ch == '\\' || ch == 0x1A || ch == 0x04 || ch == 0x11) {
                    reply(downloaded(download.toString(), append) ? "::" : "?");
                    download = null;
                } else {
                    download.append(ch);
                }
                continue;
            }
            if (ch == '\n') {
                continue;
            }
            if (ch == '"') {
                quoted = !quoted;
            }
            if (ch != '\r' && (ch != ';' || quoted)) {
                command.append(ch);
                continue;
            }
            String st = command.toString().strip();
            command.setLength(0);
            quoted = false;
            boolean wasEmpty = lineEmpty;
            lineEmpty = ch == '\r';
            if (st.isEmpty()) {
                if (ch == '\r' && wasEmpty) {
                    reply(":");
                }
                continue;
            }
            if (isDownload(st)) {
                String args = st.substring(2).strip();
                if (faults.reject()) {
                    reject();
                    continue;
                }
                try {
                    controller.downloadAllowed(args);
                    download = new StringBuilder();
                    append = args.equals("#");
                } catch (GalilException e) {
                    reply("?");
                }
                continue;
            }
            answer(st);
        }
        return false;
    }

    private static boolean isDownload(String st) {
        return st.startsWith("DL") && (st.length() == 2 || st.charAt(2) == ' ' || st.charAt(2) == '#');
    }

    private boolean downloaded(String text, boolean append) {
        try {
            controller.download(text, append);
            return true;
        } catch (GalilException e) {
            return false;
        }
    }

    private void answer(String st) throws IOException {
        if (faults.reject()) {
            reject();
            return;
        }
        String reply;
        try {
            reply = controller.command(st, port) + ":";
        } catch (GalilException e) {
            reply = "?";
        }
        reply(reply);
    }

    private void reject() throws IOException {
        controller.rejected();
        reply("?");
    }

    private void reply(String text) throws IOException {
        if (faults.slowMillis > 0) {
            try {
                Thread.sleep(faults.slowMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        send(text.getBytes(StandardCharsets.ISO_8859_1));
    }

    @Override
    public char port() {
        return port;
    }

    @Override
    public void unsolicited(byte[] bytes) {
        try {
            send(bytes);
        } catch (IOException e) {
            // the reader sees the broken link and ends the connection
        }
    }

    /** One echoed byte: not a reply, so the byte-counting faults do not count it. */
    private synchronized void echo(int b) throws IOException {
        out.write(b);
        out.flush();
    }

    private synchronized void send(byte[] bytes) throws IOException {
        int at = faults.garbageAt(bytes.length);
        if (at < 0) {
            out.write(bytes);
        } else {
            out.write(bytes, 0, at);
            out.write(Faults.GARBAGE);
            out.write(bytes, at, bytes.length - at);
        }
        out.flush();
    }
}
