package gcnc.studio;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import java.util.List;
import java.util.Set;

/**
 * The controller a run goes to, as the Run screen names it: the studio's own virtual Galil, a
 * controller's Ethernet command port ({@code gcnc run --tcp HOST[:PORT]}) or a serial port
 * ({@code gcnc run --port DEV --baud N --handshake hardware|none}). Each is checked for its shape
 * here (400 when malformed); whether it answers is the run's business (E815-E817).
 */
sealed interface RunTarget {
    /** The virtual Galil the studio starts on a loopback port (gcnc.controller). */
    record Virtual() implements RunTarget {
        @Override
        public String shown() {
            return "the studio's virtual controller";
        }
    }

    /** A controller's Ethernet command port, {@code HOST[:PORT]} (port 23 unless given). */
    record Tcp(String address) implements RunTarget {
        @Override
        public String shown() {
            return address;
        }
    }

    /** A serial port: the device, its speed and its flow control. */
    record Serial(String device, int baud, boolean hardwareHandshake) implements RunTarget {
        @Override
        public String shown() {
            return device + " at " + baud + " baud" + (hardwareHandshake ? "" : ", no handshake");
        }
    }

    /** How the run screen and its answers name the target. */
    String shown();

    /** The serial speeds a Galil offers (its RS-232 ports and the USB bridges), as jSerialComm takes them. */
    Set<Integer> BAUDS = Set.of(9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600);

    /**
     * The {@code "target"} member of an arm request: {@code {"kind": "virtual"}},
     * {@code {"kind": "tcp", "address": "10.0.0.5:23"}} or
     * {@code {"kind": "serial", "device": "/dev/ttyUSB0", "baud": 115200, "handshake": "hardware"}}.
     */
    static RunTarget of(JsonElement e) throws Http.Fail {
        if (e == null || !e.isJsonObject()) {
            throw new Http.Fail(400, "the request needs \"target\": {\"kind\": \"virtual\" | \"tcp\" | \"serial\", ...}");
        }
        JsonObject o = e.getAsJsonObject();
        String kind = Http.required(o, "kind");
        return switch (kind) {
            case "virtual" -> new Virtual();
            case "tcp" -> tcp(Http.required(o, "address"));
            case "serial" -> serial(o);
            default -> throw new Http.Fail(400, "\"kind\" is virtual, tcp or serial, not " + Workspace.shown(kind));
        };
    }

    private static Tcp tcp(String address) throws Http.Fail {
        // a host name or IPv4 address and an optional port: what TcpLink opens (no IPv6 literal there)
        if (!address.matches("[A-Za-z0-9](?:[A-Za-z0-9.-]{0,252})(?::[0-9]{1,5})?")) {
            throw new Http.Fail(400, "\"address\" is HOST or HOST:PORT (a name or an IPv4 address), not " + Workspace.shown(address));
        }
        int colon = address.indexOf(':');
        if (colon > 0) {
            int port = Integer.parseInt(address.substring(colon + 1));
            if (port < 1 || port > 65535) {
                throw new Http.Fail(400, "the port of \"address\" is from 1 to 65535");
            }
        }
        return new Tcp(address);
    }

    private static Serial serial(JsonObject o) throws Http.Fail {
        String device = Http.required(o, "device");
        // a device is named by an absolute path, never one that climbs (..) or carries control characters
        if (device.length() > 200 || !device.startsWith("/") || device.contains("/../") || device.endsWith("/..")
                || device.chars().anyMatch(c -> c < 0x20 || c == 0x7f)) {
            throw new Http.Fail(400, "\"device\" is the absolute path of a serial device (/dev/ttyUSB0), not "
                    + Workspace.shown(device));
        }
        int baud = o.has("baud") ? Http.integer(o, "baud", 1, 10_000_000) : 115200;
        if (!BAUDS.contains(baud)) {
            throw new Http.Fail(400, "\"baud\" is one of " + BAUDS.stream().sorted().toList());
        }
        String handshake = Http.string(o, "handshake");
        if (handshake != null && !List.of("hardware", "none").contains(handshake)) {
            throw new Http.Fail(400, "\"handshake\" is hardware or none");
        }
        return new Serial(device, baud, !"none".equals(handshake));
    }
}
