package gcnc;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** File helpers the tests share. */
public final class TestFiles {
    private TestFiles() {
    }

    /** Copies the folder {@code from} with everything below it into {@code to}. */
    public static void copyTree(Path from, Path to) throws IOException {
        try (var s = Files.walk(from)) {
            for (Path p : s.toList()) {
                Path t = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(t);
                } else {
                    Files.copy(p, t);
                }
            }
        }
    }

    /** A named pipe at {@code p} (mkfifo). */
    public static Path mkfifo(Path p) throws IOException, InterruptedException {
        Process mk = new ProcessBuilder("mkfifo", p.toString()).inheritIO().start();
        if (mk.waitFor() != 0) {
            throw new IOException("mkfifo " + p + " failed");
        }
        return p;
    }
}
