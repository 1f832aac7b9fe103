package gcnc.send;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;

/**
 * Galil's Ethernet command port: a plain TCP socket, port 23 unless told (galil-controller.md
 * §1.7, "TCP port 23 for commands"). Nagle is off: the protocol is one short command, one short
 * reply (Application Note 4413 measures what a delayed packet costs).
 */
public final class TcpLink implements Link {
    /** Galil's command port. */
    public static final int GALIL_PORT = 23;

    private final String name;
    private final Socket socket;
    private final InputStream in;
    private final OutputStream out;

    private TcpLink(String name, Socket socket) throws IOException {
        this.name = name;
        this.socket = socket;
        this.in = socket.getInputStream();
        this.out = socket.getOutputStream();
    }

    /** Connects to {@code HOST[:PORT]} within {@code timeoutMs}. */
    public static TcpLink open(String hostPort, int timeoutMs) throws IOException {
        String host = hostPort;
        int port = GALIL_PORT;
        int colon = hostPort.lastIndexOf(':');
        if (colon > 0 && hostPort.indexOf(':') == colon) {
            host = hostPort.substring(0, colon);
            try {
                port = Integer.parseInt(hostPort.substring(colon + 1));
            } catch (NumberFormatException e) {
                throw new IOException("'" + hostPort.substring(colon + 1) + "' is not a port number");
            }
        }
        Socket s = new Socket();
        try {
            s.connect(new InetSocketAddress(host, port), timeoutMs);
            s.setTcpNoDelay(true);
        } catch (IOException e) {
            s.close();
            throw e;
        }
        return new TcpLink(host + ":" + port, s);
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        out.write(bytes);
        out.flush();
    }

    @Override
    public int read(byte[] into, int timeoutMs) throws IOException {
        socket.setSoTimeout(Math.max(1, timeoutMs));
        try {
            return in.read(into);
        } catch (SocketTimeoutException e) {
            return 0;
        }
    }

    @Override
    public void close() {
        try {
            socket.close();
        } catch (IOException e) {
            // closing a socket that is gone: nothing left to release
        }
    }
}
