package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Issue 35 item 5: the bore's envelope ({@link LowerEnvelope}) and the top run's floor keep a
 * drilled or bored part on the fast path; this holds the fast path to the full model
 * ({@link SimOptions#withReferenceStock}) on random drilled and bored parts, in the style of
 * {@link TurnedPartPropertyTest}: a centre drill, a drill in pecks, a boring bar opening the hole,
 * facing before or after, roughing passes outside, now and then a rapid planted into the part or a
 * boring pass pulled back through the bore's bottom. The findings (code and line) and the part's
 * outline the drawing shows must be the same, point for point.
 * {@code gradle junitPlatformTest -PboreSeed=1 -PboreCount=500} runs a long campaign.
 */
class BoredPartPropertyTest {
    private static final Tables TABLES = Tables.builtIn();

    /** The generic machine with a centre drill, two drills and a boring bar in its turret. */
    private static MachineProfile machine() throws Exception {
        String text = Files.readString(Path.of("tables/machines/generic.machine"))
                + "station.2 = centre 3.15\nstation.3 = drill 10\nstation.5 = drill 16\nstation.4 = bore 10\n";
        return ProfileLoader.read(ProfileFile.parse("drilled.machine", text), TABLES, TableSource.builtIn(), null);
    }

    private static String n(double v) {
        String t = String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
        return t.endsWith(".") ? t : t.contains(".") ? t : t + ".";
    }

    /** A random drilled (and perhaps bored) part's program, with its blank's diameter in {@code blank[0]}. */
    static String program(Random rnd, double[] blank) {
        double d = 40 + rnd.nextInt(21);
        blank[0] = d;
        List<String> out = new ArrayList<>(List.of("G21 G90 G98", "G50 S2500", "M11", "S1000 M03"));
        boolean faceFirst = rnd.nextBoolean();
        if (faceFirst) {
            face(out, d);
        }
        out.addAll(List.of("T0202", "G00 X0. Z2.", "G01 Z" + n(-2 - rnd.nextInt(3)) + " F60.", "G00 Z2."));
        boolean big = rnd.nextBoolean();
        double drill = big ? 16 : 10;
        double depth = 10 + rnd.nextInt(20);
        out.addAll(List.of(big ? "T0505" : "T0303", "G00 X0. Z2."));
        for (double z = Math.min(5, depth); ; z = Math.min(depth, z + 3 + rnd.nextInt(5))) {
            out.add("G01 Z" + n(-z) + " F80.");
            out.add("G00 Z2.");
            if (z >= depth) {
                break;
            }
        }
        double bore = drill;
        if (big && rnd.nextBoolean()) { // open the 16 mm hole with the 10 mm bar
            double to = depth - 2 - rnd.nextInt(5);
            out.addAll(List.of("T0404", "G00 X" + n(drill - 1) + " Z2."));
            for (double x = drill + 1; x <= drill + 2 + rnd.nextInt(5); x += 1) {
                out.addAll(List.of("G00 X" + n(x), "G01 Z" + n(-to) + " F100.", "G01 X" + n(x - 1), "G00 Z2."));
                bore = x;
            }
        }
        if (!faceFirst) {
            face(out, d);
        }
        out.add("T0101");
        double floor = bore + 8;
        for (double c = d - 2; c > floor; c -= 2) {
            out.addAll(List.of("G00 X" + n(c) + " Z2.", "G01 Z" + n(-5 - rnd.nextInt(30)) + " F150.", "G00 U2.", "G00 Z2."));
        }
        out.addAll(List.of("G00 X" + n(d + 10) + " Z5.", "M05", "M30"));
        return String.join("\n", out) + "\n";
    }

    private static void face(List<String> out, double d) {
        out.addAll(List.of("T0101", "G00 X" + n(d + 4) + " Z-0.5", "G01 X-1.6 F150.", "G00 Z2."));
    }

    /** Findings (code@line) and the drawing's part outline, with the stock's usual model or the full one. */
    private record Outcome(List<String> findings, double[] z, double[] r) {
    }

    private static Outcome run(MachineProfile m, String program, double blank, boolean reference) throws Exception {
        double stickout = m.model().stock().orElseThrow().stickout();
        SimOptions o = SimOptions.defaults().withStock(new StockSize(blank, 120, stickout)).withPath();
        Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES, m, "galil",
                Optional.of(reference ? o.withReferenceStock() : o)), l -> { });
        List<String> found = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            found.add(d.code().id() + "@" + d.span().line());
        }
        Drawing drawing = r.simulation().orElseThrow().drawing();
        return new Outcome(found, drawing.finalZ(), drawing.finalR());
    }

    private static void same(MachineProfile m, String program, double blank, String what) throws Exception {
        Outcome fast = run(m, program, blank, false);
        Outcome full = run(m, program, blank, true);
        assertEquals(full.findings(), fast.findings(), what + ": the findings\n" + program);
        String both = "\nfull z " + java.util.Arrays.toString(full.z()) + "\nfull r " + java.util.Arrays.toString(full.r())
                + "\nfast z " + java.util.Arrays.toString(fast.z()) + "\nfast r " + java.util.Arrays.toString(fast.r()) + "\n";
        assertArrayEquals(full.z(), fast.z(), 1e-6, what + ": the outline's z" + both + program);
        assertArrayEquals(full.r(), fast.r(), 1e-6, what + ": the outline's r" + both + program);
    }

    @TestFactory
    Stream<DynamicTest> theFastPathAgreesWithTheFullModelOnDrilledParts() throws Exception {
        long first = Long.getLong("gcnc.bore.seed", 20261202L);
        long count = Long.getLong("gcnc.bore.count", 10);
        MachineProfile m = machine();
        List<DynamicTest> tests = new ArrayList<>();
        for (long seed = first; seed < first + count; seed++) {
            long s = seed;
            tests.add(dynamicTest("bored part seed " + s, () -> {
                Random rnd = new Random(s);
                double[] blank = new double[1];
                String program = program(rnd, blank);
                same(m, program, blank[0], "seed " + s);

                List<String> lines = new ArrayList<>(List.of(program.split("\n")));
                // a rapid planted into the part: the first roughing pass's approach along the blank
                int rough = lines.lastIndexOf("T0101") + 1;
                int pass = -1;
                for (int i = rough; i < lines.size(); i++) {
                    if (lines.get(i).startsWith("G01 Z")) {
                        pass = i;
                        break;
                    }
                }
                if (pass > 0) {
                    List<String> bad = new ArrayList<>(lines);
                    bad.add(pass, "G00 Z-4.");
                    String text = String.join("\n", bad) + "\n";
                    Outcome fast = run(m, text, blank[0], false);
                    assertTrue(fast.findings().contains("E305@" + (pass + 1)), "seed " + s + ": " + fast.findings() + "\n" + text);
                    same(m, text, blank[0], "seed " + s + " with a rapid into the part");
                }
                // a drill moved sideways at the bottom of its hole (E323), and what it leaves
                int peck = -1;
                for (int i = 0; i < lines.size(); i++) {
                    if (lines.get(i).startsWith("G01 Z") && lines.get(i).endsWith("F80.")) {
                        peck = i;
                    }
                }
                List<String> sideways = new ArrayList<>(lines);
                sideways.add(peck + 1, "G01 X" + n(4 + rnd.nextInt(4)));
                same(m, String.join("\n", sideways) + "\n", blank[0], "seed " + s + " with a drill moved sideways");
            }));
        }
        return tests.stream();
    }
}
