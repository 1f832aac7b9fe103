package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.ErrorMessages;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;
import picocli.CommandLine.Model.ArgSpec;
import picocli.CommandLine.Model.CommandSpec;

/** --lang es, or a Spanish locale, turns the usage help of every command Spanish: issue 11. */
class SpanishHelpTest {
    private static final Map<String, String> SPANISH_LOCALE = Map.of("LANG", "es_ES.UTF-8");
    private static final Map<String, String> C_LOCALE = Map.of("LANG", "C");

    /** Picocli's own English, which a Spanish help must not show. */
    private static final List<String> PICOCLI_ENGLISH = List.of("Usage:", "Commands:", "Show this help", "Print version",
            "Exit status:", "Display help information", "When no COMMAND", "Show usage help", "The COMMAND to display",
            "(default:", "Did you mean", "Try 'gcnc");

    /** Every command, as the words after gcnc: [], [check], ..., [machines, show], [help]. */
    private static List<List<String>> commands() {
        List<List<String>> all = new ArrayList<>();
        walk(Main.commandLine(new Main.Streams(System.in, System.out), ErrorMessages.Lang.EN), new ArrayList<>(), all);
        return all;
    }

    private static void walk(CommandLine cl, List<String> path, List<List<String>> all) {
        all.add(List.copyOf(path));
        for (Map.Entry<String, CommandLine> sub : cl.getSubcommands().entrySet()) {
            path.add(sub.getKey());
            walk(sub.getValue(), path, all);
            path.remove(path.size() - 1);
        }
    }

    private static CommandSpec spec(ErrorMessages.Lang lang, List<String> path) {
        CommandLine cl = Main.commandLine(new Main.Streams(System.in, System.out), lang);
        for (String name : path) {
            cl = cl.getSubcommands().get(name);
        }
        return cl.getCommandSpec();
    }

    private static String[] args(List<String> path, String... more) {
        List<String> a = new ArrayList<>(path);
        a.addAll(Arrays.asList(more));
        return a.toArray(new String[0]);
    }

    /** What the help of {@code path} says; `help` itself shows its help through `help help`. */
    private static String help(Map<String, String> env, List<String> before, List<String> path) {
        List<String> a = new ArrayList<>(before);
        if (path.equals(List.of("help"))) {
            a.addAll(List.of("help", "help"));
        } else {
            a.addAll(path);
            a.add("--help");
        }
        CliTest.Run r = CliTest.gcnc(env, a.toArray(new String[0]));
        assertEquals(0, r.status(), a + "\n" + r.err());
        return r.out();
    }

    /** A line of a description that is a command to type, the same in every language. */
    private static boolean isShellCommand(String line) {
        return line.startsWith("  gcnc ");
    }

    private static String flat(String text) {
        return text.replaceAll("\\s+", " ");
    }

    @Test
    void everyDescriptionOfEveryCommandIsSpanish() {
        for (List<String> path : commands()) {
            CommandSpec en = spec(ErrorMessages.Lang.EN, path);
            CommandSpec es = spec(ErrorMessages.Lang.ES, path);
            String where = "gcnc " + String.join(" ", path);
            List<String> enArgs = new ArrayList<>();
            List<String> esArgs = new ArrayList<>();
            for (ArgSpec a : en.args()) {
                enArgs.add(String.join(" ", a.description()));
            }
            for (ArgSpec a : es.args()) {
                esArgs.add(String.join(" ", a.description()));
            }
            assertEquals(enArgs.size(), esArgs.size(), where);
            for (int i = 0; i < enArgs.size(); i++) {
                if (en.args().get(i).hidden()) {
                    continue;
                }
                assertNotEquals(enArgs.get(i), esArgs.get(i), where + " " + en.args().get(i));
                assertFalse(esArgs.get(i).isBlank(), where + " " + en.args().get(i));
            }
            String[] enText = en.usageMessage().description();
            String[] esText = es.usageMessage().description();
            String[] enHeader = en.usageMessage().header();
            assertTrue(enText.length + enHeader.length > 0, where);
            assertEquals(enText.length, esText.length, where);
            for (int i = 0; i < enText.length; i++) {
                if (!isShellCommand(enText[i])) {
                    assertNotEquals(enText[i], esText[i], where);
                }
            }
            for (int i = 0; i < enHeader.length; i++) {
                assertNotEquals(enHeader[i], es.usageMessage().header()[i], where);
            }
            Map<String, String> enCodes = en.usageMessage().exitCodeList();
            Map<String, String> esCodes = es.usageMessage().exitCodeList();
            assertEquals(enCodes.keySet(), esCodes.keySet(), where);
            for (String code : enCodes.keySet()) {
                assertNotEquals(enCodes.get(code), esCodes.get(code), where + " exit status " + code);
            }
        }
    }

    @Test
    void theHelpTextsShowNoEnglish() {
        for (List<String> path : commands()) {
            CommandSpec en = spec(ErrorMessages.Lang.EN, path);
            String english = help(C_LOCALE, List.of(), path);
            for (String[] how : new String[][] {{"--lang", "es"}, {"--lang=es"}, {"--lang=ES"}}) {
                for (String spanish : new String[] {help(C_LOCALE, List.of(how), path), help(SPANISH_LOCALE, List.of(), path)}) {
                    String where = String.join(" ", how) + " gcnc " + String.join(" ", path) + "\n" + spanish;
                    assertNotEquals(english, spanish, where);
                    for (String phrase : PICOCLI_ENGLISH) {
                        assertFalse(spanish.contains(phrase), phrase + " in " + where);
                    }
                    for (ArgSpec a : en.args()) {
                        String description = String.join(" ", a.description());
                        if (!a.hidden() && description.length() > 12) {
                            assertFalse(flat(spanish).contains(flat(description)), description + " in " + where);
                        }
                    }
                    for (String line : en.usageMessage().description()) {
                        assertFalse(!isShellCommand(line) && flat(spanish).contains(flat(line).trim()), line + " in " + where);
                    }
                }
            }
            // a command's own --lang after it works as well
            if (en.findOption("--lang") != null && !path.isEmpty()) {
                String own = CliTest.gcnc(C_LOCALE, args(path, "--lang", "es", "--help")).out();
                assertTrue(own.startsWith("Uso: gcnc " + String.join(" ", path)), own);
            }
        }
        String top = help(SPANISH_LOCALE, List.of(), List.of());
        assertTrue(top.startsWith("Uso: gcnc [-hV] [COMMAND]\n"), top);
        assertTrue(top.contains("Comandos:\n"), top);
        assertTrue(top.contains("Códigos de salida:\n"), top);
        assertTrue(top.contains("  help        Muestra la ayuda del comando indicado."), top);
        String check = help(SPANISH_LOCALE, List.of(), List.of("check"));
        assertTrue(check.contains("-h, --help                Muestra esta ayuda y termina."), check);
        assertTrue(check.contains("(por omisión: generic)"), check);
    }

    /** In English nothing changes: no bundle, the annotations' text, even in a Spanish locale with --lang en. */
    @Test
    void theEnglishHelpIsTheAnnotationsText() {
        assertNull(HelpLanguage.bundle(ErrorMessages.Lang.EN));
        for (List<String> path : commands()) {
            String english = help(C_LOCALE, List.of(), path);
            assertEquals(english, help(SPANISH_LOCALE, List.of("--lang", "en"), path), "gcnc " + path);
            assertEquals(english, help(Map.of(), List.of(), path), "gcnc " + path);
            assertTrue(english.startsWith(path.equals(List.of("help")) ? "Display help" : "Usage: gcnc"), english);
            assertFalse(english.contains("--lang=en|es          Idioma"), english);
        }
        String top = help(C_LOCALE, List.of(), List.of());
        assertTrue(top.startsWith("Usage: gcnc [-hV] [COMMAND]\nChecks lathe G-code completely"), top);
        assertFalse(top.contains("--lang"), "the top command's --lang is hidden\n" + top);
    }

    @Test
    void usageErrorsInSpanish() {
        CliTest.Run command = CliTest.gcnc(SPANISH_LOCALE, "chek");
        assertEquals(2, command.status());
        assertEquals("gcnc: argumento que sobra en la posición 0: 'chek'\n"
                + "¿Quiso decir gcnc check, gcnc help o gcnc sheet?\n"
                + "Pruebe 'gcnc --help' o 'gcnc help <comando>'.\n", command.err());
        CliTest.Run sub = CliTest.gcnc(C_LOCALE, "--lang", "es", "machines", "shwo");
        assertTrue(sub.err().contains("¿Quiso decir gcnc machines show?"), sub.err());
        CliTest.Run option = CliTest.gcnc(C_LOCALE, "check", "--lang", "es", "--formt", "json", "x.nc");
        assertEquals(2, option.status());
        assertTrue(option.err().startsWith("gcnc: opción desconocida: '--formt'\nOpciones parecidas: --format"), option.err());
        CliTest.Run value = CliTest.gcnc(SPANISH_LOCALE, "check", "--format", "xml", "x.nc");
        assertTrue(value.err().startsWith("gcnc: valor no válido para la opción '--format'") && value.err().contains("se esperaba uno de"),
                value.err());
        CliTest.Run missing = CliTest.gcnc(SPANISH_LOCALE, "check");
        assertTrue(missing.err().startsWith("gcnc: falta un parámetro obligatorio: 'FILE'\n"), missing.err());
        CliTest.Run none = CliTest.gcnc(SPANISH_LOCALE);
        assertTrue(none.err().startsWith("gcnc: indique un comando: check, compile"), none.err());
        for (CliTest.Run r : List.of(command, sub, option, value, missing, none)) {
            assertEquals(2, r.status(), r.err());
            for (String phrase : PICOCLI_ENGLISH) {
                assertFalse(r.err().contains(phrase), phrase + " in " + r.err());
            }
        }
    }

    @Test
    void usageErrorsInEnglishAsBefore() {
        CliTest.Run command = CliTest.gcnc(C_LOCALE, "chek");
        assertEquals("gcnc: Unmatched argument at index 0: 'chek'\n"
                + "Did you mean: gcnc check or gcnc help or gcnc sheet?\n"
                + "Try 'gcnc --help' or 'gcnc help <command>'.\n", command.err());
        CliTest.Run option = CliTest.gcnc(SPANISH_LOCALE, "check", "--lang", "en", "--formt", "json", "x.nc");
        assertTrue(option.err().startsWith("gcnc: Unknown option: '--formt'\nPossible solutions: --format"), option.err());
    }

    /** A --lang before the command is the command's language for its messages too. */
    @Test
    void langBeforeTheCommandCountsForItsMessages() {
        CliTest.Run r = CliTest.gcnc("--lang", "es", "check", "samples/turning.nc");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("13 bloques, sin errores"), r.out());
        CliTest.Run own = CliTest.gcnc("--lang", "es", "check", "--lang", "en", "samples/turning.nc");
        assertTrue(own.out().contains("13 blocks, no errors"), own.out());
    }

    @Test
    void theLanguageIsReadBeforeParsing() {
        assertEquals(ErrorMessages.Lang.ES, HelpLanguage.of(new String[] {"check", "--lang", "es"}, C_LOCALE));
        assertEquals(ErrorMessages.Lang.ES, HelpLanguage.of(new String[] {"--lang=Es", "check"}, Map.of()));
        assertEquals(ErrorMessages.Lang.EN, HelpLanguage.of(new String[] {"check", "--lang", "en"}, SPANISH_LOCALE));
        assertEquals(ErrorMessages.Lang.ES, HelpLanguage.of(new String[] {"check", "--lang", "fr"}, SPANISH_LOCALE));
        assertEquals(ErrorMessages.Lang.EN, HelpLanguage.of(new String[] {"check", "--", "--lang", "es"}, C_LOCALE));
        assertEquals(ErrorMessages.Lang.EN, HelpLanguage.of(new String[] {"check", "--lang"}, C_LOCALE));
        assertEquals(ErrorMessages.Lang.ES, HelpLanguage.of(new String[0], Map.of("LC_MESSAGES", "es_AR.UTF-8")));
    }

    @Test
    void theBundlesAreWhatPicocliNeeds() throws Exception {
        Properties base = new Properties();
        Properties es = new Properties();
        try (var a = Main.class.getResourceAsStream("Help.properties");
             var b = Main.class.getResourceAsStream("Help_es.properties")) {
            base.load(new java.io.InputStreamReader(a, StandardCharsets.UTF_8));
            es.load(new java.io.InputStreamReader(b, StandardCharsets.UTF_8));
        }
        assertTrue(base.isEmpty(), "the English is the annotations' text: " + base);
        assertNotNull(HelpLanguage.bundle(ErrorMessages.Lang.ES));
        assertEquals("Uso: ", HelpLanguage.bundle(ErrorMessages.Lang.ES).getString("usage.synopsisHeading"));
        for (String key : es.stringPropertyNames()) {
            String v = es.getProperty(key);
            assertFalse(v.replace("%n", "").replace("%%", "").contains("%"), key + ": a lone % breaks picocli's format");
        }
    }

    /** The real entry point: java gcnc.cli.Main in a Spanish locale, and --lang en in it. */
    @Test
    void theJarInASpanishLocale() throws Exception {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Map<String, String> runs = new LinkedHashMap<>();
        runs.put("Uso: gcnc check", "check --help");
        runs.put("Usage: gcnc check", "check --lang en --help");
        for (Map.Entry<String, String> run : runs.entrySet()) {
            List<String> command = new ArrayList<>(List.of(java, "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main"));
            command.addAll(Arrays.asList(run.getValue().split(" ")));
            ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
            pb.environment().keySet().removeIf(k -> k.startsWith("LC_") || k.equals("LANG"));
            pb.environment().put("LANG", "es_ES.UTF-8");
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertTrue(p.waitFor(120, TimeUnit.SECONDS));
            assertEquals(0, p.exitValue(), out);
            assertTrue(out.startsWith(run.getKey()), out);
        }
    }
}
