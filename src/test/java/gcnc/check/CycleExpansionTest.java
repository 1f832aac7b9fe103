package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import gcnc.ir.RawBlock;
import gcnc.parse.BlockReader;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The expansion of G70/G71/G72, as the moves the checker made of each cycle, written the way the
 * program writes coordinates (X a diameter), one line per checked block with the pass it belongs
 * to; compared byte for byte with src/test/resources/cycles/NAME.MACHINE.expanded. After a
 * deliberate change: {@code gradle junitPlatformTest -PupdateGolden}, and review the diff.
 */
class CycleExpansionTest {
    private static final Path DIR = Path.of("src/test/resources/cycles");

    /** The checked blocks of a program file and its findings. */
    record Expanded(List<CheckedBlock> blocks, Diagnostics diagnostics) {
    }

    static Expanded expand(String machine, Reader program) throws Exception {
        Diagnostics d = new Diagnostics();
        BlockReader reader = new BlockReader(program, d);
        Checker checker = new Checker(Run.TABLES, Run.profile(machine), d);
        List<CheckedBlock> blocks = new ArrayList<>();
        for (RawBlock b = reader.next(); b != null; b = reader.next()) {
            blocks.addAll(checker.check(b));
        }
        checker.finish(reader.lines());
        return new Expanded(blocks, d);
    }

    /** One line per block: source line, the pass (or the block's N), then its motions in program terms. */
    static String render(Expanded e) {
        StringBuilder sb = new StringBuilder();
        for (Diagnostic d : e.diagnostics().sorted()) {
            sb.append("# ").append(d.span().line()).append(':').append(d.span().column()).append(' ')
                    .append(d.code().id()).append(' ').append(d.args()).append('\n');
        }
        for (CheckedBlock b : e.blocks()) {
            ProgramFrame f = b.frame();
            sb.append(b.line()).append(" | ").append(f.sequence()).append(" |");
            if (b.motions().isEmpty()) {
                sb.append(" -");
            }
            for (Motion m : b.motions()) {
                sb.append(' ').append(motion(m, f));
            }
            sb.append('\n');
        }
        return sb.toString();
    }

    private static String motion(Motion m, ProgramFrame f) {
        if (m instanceof Motion.Linear l) {
            return (l.rapid() ? "G00 " : "G01 ") + at(l.to(), f);
        }
        if (m instanceof Motion.Arc a) {
            return (a.clockwise() ? "G02 " : "G03 ") + at(a.to(), f) + " about " + at(a.centre(), f);
        }
        if (m instanceof Motion.Dwell d) {
            return "G04 " + d.seconds() + " s";
        }
        throw new AssertionError("a motion this test does not know: " + m);
    }

    static String at(Point p, ProgramFrame f) {
        return String.format(Locale.ROOT, "X%.4f Z%.4f", (p.x() - f.origin().x()) / f.perX(),
                (p.z() - f.origin().z()) / f.perZ());
    }

    @TestFactory
    Stream<DynamicTest> everyCycleProgramExpandsAsReviewed() throws Exception {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        List<Path> programs;
        try (Stream<Path> s = Files.list(DIR)) {
            programs = s.filter(p -> p.toString().endsWith(".nc")).sorted().toList();
        }
        return programs.stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
            String name = p.getFileName().toString();
            String machine = name.split("\\.")[1];
            String actual;
            try (Reader in = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                actual = render(expand(machine, in));
            }
            Path golden = DIR.resolve(name.replaceAll("\\.nc$", ".expanded"));
            if (update) {
                Files.writeString(golden, actual, StandardCharsets.UTF_8);
            }
            assertEquals(Files.readString(golden, StandardCharsets.UTF_8), actual);
        }));
    }
}
