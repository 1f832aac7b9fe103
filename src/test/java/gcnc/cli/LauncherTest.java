package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The gcnc command as a user installs it: the launcher reached through a symbolic link on the PATH
 * (it must find its jar from where it really is), and scripts/install.sh into a prefix (jar,
 * class-data archive, launcher). The build makes build/libs/gcnc.jar before the tests run.
 */
class LauncherTest {
    record Run(int status, String out) {
    }

    private static Run run(List<String> command, Map<String, String> env) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().remove("GCNC_JAR");
        pb.environment().remove("GCNC_JAVA_OPTS");
        pb.environment().putAll(env);
        Process p = pb.start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS));
        return new Run(p.exitValue(), new String(out, StandardCharsets.UTF_8));
    }

    private static final String BISHOP = Path.of("samples/bishop.nc").toAbsolutePath().toString();

    @Test
    void theRepositorysLauncherWorksThroughALinkFromAnotherFolder() throws Exception {
        Path bin = Files.createTempDirectory("gcnc-bin");
        Path link = Files.createSymbolicLink(bin.resolve("gcnc"), Path.of("scripts/gcnc").toAbsolutePath());
        Run r = run(List.of(link.toString(), "check", BISHOP, "--machine", "thesis-2004"), Map.of());
        assertEquals(0, r.status(), r.out());
        assertEquals(BISHOP + ": 59 blocks, no errors\n", r.out());
    }

    @Test
    void theInstalledCommandRunsWithItsArchiveAndThroughALink() throws Exception {
        Path tmp = Files.createTempDirectory("gcnc-install");
        Path prefix = tmp.resolve("prefix");
        Run install = run(List.of("bash", "scripts/install.sh", "--prefix", prefix.toString()), Map.of());
        assertEquals(0, install.status(), install.out());
        assertTrue(Files.isRegularFile(prefix.resolve("lib/gcnc/gcnc.jar")), install.out());
        assertTrue(Files.size(prefix.resolve("lib/gcnc/gcnc.jsa")) > 0, install.out());
        // the resident checker's client, which the launcher finds beside the jar (ResidentCheckerTest)
        assertTrue(Files.isRegularFile(prefix.resolve("lib/gcnc/gcnc-client.py")), install.out());
        Path link = Files.createSymbolicLink(tmp.resolve("gcnc"), prefix.resolve("bin/gcnc"));
        Run r = run(List.of(link.toString(), "check", BISHOP, "--machine", "thesis-2004"), Map.of());
        assertEquals(0, r.status(), r.out());
        // The archive's own messages never reach the user, even when it no longer matches the jar.
        assertEquals(BISHOP + ": 59 blocks, no errors\n", r.out());
        Files.setLastModifiedTime(prefix.resolve("lib/gcnc/gcnc.jar"), java.nio.file.attribute.FileTime.fromMillis(0));
        Run stale = run(List.of(link.toString(), "check", BISHOP, "--machine", "thesis-2004"), Map.of());
        assertEquals(0, stale.status(), stale.out());
        assertEquals(BISHOP + ": 59 blocks, no errors\n", stale.out());
    }

    @Test
    void aMissingJarIsAClearMessageNotAJavaError() throws Exception {
        Path tmp = Files.createTempDirectory("gcnc-install");
        Run r = run(List.of("sh", "scripts/gcnc", "--version"), Map.of("GCNC_JAR", tmp.resolve("none.jar").toString()));
        assertEquals(2, r.status(), r.out());
        assertTrue(r.out().startsWith("gcnc: no " + tmp.resolve("none.jar")), r.out());
    }
}
