package gcnc.cli;

import gcnc.diag.Code;
import gcnc.send.Link;
import gcnc.send.RunFault;
import gcnc.send.TcpLink;
import java.io.IOException;
import picocli.CommandLine.Option;

/**
 * How a command reaches a real Galil ({@code gcnc run}, {@code gcnc controller probe}): a serial
 * device ({@code --port DEV}, opened at {@code --baud N} with or without the hardware handshake) or
 * Ethernet ({@code --tcp HOST[:PORT]}), exactly one of them ({@link Where}, the commands' argument
 * group: picocli lists a group's options twice in the help when a mixin holds it). This mixin holds the
 * serial settings and how long a reply may take. The descriptions' Spanish are the commands' own keys
 * (Help_es.properties: {@code gcnc.run.baud}, {@code gcnc.controller.probe.baud}).
 */
final class ControllerTarget {
    /** The one way to the controller: {@code @ArgGroup(exclusive = true, multiplicity = "1")} in each command. */
    static final class Where {
        @Option(names = "--port", paramLabel = "DEV", required = true, description = "Serial device of the controller (/dev/ttyUSB0).")
        String port;

        @Option(names = "--tcp", paramLabel = "HOST[:PORT]", required = true, description = "Ethernet: the controller's address (port 23 unless given).")
        String tcp;
    }

    @Option(names = "--baud", paramLabel = "N", defaultValue = "115200", description = "Serial speed (default: ${DEFAULT-VALUE}).")
    int baud;

    @Option(names = "--handshake", paramLabel = "hardware|none", defaultValue = "hardware",
            description = "Serial flow control (default: ${DEFAULT-VALUE}, as Galil's own library).")
    String handshake;

    @Option(names = "--timeout", paramLabel = "MS", defaultValue = "2000",
            description = "How long to wait for each reply (default: ${DEFAULT-VALUE} ms).")
    int timeoutMs;

    /**
     * The link {@code where} names: the serial device opened at {@code --baud} with {@code --handshake},
     * or Ethernet; E817 when the address cannot be reached.
     */
    Link open(Where where) throws RunFault {
        if (where.port != null) {
            return SerialLink.open(where.port, baud, !handshake.equals("none"));
        }
        try {
            return TcpLink.open(where.tcp, timeoutMs);
        } catch (IOException e) {
            throw new RunFault(Code.E817_NO_CONNECTION, 0, false, where.tcp,
                    e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage());
        }
    }
}
