package gcnc.send;

import java.io.IOException;

/**
 * A byte link to a Galil controller: a TCP socket ({@link TcpLink}) or a serial port (the command
 * line's jSerialComm link). The protocol ({@link GalilClient}) sits on top and knows nothing of which.
 */
public interface Link extends AutoCloseable {
    /** What the user named: {@code /dev/ttyUSB0}, {@code 10.0.0.5:23}. */
    String name();

    /**
     * Whether the link is a serial port (RS-232 or USB), which echoes until {@code EO 0} (COMALL EO);
     * an Ethernet handle never echoes and takes {@code CF I} for its unsolicited messages.
     */
    default boolean serial() {
        return false;
    }

    void write(byte[] bytes) throws IOException;

    /**
     * Reads what has arrived, waiting at most {@code timeoutMs} for the first byte.
     *
     * @return the number of bytes read, 0 when nothing came in time, -1 when the link is closed
     *         (the peer went away, the cable was pulled)
     */
    int read(byte[] into, int timeoutMs) throws IOException;

    @Override
    void close();
}
