package gcnc.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * gcnc lsp driven by real editors' clients (docs/editors.md): the pytest-lsp suite in src/test/lsp
 * (pygls's client: open, edit, diagnostics equal to gcnc check's, hover, definition, references,
 * symbols, code actions, .gcnc settings, the simulator's findings, bad input), and Neovim's own
 * client, headless (src/test/lsp/nvim.lua). Both mostly wait for the server's JVMs: lane 3 (build.gradle's `lanes`). Each needs its program: pytest-lsp in the virtual
 * environment setup.sh makes (.venv-lsp), Debian's neovim; without it the test is skipped, saying so.
 */
class LspClientTest {
    private static final Path JAR = Path.of("build/libs/gcnc.jar").toAbsolutePath();

    @Test
    void pytestLspSuitePasses() throws Exception {
        Path python = Path.of(".venv-lsp/bin/python");
        assumeTrue(Files.isExecutable(python), "pytest-lsp is not installed: setup.sh makes .venv-lsp with it");
        Run r = run(List.of(python.toAbsolutePath().toString(), "-m", "pytest", "-q", "-p", "no:cacheprovider"),
                Path.of("src/test/lsp"), 240);
        assertEquals(0, r.status, r.output);
    }

    @Test
    void neovimsOwnClientGetsTheDiagnosticsHoverAndDefinition() throws Exception {
        assumeTrue(onPath("nvim"), "neovim is not installed: setup.sh installs Debian's");
        // Debian 12's Neovim is 0.7: no -l (0.9); the script reads the jar from GCNC_JAR
        Run r = run(List.of("nvim", "--headless", "-u", "NONE", "-c",
                "luafile " + Path.of("src/test/lsp/nvim.lua").toAbsolutePath()), Path.of("."), 120);
        assertEquals(0, r.status, r.output);
        assertEquals(true, r.output.contains("nvim: ok"), r.output);
    }

    private record Run(int status, String output) {
    }

    private static Run run(List<String> command, Path dir, int seconds) throws IOException, InterruptedException {
        Path log = Files.createTempFile("gcnc-lsp-client", ".log");
        try {
            ProcessBuilder pb = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true)
                    .redirectOutput(log.toFile());
            pb.environment().put("GCNC_JAR", JAR.toString());
            Process p = pb.start();
            if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return new Run(-1, "timed out after " + seconds + " s\n" + Files.readString(log, StandardCharsets.UTF_8));
            }
            return new Run(p.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
        } finally {
            Files.deleteIfExists(log);
        }
    }

    private static boolean onPath(String program) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(":")) {
            if (Files.isExecutable(Path.of(dir, program))) {
                return true;
            }
        }
        return false;
    }
}
