package gcnc;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** File helpers the tests share. */
public final class TestFiles {
    private TestFiles() {
    }

    /**
     * The second lane of a test run. The classes that spend most of their time waiting rather than
     * computing in the test JVM are marked {@code @Execution(CONCURRENT) @ResourceLock(SECOND_LANE)}:
     * those that wait for the virtual Galil's real-time motion (gcnc run, the studio's Run endpoints,
     * the controller's links) or for programs of their own (child JVMs under a small heap, the
     * resident checker's cold runs, the shop project's Gradle builds). The test JVM runs them one
     * after another, each class's tests in order, beside all the other classes, which run one at a
     * time as before (build.gradle's junitPlatform: two threads). A class that changes what the whole
     * JVM shares (a system property, System.out) must not go in this lane; a class that looks at it
     * takes the lock alone, {@code @ResourceLock(SECOND_LANE)}, and then runs while nothing of this
     * lane does (OutputSafetyTest: the temporary files gcnc.output.TempFiles still holds for the JVM).
     * {@code gradle junitPlatformTest -PtestSequential} runs every class one at a time.
     */
    public static final String SECOND_LANE = "gcnc.second-lane";

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
