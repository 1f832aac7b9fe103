package gcnc.check;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.galil.Dialect;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.util.ArrayList;
import java.util.List;

/**
 * Test utility: runs the checker over a program without the parser. Words are split on spaces;
 * a token is a letter and its number text; "(..." tokens are comments and skipped; blank lines
 * count as lines but make no block.
 */
final class Run {
    static final Tables TABLES = Tables.builtIn();

    final Diagnostics diagnostics = new Diagnostics();
    final List<CheckedBlock> blocks = new ArrayList<>();
    final Checker checker;

    private Run(MachineProfile p, int cap) {
        checker = new Checker(TABLES, p, diagnostics, cap);
    }

    /** The part programs (*.nc) of a test folder, in name order. */
    static List<java.nio.file.Path> programsIn(java.nio.file.Path dir) throws java.io.IOException {
        try (java.util.stream.Stream<java.nio.file.Path> s = java.nio.file.Files.list(dir)) {
            return s.filter(p -> p.toString().endsWith(".nc")).sorted().toList();
        }
    }

    /**
     * Checks {@code program} on {@code profile} as its control reads it: no error, and its blocks as
     * the checker expanded them ({@link CycleExpansionTest#render}) are the golden file beside it
     * ({@code .expanded} for {@code .nc}; rewritten with {@code -PupdateGolden}).
     */
    static void expandsAsGolden(java.nio.file.Path program, MachineProfile profile) throws Exception {
        String name = program.getFileName().toString();
        CycleExpansionTest.Expanded e;
        try (java.io.Reader in = java.nio.file.Files.newBufferedReader(program, java.nio.charset.StandardCharsets.UTF_8)) {
            e = CycleExpansionTest.expand(profile, in);
        }
        for (Diagnostic d : e.diagnostics().sorted()) {
            org.junit.jupiter.api.Assertions.assertTrue(d.severity() != gcnc.diag.Severity.ERROR, () -> name + ": " + d);
        }
        String actual = CycleExpansionTest.render(e);
        java.nio.file.Path golden = program.resolveSibling(name.replaceAll("\\.nc$", ".expanded"));
        if (Boolean.getBoolean("gcnc.updateGolden")) {
            java.nio.file.Files.writeString(golden, actual, java.nio.charset.StandardCharsets.UTF_8);
        }
        org.junit.jupiter.api.Assertions.assertEquals(
                java.nio.file.Files.readString(golden, java.nio.charset.StandardCharsets.UTF_8), actual);
    }

    /**
     * Compiles {@code program} on {@code profile} with no blank (a finishing program; a blank would
     * move G54 to its face), asserts it compiles and simulates clean and that its DMC is the golden
     * file beside it ({@code .dmc} for {@code .nc}; rewritten with {@code -PupdateGolden}).
     */
    static void compilesCleanAsGolden(java.nio.file.Path program, MachineProfile profile) throws java.io.IOException {
        String name = program.getFileName().toString();
        gcnc.Compiler.Settings settings = new gcnc.Compiler.Settings(TABLES, profile, Dialect.Kind.GALIL,
                java.util.Optional.of(gcnc.sim.SimOptions.defaults().withoutBlank()), true);
        gcnc.Compiler.Result r;
        StringBuilder dmc = new StringBuilder();
        try (java.io.Reader in = java.nio.file.Files.newBufferedReader(program, java.nio.charset.StandardCharsets.UTF_8)) {
            r = gcnc.Compiler.compile(in, settings, l -> dmc.append(l.text()).append('\n'));
        }
        org.junit.jupiter.api.Assertions.assertTrue(r.ok(), () -> name + ": " + r.diagnostics().sorted());
        org.junit.jupiter.api.Assertions.assertEquals(0, r.simulation().orElseThrow().findings(),
                () -> name + ": " + r.diagnostics().sorted());
        java.nio.file.Path golden = program.resolveSibling(name.replaceAll("\\.nc$", ".dmc"));
        if (Boolean.getBoolean("gcnc.updateGolden")) {
            java.nio.file.Files.writeString(golden, dmc.toString(), java.nio.charset.StandardCharsets.UTF_8);
        }
        org.junit.jupiter.api.Assertions.assertEquals(
                java.nio.file.Files.readString(golden, java.nio.charset.StandardCharsets.UTF_8), dmc.toString());
    }

    static MachineProfile profile(String name) {
        try {
            return ProfileLoader.load(name, TableSource.builtIn(), TABLES);
        } catch (TableException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A shipped machine under another control ({@code --machine generic --control fanuc-a}). */
    static MachineProfile profileWithControl(String name, String control) {
        try {
            return ProfileLoader.load(name, TableSource.builtIn(), TABLES, control);
        } catch (TableException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The generic machine under the thesis's own control: the tests of the thesis's rules. */
    static MachineProfile thesisRules() {
        try {
            return ProfileLoader.load("generic", TableSource.builtIn(), TABLES, "thesis-2004");
        } catch (TableException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A program on the generic machine with the thesis's rules (control thesis-2004). */
    static Run generic(String program) {
        return of(thesisRules(), program, Checker.ERROR_CAP);
    }

    static Run thesis(String program) {
        return of("thesis-2004", program);
    }

    static Run of(String profile, String program) {
        return of(profile(profile), program, Checker.ERROR_CAP);
    }

    static Run of(MachineProfile p, String program, int cap) {
        Run r = new Run(p, cap);
        String[] lines = program.split("\n", -1);
        int last = 0;
        for (int i = 0; i < lines.length; i++) {
            RawBlock b = block(i + 1, lines[i]);
            if (b != null) {
                last = i + 1;
                r.blocks.addAll(r.checker.check(b));
            }
        }
        r.checker.finish(last);
        return r;
    }

    /** One line as the parser would hand it over (null when it has no word). */
    static RawBlock block(int line, String program) {
        char[] cs = program.toCharArray();
        boolean comment = false;
        for (int k = 0; k < cs.length; k++) {
            comment |= cs[k] == '(';
            if (comment) {
                comment = cs[k] != ')';
                cs[k] = ' ';
            }
        }
        String text = new String(cs);
        List<Word> words = new ArrayList<>();
        int i = 0;
        while (i < text.length()) {
            if (text.charAt(i) == ' ') {
                i++;
                continue;
            }
            int end = text.indexOf(' ', i);
            end = end < 0 ? text.length() : end;
            {
                Letter l = Letter.of(text.charAt(i));
                if (l == null) {
                    throw new IllegalArgumentException("test program has no such letter: " + text.substring(i, end));
                }
                words.add(new Word(l, text.substring(i + 1, end), Span.of(line, i + 1)));
            }
            i = end;
        }
        return words.isEmpty() ? null : new RawBlock(line, words, words.get(words.size() - 1).span(), false);
    }

    /** The findings as "line:column:E0nn", in report order, comma separated. */
    String errors() {
        StringBuilder sb = new StringBuilder();
        for (Diagnostic d : diagnostics.sorted()) {
            if (sb.length() > 0) {
                sb.append(", ");
            }
            sb.append(d.span().line()).append(':').append(d.span().column()).append(':').append(d.code().id());
        }
        return sb.toString();
    }

    /** The findings' English messages, one a line. */
    String messages() {
        StringBuilder sb = new StringBuilder();
        for (Diagnostic d : diagnostics.sorted()) {
            sb.append(TABLES.messages().render(d.code(), d.args(), gcnc.tables.ErrorMessages.Lang.EN)).append('\n');
        }
        return sb.toString();
    }

    CheckedBlock line(int n) {
        for (CheckedBlock b : blocks) {
            if (b.line() == n) {
                return b;
            }
        }
        throw new AssertionError("no checked block for line " + n + "; errors: " + errors());
    }
}
