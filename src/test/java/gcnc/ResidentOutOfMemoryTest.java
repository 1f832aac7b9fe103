package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The resident checker out of memory (issue 23): a run whose output had begun (here a program on
 * standard input, which cannot be run again cold) ends as a cold run ends, with E506 on one line and
 * status 2, never a stack trace; and the daemon serves on. Its heap is made small for the test with
 * {@code GCNC_DAEMON_JAVA_OPTS} (8 MiB), too small for the drawing ({@code --svg}) of 60,000 blocks
 * (12 MiB held it once the drawing kept its path within a budget: issue 35).
 */
class ResidentOutOfMemoryTest {
    private static final Path JAR = Path.of("build/libs/gcnc.jar");

    record Run(int status, String out, String err) {
    }

    private static Run run(Path state, Path stdin, String... command) throws Exception {
        Path tmp = Files.createTempDirectory("gcnc-oom-run");
        ProcessBuilder pb = new ProcessBuilder(command).redirectOutput(tmp.resolve("out").toFile())
                .redirectError(tmp.resolve("err").toFile());
        pb.redirectInput(stdin == null ? ProcessBuilder.Redirect.from(new java.io.File("/dev/null"))
                : ProcessBuilder.Redirect.from(stdin.toFile()));
        pb.environment().remove("GCNC_JAR");
        pb.environment().remove("GCNC_JAVA_OPTS");
        pb.environment().put("GCNC_DAEMON_DIR", state.toString());
        pb.environment().put("GCNC_DAEMON_JAVA_OPTS", "-XX:+UseSerialGC -Xmx8m");
        pb.environment().put("LANG", "C.UTF-8");
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), List.of(command).toString());
        return new Run(p.exitValue(), Files.readString(tmp.resolve("out"), StandardCharsets.UTF_8),
                Files.readString(tmp.resolve("err"), StandardCharsets.UTF_8));
    }

    @Test
    void aRunOutOfMemoryInTheDaemonIsE506AndTheDaemonServesOn() throws Exception {
        Path state = Files.createTempDirectory("gcnc-oom-state");
        Path dir = Files.createTempDirectory("gcnc-oom");
        // roughing passes with a radius at each shoulder, cut from the profile's blank: the stock's outline grows
        StringBuilder p = new StringBuilder("O2000\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\nG00 X52. Z2.\n");
        for (int i = 0; i < 12_000; i++) {
            double x = 50 - (i % 150) * 0.25;
            p.append(String.format(java.util.Locale.ROOT, "G00 X%.3f Z2.%nG01 Z-40.5 F120.%nG02 X%.3f Z-41.5 R1.%n"
                    + "G01 X%.3f%nG00 Z2.%n", x, x + 2, x + 4));
        }
        Path program = Files.writeString(dir.resolve("long.nc"), p.append("M05\nM30\n"));
        String jar = JAR.toString();
        assertEquals(0, run(state, null, "java", "-jar", jar, "daemon", "start").status());
        try {
            Run r = run(state, program, "sh", "scripts/gcnc", "simulate", "-", "--svg", dir.resolve("long.svg").toString());
            assertEquals(2, r.status(), r.err());
            assertTrue(r.err().contains("gcnc: error[E506]: out of memory: the Java heap of "), r.err());
            assertEquals(1, r.err().split("E506", -1).length - 1, r.err());
            assertFalse(r.err().contains("Exception") || r.err().contains("\tat "), r.err());
            // the daemon answered (a cold run's 512 MB heap would have drawn it) and is still there
            assertTrue(r.err().matches("(?s).*heap of [6-8] MiB.*"), r.err());
            Run status = run(state, null, "java", "-jar", jar, "daemon", "status");
            assertEquals(0, status.status(), status.out() + status.err());
            assertTrue((status.out() + status.err()).contains("1 runs served"), status.out() + status.err());
        } finally {
            run(state, null, "java", "-jar", jar, "daemon", "stop");
        }
    }
}
