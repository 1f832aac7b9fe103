package gcnc.daemon;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

/**
 * Where a running resident checker is found: {@code daemon.state} in {@code $GCNC_DAEMON_DIR}, else
 * {@code $XDG_RUNTIME_DIR/gcnc}, else {@code ~/.cache/gcnc} (the folder made 0700, the file 0600:
 * it holds the token, and only the user may read it). One {@code key=value} a line: the server's
 * pid, port and token, its jar and the folder it serves. scripts/gcnc-client.py reads the same file.
 *
 * @param pid   the server's process
 * @param port  its loopback port
 * @param token what a client must send first (64 hex digits, from SecureRandom)
 * @param jar   the jar it runs (a client running another jar runs cold)
 * @param dir   the working directory it serves
 */
record StateFile(long pid, int port, String token, String jar, String dir) {
    static final String NAME = "daemon.state";

    /** The folder of the state file for this environment. */
    static Path folder(Map<String, String> env) {
        String own = env.get("GCNC_DAEMON_DIR");
        if (own != null && !own.isEmpty()) {
            return Path.of(own);
        }
        String runtime = env.get("XDG_RUNTIME_DIR");
        if (runtime != null && !runtime.isEmpty()) {
            return Path.of(runtime, "gcnc");
        }
        return Path.of(System.getProperty("user.home"), ".cache", "gcnc");
    }

    static Optional<StateFile> read(Path folder) {
        Map<String, String> m = new LinkedHashMap<>();
        try {
            for (String line : Files.readAllLines(folder.resolve(NAME), StandardCharsets.UTF_8)) {
                int eq = line.indexOf('=');
                if (eq > 0) {
                    m.put(line.substring(0, eq), line.substring(eq + 1));
                }
            }
            return Optional.of(new StateFile(Long.parseLong(m.get("pid")), Integer.parseInt(m.get("port")),
                    m.get("token"), m.get("jar"), m.get("dir")));
        } catch (IOException | RuntimeException e) {
            return Optional.empty(); // none, or half of one: no daemon to talk to
        }
    }

    /** Written beside and renamed into place, 0600 from the start: a client never reads half of it. */
    void write(Path folder) throws IOException {
        Files.createDirectories(folder);
        try {
            Files.setPosixFilePermissions(folder, PosixFilePermissions.fromString("rwx------"));
        } catch (UnsupportedOperationException e) {
            // not a POSIX file system: the file's own permissions below still apply where they can
        }
        String text = "pid=" + pid + "\nport=" + port + "\ntoken=" + token + "\njar=" + jar + "\ndir=" + dir + "\n";
        Path temp = Files.createTempFile(folder, ".daemon", ".state",
                PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        Files.writeString(temp, text, StandardCharsets.UTF_8);
        try {
            Files.move(temp, folder.resolve(NAME), StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(temp, folder.resolve(NAME), StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** Removes the state file if it is still this server's (a newer server may have replaced it). */
    void remove(Path folder) {
        Optional<StateFile> now = read(folder);
        if (now.isPresent() && now.get().token().equals(token)) {
            try {
                Files.deleteIfExists(folder.resolve(NAME));
            } catch (IOException e) {
                // a state file left behind names a port nothing answers on: clients run cold
            }
        }
    }
}
