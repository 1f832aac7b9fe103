package gcnc.cli;

import gcnc.send.RunFault;
import picocli.CommandLine.Option;

/**
 * How a command reaches a real Galil ({@code gcnc run}, {@code gcnc controller probe}): a serial
 * device ({@code --port DEV}, opened at {@code --baud N} with or without the hardware handshake) or
 * Ethernet ({@code --tcp HOST[:PORT]}), exactly one of them ({@link Where}, the commands' argument
 * group: picocli lists a group's options twice in the help when a mixin holds it). This mixin holds the
 * serial settings. The descriptions' Spanish are the commands' own keys (Help_es.properties:
 * {@code gcnc.run.baud}, {@code gcnc.controller.probe.baud}).
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

    /** The serial {@code device} opened at {@code --baud} with {@code --handshake}. */
    SerialLink open(String device) throws RunFault {
        return SerialLink.open(device, baud, !handshake.equals("none"));
    }
}
