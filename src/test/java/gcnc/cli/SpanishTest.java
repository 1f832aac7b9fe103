package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.ErrorMessages;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;

/** --lang es (or a Spanish LANG) turns the summaries and the run's warnings Spanish, not only the findings. */
class SpanishTest {
    @Test
    void summariesAndWarningsInSpanish() throws Exception {
        Path p = CliTest.program(Files.readString(Path.of("samples/arcs.nc")));
        CliTest.Run check = CliTest.gcnc("check", p.toString(), "--lang", "es");
        assertTrue(check.out().contains("19 bloques, sin errores"), check.out());
        CliTest.Run compile = CliTest.gcnc("compile", p.toString(), "--lang", "es", "--no-simulate");
        assertTrue(compile.out().contains("19 bloques -> "), compile.out());
        assertTrue(compile.out().contains("líneas, dialecto galil"), compile.out());
        assertTrue(compile.err().contains("aviso: --no-simulate"), compile.err());
        CliTest.Run simulate = CliTest.gcnc("simulate", p.toString(), "--lang", "es");
        assertTrue(simulate.out().contains("simulación: 3 secuencias, 11 segmentos, 0 hallazgos"), simulate.out()); // blended: 11 moves in 3 sequences
    }

    @Test
    void oneAndManyAndNoGrouping() {
        Phrases en = new Phrases(ErrorMessages.Lang.EN);
        assertEquals("1 block", en.count(1, "block"));
        assertEquals("1000000 blocks", en.count(1000000, "block"));
        assertEquals("1 bloque", new Phrases(ErrorMessages.Lang.ES).count(1, "block"));
    }

    @Test
    void theLocaleChoosesWhenLangIsNotGiven() {
        assertEquals(ErrorMessages.Lang.ES, LanguageOption.fromEnvironment(Map.of("LANG", "es_MX.UTF-8")));
        assertEquals(ErrorMessages.Lang.EN, LanguageOption.fromEnvironment(Map.of("LC_ALL", "C", "LANG", "es_ES")));
        assertEquals(ErrorMessages.Lang.ES, LanguageOption.fromEnvironment(Map.of("LC_ALL", "es_ES.UTF-8")));
        assertEquals(ErrorMessages.Lang.EN, LanguageOption.fromEnvironment(Map.of()));
    }

    @Test
    void everyPhraseHasItsSpanish() throws Exception {
        Properties en = new Properties();
        Properties es = new Properties();
        try (var a = Phrases.class.getResourceAsStream("Phrases.properties");
             var b = Phrases.class.getResourceAsStream("Phrases_es.properties")) {
            en.load(new java.io.InputStreamReader(a, java.nio.charset.StandardCharsets.UTF_8));
            es.load(new java.io.InputStreamReader(b, java.nio.charset.StandardCharsets.UTF_8));
        }
        assertEquals(en.keySet(), es.keySet());
    }
}
