package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import gcnc.tables.GalilConformance;
import gcnc.tables.GalilConformance.Row;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * tables/galil_conformance.csv holds gcnc to Galil's documentation (issue 30): every row well formed and
 * pinned by a test class that exists; docs/galil-conformance.md its rendering, never stale; and no command or
 * operand without a row in a golden DMC file or among those the virtual controller accepts (the sender's are
 * gcnc.cli.SenderConformanceTest's). A failure names what is missing: add its row, with the manual's words.
 */
class GalilConformanceTest {
    private static final Path PAGE = Path.of("docs/galil-conformance.md");
    private static final Set<String> KINDS = Set.of("command", "operand", "protocol");
    private static final Set<String> STATUSES = Set.of("fine", "fixing", "silent");

    @Test
    void everyRowIsWellFormedAndNamesATestThatExists() throws IOException {
        List<Row> rows = GalilConformance.rows();
        assertTrue(rows.size() > 50, "the table has its rows");
        Set<String> ids = new HashSet<>();
        Set<String> names = new HashSet<>();
        List<String> faults = new ArrayList<>();
        for (Row r : rows) {
            String at = "galil_conformance.csv:" + r.line() + " (" + r.get("id") + "): ";
            if (!r.get("id").matches("[a-z0-9]+(-[a-z0-9]+)*") || !ids.add(r.get("id"))) {
                faults.add(at + "id is not kebab-case or is used twice");
            }
            if (!names.add(r.get("kind") + " " + r.get("name"))) {
                faults.add(at + "a second row for " + r.get("kind") + " " + r.get("name"));
            }
            if (!KINDS.contains(r.get("kind"))) {
                faults.add(at + "kind is one of " + KINDS);
            }
            if (!STATUSES.contains(r.get("status"))) {
                faults.add(at + "status is one of " + STATUSES);
            }
            if (!Set.of("yes", "no").contains(r.get("probe"))) {
                faults.add(at + "probe is yes or no");
            }
            for (String c : List.of("name", "manual", "source", "gcnc", "models", "test")) {
                if (r.get(c).isBlank()) {
                    faults.add(at + c + " is empty");
                }
            }
            if (!r.get("review").matches("([ABC]\\d{1,2}( [ABC]\\d{1,2})*)?")) {
                faults.add(at + "review names rows such as A1 or B2 C2");
            }
            if (r.get("status").equals("fixing") && r.get("review").isBlank()) {
                faults.add(at + "a row being fixed names the review's row of its misreading");
            }
            String test = r.get("test");
            if (test.equals("pending")) {
                if (!r.get("status").equals("fixing")) {
                    faults.add(at + "only a row being fixed may wait for its test (pending)");
                }
            } else {
                try {
                    Class.forName(test);
                } catch (ClassNotFoundException e) {
                    faults.add(at + "no test class " + test);
                }
            }
        }
        assertEquals(List.of(), faults);
    }

    /** The page is the table's rendering: {@code -PupdateGolden} writes it again after a change to the table. */
    @Test
    void thePageRendersTheTable() throws IOException {
        String page = render(GalilConformance.rows());
        if (Boolean.getBoolean("gcnc.updateGolden")) {
            Files.writeString(PAGE, page);
        }
        assertEquals(page, Files.readString(PAGE), "docs/galil-conformance.md is stale: run the test with -PupdateGolden");
    }

    /** Every command and operand of every golden DMC file (both forms; the thesis dialect is a record, not for a Galil). */
    @Test
    void everyCommandOfTheGoldenFilesHasARow() throws IOException {
        Set<String> names = GalilConformance.names(GalilConformance.rows());
        TreeMap<String, String> missing = new TreeMap<>();
        int files = 0;
        try (Stream<Path> s = Files.walk(Path.of("src/test/resources/golden"))) {
            for (Path p : s.filter(f -> {
                String n = f.getFileName().toString();
                return (n.endsWith(".dmc") || n.endsWith(".stream")) && !n.endsWith(".thesis.dmc");
            }).sorted().toList()) {
                files++;
                for (String line : Files.readAllLines(p)) {
                    for (String n : GalilConformance.namesOfLine(line)) {
                        if (!names.contains(n)) {
                            missing.putIfAbsent(n, p + ": " + line);
                        }
                    }
                }
            }
        }
        assertTrue(files >= 9, "the goldens were found");
        assertEquals(new TreeMap<String, String>(), missing, "commands and operands without a row in galil_conformance.csv");
    }

    /**
     * What the virtual controller accepts, found by asking it: every two-letter command with a few argument
     * forms (accepted unless it answers TC 1), the axis forms {@code KPC=0}, every operand stem with a suffix,
     * every @ function of two to four letters, and the few longer words.
     */
    @Test
    void everyCommandAndOperandTheVirtualControllerAcceptsHasARow() throws GalilException, IOException {
        Set<String> accepted = new TreeSet<>();
        String[] forms = {"", " 0", " 1", " S", " X", " XY", " ?", " 1,1", " #A"};
        for (char a = 'A'; a <= 'Z'; a++) {
            for (char b = 'A'; b <= 'Z'; b++) {
                String cmd = "" + a + b;
                for (String f : forms) {
                    if (accepts(cmd + f)) {
                        accepted.add(cmd);
                        break;
                    }
                }
                VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null);
                try {
                    c.command(cmd + "X=1");
                    if (!c.variables.containsKey(cmd + "X")) {
                        accepted.add(cmd); // an axis form, not a variable
                    }
                } catch (GalilException e) {
                    if (e.tc != Tc.UNRECOGNIZED) {
                        accepted.add(cmd);
                    }
                }
                for (String suffix : new String[] {"", "S", "X", "0", "1"}) {
                    try {
                        c.operand(cmd + suffix);
                        accepted.add("_" + cmd);
                    } catch (GalilException e) {
                        if (e.tc != Tc.UNRECOGNIZED) {
                            accepted.add("_" + cmd);
                        }
                    }
                }
            }
        }
        for (String w : List.of("ELSE", "ENDIF", "IF (1)")) {
            if (accepts(w)) {
                accepted.add("IF");
            }
        }
        if (accepts("\u0012\u0016")) {
            accepted.add("^R^V");
        }
        if (accepts("tool=1")) {
            accepted.add("=");
        }
        VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null);
        c.variable("TIME");
        accepted.add("TIME");
        StringBuilder name = new StringBuilder();
        for (int length = 2; length <= 4; length++) {
            int[] at = new int[length];
            while (true) {
                name.setLength(0);
                for (int i : at) {
                    name.append((char) ('A' + i));
                }
                try {
                    Expressions.eval("@" + name + "[1]", c);
                    accepted.add("@" + name);
                } catch (GalilException e) {
                    if (e.tc != Tc.BAD_FUNCTION) {
                        accepted.add("@" + name);
                    }
                }
                int i = length - 1;
                while (i >= 0 && ++at[i] == 26) {
                    at[i--] = 0;
                }
                if (i < 0) {
                    break;
                }
            }
        }
        assertTrue(accepted.containsAll(List.of("VP", "MG", "_CS", "@INT", "TIME", "^R^V")), accepted.toString());
        Set<String> missing = new TreeSet<>(accepted);
        missing.removeAll(GalilConformance.names(GalilConformance.rows()));
        assertEquals(Set.of(), missing, "accepted by the virtual controller without a row in galil_conformance.csv");
    }

    /** Does a fresh controller take {@code statement} from the host (any answer but TC 1)? */
    private static boolean accepts(String statement) {
        VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null);
        try {
            c.command(statement);
            return true;
        } catch (GalilException e) {
            return e.tc != Tc.UNRECOGNIZED;
        }
    }

    /** The page: what the table is, its counts, the rows still being fixed or silent, then one table per kind. */
    static String render(List<Row> rows) {
        StringBuilder b = new StringBuilder();
        b.append("# gcnc held to Galil's documentation\n\n");
        b.append("<!-- Generated from tables/galil_conformance.csv by gcnc.controller.GalilConformanceTest: edit the table,\n");
        b.append("     then run `gradle junitPlatformTest -Ponly=GalilConformanceTest -PupdateGolden`. -->\n\n");
        b.append("The manual is the specification for the controller. This page renders\n");
        b.append("[tables/galil_conformance.csv](../tables/galil_conformance.csv): one row for every command gcnc emits\n");
        b.append("(the [galil dialect](galil.md), both forms), every command the sender ([run.md](run.md)) sends, every\n");
        b.append("operand it reads, every protocol rule it relies on, and every command and operand the\n");
        b.append("[virtual controller](virtual-controller.md) accepts; each with the manual's words it rests on, where\n");
        b.append("they are, what gcnc does, the models they hold for, and the test that pins it. The sources' short\n");
        b.append("names are those of `../shared/spec/galil-manual-review.md` (COMALL is Galil's firmware command\n");
        b.append("reference) and are listed in the table's header. Status: **fine** (gcnc, the simulator and the virtual\n");
        b.append("controller read the manual alike), **fixing** (a misreading of the review, being fixed; its test is\n");
        b.append("`pending` until the fix lands), **silent** (the manual does not say: gcnc takes the safe reading, and\n");
        b.append("`gcnc controller probe` should read it on the user's unit). Tests that hold the table complete:\n");
        b.append("`GalilConformanceTest` (goldens, the virtual controller) and `SenderConformanceTest` (what a run sends).\n\n");
        TreeMap<String, Integer> counts = new TreeMap<>();
        for (Row r : rows) {
            counts.merge(r.get("status"), 1, Integer::sum);
        }
        b.append(rows.size()).append(" rows: ");
        List<String> parts = new ArrayList<>();
        counts.forEach((k, v) -> parts.add(v + " " + k));
        b.append(String.join(", ", parts)).append(".\n\n");
        for (String status : List.of("fixing", "silent")) {
            b.append("**").append(status).append(":** ");
            List<String> ids = new ArrayList<>();
            for (Row r : rows) {
                if (r.get("status").equals(status)) {
                    ids.add("`" + r.get("name") + "`" + (r.get("review").isBlank() ? "" : " (" + r.get("review") + ")"));
                }
            }
            b.append(String.join(", ", ids)).append(".\n\n");
        }
        for (String kind : List.of("command", "operand", "protocol")) {
            b.append("## ").append(Character.toUpperCase(kind.charAt(0))).append(kind.substring(1)).append("s\n\n");
            b.append("| name | the manual says | source | gcnc | models | status | test |\n");
            b.append("|---|---|---|---|---|---|---|\n");
            for (Row r : rows) {
                if (!r.get("kind").equals(kind)) {
                    continue;
                }
                String test = r.get("test");
                b.append("| `").append(cell(r.get("name"))).append("` | ").append(cell(r.get("manual"))).append(" | ")
                        .append(cell(r.get("source"))).append(" | ").append(cell(r.get("gcnc"))).append(" | ")
                        .append(cell(r.get("models"))).append(" | ").append(r.get("status"))
                        .append(r.get("review").isBlank() ? "" : " (" + r.get("review") + ")").append(" | ")
                        .append(test.equals("pending") ? "pending" : "`" + test.substring(test.lastIndexOf('.') + 1) + "`")
                        .append(" |\n");
            }
            b.append('\n');
        }
        return b.toString();
    }

    private static String cell(String s) {
        return s.replace("|", "\\|").replace("<", "&lt;");
    }

    @Test
    void aLineWithoutARowIsFound() {
        // the check finds what it must: a command, an operand in an argument, an automatic subroutine
        assertEquals(Set.of("ZZ", "_QQ"), GalilConformance.namesOf("ZZ _QQA"));
        assertEquals(Set.of("#CMDERR"), GalilConformance.namesOf("#CMDERR"));
        assertEquals(Set.of("#"), GalilConformance.namesOf("#B12"));
        assertEquals(Set.of("=", "@INT", "_TP"), GalilConformance.namesOf("gsp=(@INT[_TPC/4096]+1)*4096"));
        assertEquals(Set.of("KP"), GalilConformance.namesOf("KPC=0"));
        assertEquals(Set.of("MG", "_TC"), GalilConformance.namesOf("MG \"_XX IN A STRING\",gline,_TC"));
        assertEquals(Set.of("VP", "<>"), GalilConformance.namesOf("VP 1,2 <100 >50"));
        assertEquals(Set.of("JP", "TIME"), GalilConformance.namesOf("JP #TUW,TIME<twt"));
        if (GalilConformance.namesOf("JP #A,@ABS[_TPX-1]>2").contains("<>")) {
            fail("a comparison is not a segment speed");
        }
    }
}
