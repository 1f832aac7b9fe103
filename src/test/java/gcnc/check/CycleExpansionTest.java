package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.galil.Dialect;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import gcnc.ir.RawBlock;
import gcnc.parse.BlockReader;
import java.io.IOException;
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
        return expand(Run.profile(machine), program);
    }

    /** The program read as the profile's control reads it (its comments, the closing '%'), then checked. */
    static Expanded expand(gcnc.machine.MachineProfile profile, Reader program) throws Exception {
        Diagnostics d = new Diagnostics();
        BlockReader reader = BlockReader.forControl(program, d, false, profile.control().lineComments());
        Checker checker = new Checker(Run.TABLES, profile, d);
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
        if (m instanceof Motion.Thread t) {
            // a continuous G32 thread: each joint; a chamfered pull-out (M23): the straight part's end, then the chamfer's
            StringBuilder joints = new StringBuilder();
            for (Point j : t.joints()) {
                joints.append(at(j, f)).append(" THEN ");
            }
            return String.format(Locale.ROOT, "THREAD %s%s%s lead %.5f at %.0f r/min%s", joints,
                    t.chamfered() ? at(t.chamferStart(), f) + " CHAMFER " : "", at(t.to(), f), t.lead() / f.perZ(),
                    t.rpm(), t.reverse() ? " M04" : "");
        }
        throw new AssertionError("a motion this test does not know: " + m);
    }

    static String at(Point p, ProgramFrame f) {
        return String.format(Locale.ROOT, "X%.4f Z%.4f", (p.x() - f.origin().x()) / f.perX(),
                (p.z() - f.origin().z()) / f.perZ());
    }

    /** The cycle's blocks only, rendered. */
    private static String cycle(Expanded e) {
        StringBuilder sb = new StringBuilder();
        for (CheckedBlock b : e.blocks()) {
            if (b.frame().sequence().contains("G71")) {
                for (Motion m : b.motions()) {
                    sb.append(motion(m, b.frame())).append('\n');
                }
            }
        }
        return sb.toString();
    }

    @org.junit.jupiter.api.Test
    void aG90InForceCutsAgainForAnAxisWordButNotForAOneShotGsWords() {
        Run r = Run.of("fanuc", "S500 M03\nG00 X42. Z2.\nG90 X39. Z-20. F0.2\nX36.\nG04 U1.\nG00 X50.\nX60.\nM30\n");
        assertEquals("", r.errors());
        List<String> moves = new ArrayList<>();
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                moves.add(b.line() + " " + motion(m, b.frame()));
            }
        }
        assertEquals(List.of("2 G00 X42.0000 Z2.0000",
                "3 G00 X39.0000 Z2.0000", "3 G01 X39.0000 Z-20.0000", "3 G01 X42.0000 Z-20.0000", "3 G00 X42.0000 Z2.0000",
                "4 G00 X36.0000 Z2.0000", "4 G01 X36.0000 Z-20.0000", "4 G01 X42.0000 Z-20.0000", "4 G00 X42.0000 Z2.0000",
                "5 G04 1.0 s", "6 G00 X50.0000 Z2.0000", "7 G00 X60.0000 Z2.0000"), moves);
    }

    @org.junit.jupiter.api.Test
    void aContourWrittenWithUAndWMakesTheSameMovesAsOneWithXAndZ() throws Exception {
        String head = "G21 G99\nT0101\nG97 S1000 M03\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n";
        String absolute = head + "N10 G00 X20.\nG01 Z-15.\nX30. Z-25.\nG02 X40. Z-30. R5.\nN20 G01 X50.\nG70 P10 Q20\nM30\n";
        String relative = head + "N10 G00 U-32.\nG01 W-17.\nU10. W-10.\nG02 U10. W-5. R5.\nN20 G01 U10.\nG70 P10 Q20\nM30\n";
        Expanded a = expand("fanuc", new java.io.StringReader(absolute));
        Expanded r = expand("fanuc", new java.io.StringReader(relative));
        assertEquals("[]", a.diagnostics().sorted().toString());
        assertEquals("[]", r.diagnostics().sorted().toString());
        assertEquals(render(a), render(r));
    }

    @org.junit.jupiter.api.Test
    void aTypeTwoContourThatNeverGoesBackInMakesTheMovesOfTypeOne() throws Exception {
        // Z2. in the first block (the start's own Z) makes the contour type II; with no pocket its
        // passes are type I's, move for move, outside (G71), inside (Haas R1) and facing (G72)
        String head = "G21 G99\nT0101\nG97 S1000 M03\nG00 X52. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n";
        String shape = "G01 Z-15. F0.1\nX30. Z-25.\nG02 X40. Z-30. R5.\nN20 G01 X50.\nG70 P10 Q20\nM30\n";
        assertEquals(render(expand("fanuc", new java.io.StringReader(head + "N10 G00 X20.\n" + shape))),
                render(expand("fanuc", new java.io.StringReader(head + "N10 G00 X20. Z2.\n" + shape))));
        String inside = "G20 G99\nT0101\nG97 S800 M03\nG00 X0.5 Z0.1\nG71 P30 Q40 U-0.02 W0.005 D0.05%s F0.008\n"
                + "N30 G00 X1.5\nG01 Z0. F0.004\nX1.2 Z-0.15\nZ-1.\nX0.8\nN40 Z-1.5\nM30\n";
        assertEquals(render(expand("haas", new java.io.StringReader(String.format(inside, "")))),
                render(expand("haas", new java.io.StringReader(String.format(inside, " R1")))));
        String facing = "G21 G99\nT0101\nG97 S1000 M03\nG00 X68. Z2.\nG72 W1.5 R0.5\nG72 P50 Q60 U0.2 W0.1 F0.2\n"
                + "N50 G00 %sZ-6.\nG01 X40. F0.1\nZ-3.\nX20. Z0.\nN60 X0.\nM30\n";
        assertEquals(render(expand("fanuc", new java.io.StringReader(String.format(facing, "")))),
                render(expand("fanuc", new java.io.StringReader(String.format(facing, "X68. ")))));
    }

    @org.junit.jupiter.api.Test
    void underG91TheCycleMakesTheSameMovesAsUnderG90() throws Exception {
        gcnc.machine.MachineProfile b = gcnc.machine.ProfileLoader.load("fanuc", gcnc.tables.TableSource.builtIn(),
                Run.TABLES, "fanuc-b");
        String head = "G21 G95\nT0101\nG97 S1000 M03\nG90 G00 X52. Z2.\n";
        String absolute = head + "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z-15.\nX48.\n"
                + "N20 Z-40.\nM30\n";
        String incremental = head + "G91\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X-32.\nG01 Z-17.\n"
                + "X28.\nN20 Z-25.\nG90\nM30\n";
        Expanded a = expand(b, new java.io.StringReader(absolute));
        Expanded i = expand(b, new java.io.StringReader(incremental));
        assertEquals("[]", a.diagnostics().sorted().toString());
        assertEquals("[]", i.diagnostics().sorted().toString());
        String moves = cycle(a);
        assertEquals(true, moves.split("\n").length > 20, moves);
        assertEquals(moves, cycle(i));
    }

    /** The cycle programs of the goldens, NAME.MACHINE.nc, in name order. */
    private static List<Path> programs() throws IOException {
        try (Stream<Path> s = Files.list(DIR)) {
            return s.filter(p -> p.toString().endsWith(".nc")).sorted().toList();
        }
    }

    @TestFactory
    Stream<DynamicTest> everyCycleProgramExpandsAsReviewed() throws Exception {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        return programs().stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
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

    /**
     * The same programs through the whole pipeline: the Galil program, with the source map that
     * points each cycle move back at the cycle's line, byte for byte as reviewed in NAME.MACHINE.dmc;
     * on the metric fanuc machine the simulator replays it over the machine's bar blank without a
     * finding (not a G73: a pattern repeat follows a forged or cast shape, and its first pass over
     * a bar is rightly too deep for the insert; not a G74: the shipped profiles have no drill or
     * face-grooving tool outline, and a turning insert fed along Z at X0 rightly puts its holder
     * into the stock), and so do the threads on the haas machine over the blank of their stock
     * header (the chamfered pull-out of M23 among them).
     */
    @TestFactory
    Stream<DynamicTest> everyCycleProgramCompilesAsReviewed() throws Exception {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        return programs().stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
            String name = p.getFileName().toString();
            String machine = name.split("\\.")[1];
            boolean simulate = machine.equals("fanuc") && !name.startsWith("pattern") && !name.startsWith("face-peck")
                    || name.startsWith("thread-");
            gcnc.Compiler.Settings settings = new gcnc.Compiler.Settings(Run.TABLES, Run.profile(machine), Dialect.Kind.GALIL,
                    simulate ? java.util.Optional.of(gcnc.sim.SimOptions.defaults()) : java.util.Optional.empty(), true);
            StringBuilder dmc = new StringBuilder();
            gcnc.Compiler.Result r;
            try (Reader in = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                r = gcnc.Compiler.compile(in, settings, l -> dmc.append(l.text()).append('\n'));
            }
            assertEquals(true, r.ok(), () -> name + ": " + r.diagnostics().sorted());
            if (simulate) {
                assertEquals(0, r.simulation().orElseThrow().findings(), () -> name + ": " + r.diagnostics().sorted());
            }
            Path golden = DIR.resolve(name.replaceAll("\\.nc$", ".dmc"));
            if (update) {
                Files.writeString(golden, dmc.toString(), StandardCharsets.UTF_8);
            }
            assertEquals(Files.readString(golden, StandardCharsets.UTF_8), dmc.toString());
        }));
    }
}
