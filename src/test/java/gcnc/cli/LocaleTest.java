package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** gcnc in the C locale of a container or CI runner, with a program whose name is not ASCII. */
class LocaleTest {
    record Run(int status, String out) {
    }

    private static Run run(List<String> command, Map<String, String> env) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().keySet().removeIf(k -> k.startsWith("LC_") || k.equals("LANG"));
        pb.environment().putAll(env);
        Process p = pb.start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS));
        return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8));
    }

    private static Path accented() throws IOException {
        // The test JVM itself must be able to pass the name on (it runs in the build's locale).
        assumeTrue("UTF-8".equalsIgnoreCase(System.getProperty("sun.jnu.encoding")), "the test JVM's locale is not UTF-8");
        Path p = Files.createTempDirectory("gcnc-locale").resolve("pièce ñ.nc");
        Files.writeString(p, Files.readString(Path.of("samples/turning.nc")));
        return p;
    }

    @Test
    void theLauncherChecksANonAsciiNameInTheCLocale() throws Exception {
        Path p = accented();
        Run r = run(List.of("sh", "scripts/gcnc", "check", "--lang", "es", p.toString()),
                Map.of("LANG", "C", "GCNC_CLASSPATH", System.getProperty("java.class.path")));
        assertEquals(0, r.status(), r.out());
        assertTrue(r.out().contains(p + ": 13 bloques, sin errores"), r.out());
    }

    /** Without the launcher Java cannot take the name; the user gets a reason and a way out, not a stack trace. */
    @Test
    void plainJavaInTheCLocaleSaysWhatToDo() throws Exception {
        Path p = accented();
        String javaCommand = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Run r = run(List.of(javaCommand, "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main", "check", p.toString()),
                Map.of("LC_ALL", "C"));
        assertEquals(2, r.status(), r.out());
        assertTrue(r.out().contains("cannot be a file name"), r.out());
        assertTrue(r.out().contains("LC_ALL=C.UTF-8"), r.out());
        assertFalse(r.out().contains("Exception"), r.out());
    }
}
