package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** gcnc machines in Spanish: a profile's faults (E400) and the command's own lines. */
class SpanishMachinesTest {
    private static Path withUnknownKey() throws IOException {
        Path p = Files.createTempDirectory("gcnc-es400").resolve("bad.machine");
        Files.writeString(p, Files.readString(Path.of("tables/machines/generic.machine")) + "foo = 1\n");
        return p;
    }

    @Test
    void anUnknownKeyIsSpanishWithLangEs() throws Exception {
        Path p = withUnknownKey();
        CliTest.Run r = CliTest.gcnc("--lang", "es", "machines", "validate", p.toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("clave desconocida 'foo'"), r.err());
        assertFalse(r.err().contains("unknown key"), r.err());
        CliTest.Run en = CliTest.gcnc("machines", "validate", "--lang", "en", p.toString());
        assertTrue(en.err().contains("unknown key 'foo'"), en.err());
    }

    @Test
    void anUnknownKeyIsSpanishWithASpanishLang() throws Exception {
        Path p = withUnknownKey();
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        ProcessBuilder pb = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main",
                "machines", "validate", p.toString()).redirectErrorStream(true);
        pb.environment().keySet().removeIf(k -> k.startsWith("LC_") || k.equals("LANG"));
        pb.environment().put("LANG", "es_ES.UTF-8");
        Process proc = pb.start();
        String out = new String(proc.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(proc.waitFor(120, TimeUnit.SECONDS));
        assertEquals(2, proc.exitValue(), out);
        assertTrue(out.contains("clave desconocida 'foo'"), out);
    }

    @Test
    void theCommandsOwnLinesAreSpanish() {
        CliTest.Run valid = CliTest.gcnc("--lang", "es", "machines", "validate", "tables/machines/haas.machine");
        assertEquals(0, valid.status(), valid.err());
        assertTrue(valid.out().contains("tables/machines/haas.machine: válido (máquina haas, controlador haas)"), valid.out());
        CliTest.Run list = CliTest.gcnc("--lang", "es", "machines");
        assertEquals(0, list.status(), list.err());
        assertTrue(list.out().contains("haas           controlador haas"), list.out());
    }

    /** A user's copy of the tables with a broken phrases.csv: the fault still reads, with gcnc's own phrases. */
    @Test
    void aBrokenPhraseTableIsReportedWithTheBuiltInPhrases() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-es400-tables");
        try (Stream<Path> s = Files.walk(Path.of("tables"))) {
            for (Path f : s.toList()) {
                Path to = dir.resolve(Path.of("tables").relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(to);
                } else {
                    Files.copy(f, to);
                }
            }
        }
        Path phrases = dir.resolve("phrases.csv");
        Files.writeString(phrases, Files.readString(phrases).replaceFirst("\nUNKNOWN_KEY_DOCS,[^\n]*", ""));
        for (String lang : List.of("es", "en")) {
            CliTest.Run r = CliTest.gcnc("--lang", lang, "machines", "validate", "--tables", dir.toString(), "haas");
            assertEquals(2, r.status(), r.err());
            assertTrue(r.err().contains(lang.equals("es") ? "no hay fila para la frase UNKNOWN_KEY_DOCS"
                    : "no row for the phrase UNKNOWN_KEY_DOCS"), r.err());
            assertFalse(r.err().contains("Exception"), r.err());
        }
    }
}
