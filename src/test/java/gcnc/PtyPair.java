package gcnc;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A pseudo-terminal pair made by socat (setup.sh installs it): a real serial line between the virtual
 * Galil ({@link #controller}) and what the tests drive as a host ({@link #host}: gcnc run --port,
 * jSerialComm). Closing it stops socat, which ends the line.
 */
public final class PtyPair implements AutoCloseable {
    /** The controller's end and the host's end (links socat makes to its two ptys). */
    public final Path controller;
    public final Path host;
    private final Process socat;

    private PtyPair(Path controller, Path host, Process socat) {
        this.controller = controller;
        this.host = host;
        this.socat = socat;
    }

    /** Is socat on the PATH? The pty tests need it. */
    public static boolean available() {
        for (String d : System.getenv().getOrDefault("PATH", "/usr/bin").split(":")) {
            if (Files.isExecutable(Path.of(d, "socat"))) {
                return true;
            }
        }
        return false;
    }

    /**
     * A pair in {@code dir} ({@code controller<tag>}, {@code host<tag>}, socat's log beside them),
     * returned once both ends exist (up to 5 s).
     */
    public static PtyPair open(Path dir, String tag) throws IOException, InterruptedException {
        Path controller = dir.resolve("controller" + tag);
        Path host = dir.resolve("host" + tag);
        Process socat = new ProcessBuilder("socat", "-d", "-d", "pty,raw,echo=0,link=" + controller,
                "pty,raw,echo=0,link=" + host).redirectErrorStream(true)
                .redirectOutput(dir.resolve("socat" + tag + ".log").toFile()).start();
        long until = System.nanoTime() + 5_000_000_000L;
        while (!(Files.exists(controller) && Files.exists(host)) && System.nanoTime() < until) {
            Thread.sleep(10);
        }
        return new PtyPair(controller, host, socat);
    }

    @Override
    public void close() throws InterruptedException {
        socat.destroy();
        socat.waitFor();
    }
}
