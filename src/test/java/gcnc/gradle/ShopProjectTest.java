package gcnc.gradle;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * The Gradle plugin end to end, as a shop meets it (docs/gradle-plugin.md): scripts/shop-project-test.sh
 * publishes the library and plugin to a throwaway Maven local repository and builds copies of
 * samples/shop-project with them. The script checks the outcomes too; this test reads Gradle's own output of each stage,
 * so that a script that stopped checking would not pass it (stage stock: gcnc { stock }). Twelve Gradle builds through one Gradle daemon
 * (about 30 s at load 10 for the first six; the four of stage library, a shop's library through a
 * build cache, add about 25 s).
 */
class ShopProjectTest {
    private static final String FAULT = "src/main/gcode/o1299-faulty.gcode:6:1: error[E051]";
    private static final String WARNED = java.util.regex.Pattern.quote("o1201-pin.gcode:10:1: warning[E646]");

    @Test
    void theSampleBuildsIsUpToDateTheSecondTimeAFaultyProgramFailsAtItsLineAndALibraryIsJudgedIncrementally() throws Exception {
        Assumptions.assumeTrue(onPath("gradle"), "needs gradle on PATH; absent here");
        List<String> command = List.of("bash", "scripts/shop-project-test.sh");
        Path log = Files.createTempFile("gcnc-shop", ".log");
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
            if (!p.waitFor(10, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                fail("scripts/shop-project-test.sh took more than 10 minutes:\n" + Files.readString(log));
            }
            String output = Files.readString(log, StandardCharsets.UTF_8);
            Map<String, String> stage = stages(output);
            assertAll(output,
                    () -> assertTrue(stage.getOrDefault("clean", "").contains("BUILD SUCCESSFUL"), "the clean build passes"),
                    () -> assertTrue(stage.getOrDefault("again", "").contains(":gcncCheck UP-TO-DATE"), "gcncCheck up to date"),
                    () -> assertTrue(stage.getOrDefault("again", "").contains(":gcncCompile UP-TO-DATE"), "gcncCompile up to date"),
                    () -> assertTrue(stage.getOrDefault("again", "").contains(":gcncSimulate UP-TO-DATE"), "gcncSimulate up to date"),
                    () -> assertTrue(stage.getOrDefault("faulty", "").contains("BUILD FAILED"), "the faulty build fails"),
                    () -> assertTrue(stage.getOrDefault("faulty", "").contains(FAULT), "at " + FAULT),
                    // three tasks judge the warned program; Gradle's log shows its warning once (issue 34)
                    () -> assertEquals(1, stage.getOrDefault("warned", "").split(WARNED, -1).length - 1,
                            "the warning " + WARNED + " printed once"),
                    () -> assertTrue(stage.getOrDefault("stock", "").contains(
                            "o1205-inch.gcode: stock 1.75,4,2 read in inches (G20 at line 2)"),
                            "gcnc { stock } without units is read in the program's inches"),
                    () -> assertTrue(stage.getOrDefault("stock", "").contains(
                            "gcnc { stock }: the bore 65 must be smaller than the diameter 65"),
                            "a bad gcnc { stock } fails with the command line's message"),
                    () -> assertTrue(stage.getOrDefault("library", "").contains(
                            "gcncCheck: judged again: src/main/gcode/ops/O9010.nc, src/main/gcode/ops/o1204-bushing.gcode\n"),
                            "an edit of a called file judges it and its caller again, no other program"),
                    () -> assertTrue(stage.getOrDefault("library", "").contains(":gcncCheck FROM-CACHE"),
                            "a second clone takes gcncCheck from the build cache"),
                    () -> assertTrue(stage.getOrDefault("library", "").contains(":gcncCompile FROM-CACHE"),
                            "a second clone takes gcncCompile from the build cache"),
                    () -> assertEquals(0, p.exitValue(), "the script's own verdict"));
        } finally {
            Files.deleteIfExists(log);
        }
    }

    /** The script's output cut at its "== stage NAME" lines. */
    private static Map<String, String> stages(String output) {
        Map<String, String> stages = new LinkedHashMap<>();
        String name = "";
        StringBuilder text = new StringBuilder();
        for (String line : output.split("\n", -1)) {
            if (line.startsWith("== stage ")) {
                stages.put(name, text.toString());
                name = line.substring("== stage ".length()).strip();
                text.setLength(0);
            } else {
                text.append(line).append('\n');
            }
        }
        stages.put(name, text.toString());
        return stages;
    }

    private static boolean onPath(String program) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String dir : path.split(File.pathSeparator)) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, program))) {
                return true;
            }
        }
        return false;
    }
}
