package gcnc.cli;

import com.fazecast.jSerialComm.SerialPort;
import gcnc.diag.Code;
import gcnc.send.Link;
import gcnc.send.RunFault;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A Galil's RS-232 or USB serial port through jSerialComm (galil-notes.md §3: ptys and socat
 * links open by name; a second open of a held port fails; a vanished peer reads -1). 8 data bits,
 * no parity, one stop bit; hardware handshake unless told (gclib's default).
 */
final class SerialLink implements Link {
    private final String name;
    private final SerialPort port;

    private SerialLink(String name, SerialPort port) {
        this.name = name;
        this.port = port;
    }

    /** Opens {@code device}: E815 when it does not exist, E816 when it cannot be opened (held, no permission). */
    static SerialLink open(String device, int baud, boolean hardwareHandshake) throws RunFault {
        Path p = Path.of(device);
        if (!Files.exists(p)) {
            throw new RunFault(Code.E815_PORT_MISSING, 0, false, device);
        }
        if (!characterDevice(p)) {
            // jSerialComm opened a plain file as a port, and the run wrote its program into it
            throw new RunFault(Code.E865_PORT_NOT_A_DEVICE, 0, false, device);
        }
        if (!Files.isReadable(p) || !Files.isWritable(p)) {
            throw new RunFault(Code.E816_PORT_HELD, 0, false, device, "no permission to read and write it");
        }
        SerialPort port = SerialPort.getCommPort(device);
        port.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        port.setFlowControl(hardwareHandshake ? SerialPort.FLOW_CONTROL_RTS_ENABLED | SerialPort.FLOW_CONTROL_CTS_ENABLED
                : SerialPort.FLOW_CONTROL_DISABLED);
        if (!port.openPort()) {
            int errno = port.getLastErrorCode();
            throw new RunFault(Code.E816_PORT_HELD, 0, false, device,
                    "another program holds it" + (errno != 0 ? ", error " + errno : ""));
        }
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 200, 0);
        return new SerialLink(device, port);
    }

    /** Whether {@code p} is a character device (a tty), by its mode; without one, anything but a file or a folder. */
    static boolean characterDevice(Path p) {
        try {
            int mode = (Integer) Files.getAttribute(p, "unix:mode");
            return (mode & 0170000) == 0020000; // S_IFMT, S_IFCHR
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            return !Files.isRegularFile(p) && !Files.isDirectory(p);
        }
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public boolean serial() {
        return true;
    }

    @Override
    public void write(byte[] bytes) throws IOException {
        int done = 0;
        while (done < bytes.length) {
            int n = port.writeBytes(bytes, bytes.length - done, done);
            if (n <= 0) {
                throw new IOException("the serial port " + name + " refused the write (error " + port.getLastErrorCode() + ")");
            }
            done += n;
        }
    }

    @Override
    public int read(byte[] into, int timeoutMs) throws IOException {
        // the port waits up to 200 ms for a first byte (semi-blocking); the protocol loops to its deadline
        int n = port.readBytes(into, into.length);
        if (n < 0 || n == 0 && port.bytesAvailable() < 0) {
            return -1;
        }
        return n;
    }

    @Override
    public void close() {
        port.closePort();
    }
}
