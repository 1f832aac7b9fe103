package gcnc.daemon;

import java.io.DataInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/** A client's request to run a command, as its frames give it, and whether a warm JVM may run it. */
final class Requests {
    private Requests() {
    }

    /** The commands the resident checker runs; any other (help, tables, studio...) runs cold. */
    static final Set<String> COMMANDS = Set.of("check", "compile", "simulate");

    /**
     * @param jar      the jar the client's launcher would run
     * @param cwd      the client's working directory
     * @param env      the client's environment
     * @param argv     the arguments after {@code gcnc}
     * @param console  the client's standard input and output are a terminal (System.console() in a cold JVM)
     * @param stdoutId the device and inode of the client's standard output ("dev:ino"), or null
     * @param stdin    the client sends its standard input (an argument is {@code -})
     */
    record Request(String jar, String cwd, Map<String, String> env, List<String> argv, boolean console,
                   String stdoutId, boolean stdin) {
        /**
         * Whether {@code p} is the client's standard output, as a cold JVM tells by comparing it
         * with /proc/self/fd/1 ({@code gcnc compile p.nc -o log > log}): the same device and inode.
         */
        boolean isStandardOutput(Path p) {
            return stdoutId != null && stdoutId.equals(identity(p));
        }
    }

    static String identity(Path p) {
        try {
            if (!Files.exists(p)) {
                return null;
            }
            return Files.getAttribute(p, "unix:dev") + ":" + Files.getAttribute(p, "unix:ino");
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** Reads the frames of a run request up to {@code G}. */
    static Request read(DataInputStream in) throws IOException {
        String jar = "";
        String cwd = "";
        List<String> env = new ArrayList<>();
        List<String> argv = new ArrayList<>();
        boolean console = false;
        String stdoutId = null;
        boolean stdin = false;
        for (Frames.Frame f = Frames.read(in); f.type() != 'G'; f = Frames.read(in)) {
            switch (f.type()) {
                case 'J' -> jar = f.text();
                case 'C' -> cwd = strict(f.data());
                case 'E' -> env.add(f.text());
                case 'A' -> argv.add(strict(f.data()));
                case 'O' -> console = f.text().equals("1");
                case 'S' -> stdoutId = f.text();
                case 'I' -> stdin = true;
                default -> throw new IOException("unknown frame " + f.type());
            }
        }
        return new Request(jar, cwd, DaemonServer.env(env), List.copyOf(argv), console, stdoutId, stdin);
    }

    /** Stands for a name that is not UTF-8: a cold JVM decodes it its own way, so such a request runs cold. */
    static final String NOT_UTF8 = "\u0000not UTF-8";

    private static String strict(byte[] b) {
        try {
            return java.nio.charset.StandardCharsets.UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(b)).toString();
        } catch (java.nio.charset.CharacterCodingException e) {
            return NOT_UTF8;
        }
    }

    /**
     * Why a warm JVM cannot run {@code r} exactly as a cold one would, or null when it can:
     * <ul>
     * <li>the client runs another jar, or this one was replaced (stale);</li>
     * <li>it runs in another folder: a JVM cannot change its working directory, and every relative
     *     name (the program, -o, --tables, a called O1000.nc, the names messages print) is read
     *     against it;</li>
     * <li>a command other than check, compile and simulate, or help and version (picocli colours
     *     those on a terminal);</li>
     * <li>a name under /dev or /proc ({@code -o /dev/stdout}): those name the server's own
     *     descriptors, not the client's.</li>
     * </ul>
     */
    static String coldReason(Request r, JarIdentity jar, String dir) {
        if (!jar.serves(r.jar())) {
            return "stale: the client runs " + r.jar() + ", the daemon " + jar.path()
                    + (jar.changed() ? " (replaced since it started)" : "");
        }
        if (r.cwd().equals(NOT_UTF8) || r.argv().contains(NOT_UTF8)) {
            return "a name that is not UTF-8";
        }
        if (!sameFolder(r.cwd(), dir)) {
            return "another folder: the daemon serves " + dir;
        }
        String command = null;
        for (int i = 0; i < r.argv().size(); i++) {
            String a = r.argv().get(i);
            if (a.equals("-h") || a.equals("--help") || a.equals("-V") || a.equals("--version")) {
                return "help or version";
            }
            if (a.contains("/dev/") || a.contains("/proc/")) {
                return "a name under /dev or /proc";
            }
            if (command == null) {
                if (a.equals("--lang")) {
                    i++;
                } else if (!a.startsWith("-")) {
                    command = a;
                }
            }
        }
        if (command == null || !COMMANDS.contains(command)) {
            return "not check, compile or simulate";
        }
        return null;
    }

    /** Both are the kernel's working directory (getcwd, symbolic links resolved), so equal strings are the same folder. */
    private static boolean sameFolder(String client, String served) {
        return client.equals(served);
    }
}
