package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Random stepped parts turned from random blanks the way a machinist programs them, on every
 * shipped machine: facing, roughing passes with a radial retract, a finishing pass up the
 * shoulders. The generator knows nothing of the simulator: it only keeps each pass's depth under
 * the insert and stops each pass at the shoulder it must leave. Such programs simulate with no
 * finding (an inch program on the haas, a groove with the grooving blade where the machine has
 * one); the same program with one rapid moved into the blank is flagged on that block, a
 * roughing pass turned back toward the tailstock deeper than the insert's trailing edge reaches is
 * a cut with the back of the insert, and with an insert smaller than the depth of cut the holder
 * is found in the stock.
 * {@code gradle junitPlatformTest -PpartSeed=1 -PpartCount=2000} runs a long campaign.
 */
class TurnedPartPropertyTest {
    private static final Tables TABLES = Tables.builtIn();

    /**
     * A machine, the program head its control wants, the feed in its feed mode, the program's
     * units (mm per unit: 25.4 for an inch program, 0.01 in the thesis's language), the grooving
     * and parting tools' T words ("" = none), whether X is a radius and numbers are written as
     * signed integers without a point (the thesis's language), and the profile's units per mm.
     */
    private record Machine(String name, String head, String feed, double unit, String groover, String parter,
                           boolean thesis) {
        double profilePerMm() {
            return thesis ? 1 / unit : 1;
        }
    }

    private static final Machine[] MACHINES = {
        new Machine("generic", "G21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\n", "F150.", 1, "", "", false),
        new Machine("haas", "G20\nG50 S2500\nT0101\nG97 S1000 M03\n", "F0.006", 25.4, "T0909", "T1212", false),
        new Machine("fanuc", "G21\nG50 S2500\nT0101\nG97 S1000 M03\n", "F0.15", 1, "T0505", "", false),
        // the thesis's lathe: its blank's face is 60 mm out of the jaws, so parts up to 50 mm long
        new Machine("thesis-2004", "G50 S5000 M11 M03 F150\n", "F150", 0.01, "", "", true),
    };

    /** A stepped part: zone k runs from Z -z[k-1] to -z[k] at diameter d[k], d increasing away from the face. */
    record Part(double blank, double[] d, double[] z) {
    }

    static Part part(Random rnd) {
        double blank = 30 + rnd.nextInt(31);
        int zones = 1 + rnd.nextInt(3);
        double[] d = new double[zones];
        double[] z = new double[zones];
        double dia = blank - 4 - rnd.nextInt(8);
        double at = 0;
        for (int k = zones - 1; k >= 0; k--) {
            d[k] = dia;
            dia = Math.max(6, dia - 2 - rnd.nextInt(10));
        }
        for (int k = 0; k < zones; k++) {
            at += 5 + rnd.nextInt(20);
            z[k] = at;
        }
        return new Part(blank, d, z);
    }

    /** The program; {@code lines} gets, for each G-code line (1-based), what it is ("rapid", "rough" ...). */
    static String program(Part p, Machine m, List<String> lines) {
        unit = m.unit();
        thesis = m.thesis();
        StringBuilder out = new StringBuilder();
        for (String h : m.head().split("\n")) {
            add(out, lines, h, "head");
        }
        double outside = p.blank() + 4;
        // face 0.5 mm
        add(out, lines, "G00 X" + x(outside) + " Z" + n(-0.5), "rapid");
        add(out, lines, "G01 X" + x(-1.6) + " " + m.feed(), "face");
        add(out, lines, "G00 Z" + n(2), "rapid");
        // rough: 1 mm a side, each pass stopping at the first zone at least as large as it
        for (double c = p.blank() - 2; c > p.d()[0]; c -= 2) {
            double end = p.z()[p.d().length - 1];
            for (int k = 0; k < p.d().length; k++) {
                if (p.d()[k] >= c) {
                    end = k == 0 ? 0 : p.z()[k - 1];
                    break;
                }
            }
            if (end == 0) {
                continue;
            }
            add(out, lines, "G00 X" + x(c), "rapid");
            add(out, lines, "G01 Z" + n(-end), "rough");
            add(out, lines, "G00 U" + x(2), "rapid");
            add(out, lines, "G00 Z" + n(2), "rapid");
        }
        // finish: a 1 mm radius from the face onto each zone (G03, convex), along each zone, up each
        // shoulder to the next radius, out past the blank
        double r = 1;
        add(out, lines, "G00 X" + x(p.d()[0] - 2 * r), "rapid");
        add(out, lines, "G01 Z" + n(-0.5), "finish");
        add(out, lines, "G03 X" + x(p.d()[0]) + " Z" + n(-0.5 - r) + " R" + n(r), "finish");
        for (int k = 0; k < p.d().length; k++) {
            add(out, lines, "G01 Z" + n(-p.z()[k]), "finish");
            if (k + 1 < p.d().length) {
                add(out, lines, "G01 X" + x(p.d()[k + 1] - 2 * r), "finish");
                add(out, lines, "G03 X" + x(p.d()[k + 1]) + " Z" + n(-p.z()[k] - r) + " R" + n(r), "finish");
            } else {
                add(out, lines, "G01 X" + x(outside), "finish");
            }
        }
        add(out, lines, "G00 Z" + n(2), "rapid");
        // a 3 mm groove, 1 mm deep, in the middle of the largest zone, with the grooving blade
        int last = p.d().length - 1;
        double from = last == 0 ? 0 : p.z()[last - 1];
        if (!m.groover().isEmpty() && p.z()[last] - from >= 8) {
            double zg = (from + p.z()[last]) / 2 + 1.5; // the blade's tip is its chuck-side corner
            add(out, lines, m.groover(), "tool");
            add(out, lines, "G00 X" + x(outside) + " Z" + n(-zg), "rapid");
            add(out, lines, "G01 X" + x(p.d()[last] - 2) + " " + m.feed(), "groove");
            add(out, lines, "G00 X" + x(outside), "rapid");
            add(out, lines, "G00 Z" + n(2), "rapid");
        }
        // part off 1 mm behind the last zone with the parting blade, where the machine has one
        if (!m.parter().isEmpty()) {
            double zp = p.z()[last] + 1 + 3; // the blade's tip is its chuck-side corner; the blade is 3 mm wide
            add(out, lines, m.parter(), "tool");
            add(out, lines, "G00 X" + x(outside) + " Z" + n(-zp), "rapid");
            add(out, lines, "G01 X" + x(-1) + " " + m.feed(), "part");
            add(out, lines, "G00 X" + x(outside), "rapid");
            add(out, lines, "G00 Z" + n(2), "rapid");
        }
        add(out, lines, "M05", "tail");
        add(out, lines, "M30", "tail");
        return out.toString();
    }

    private static void add(StringBuilder out, List<String> lines, String block, String what) {
        out.append(block).append('\n');
        for (String l : block.split("\n")) {
            lines.add(what);
        }
    }

    /** The value of {@code letter}'s word in a block this generator wrote, in mm. */
    private static double mm(String block, char letter) {
        for (String w : block.split(" ")) {
            if (w.charAt(0) == letter) {
                return Double.parseDouble(w.substring(1)) * unit;
            }
        }
        throw new IllegalArgumentException(letter + " in " + block);
    }

    /** mm per program unit of the program being written (25.4 for inch, 0.01 in the thesis's language). */
    private static double unit = 1;
    /** The thesis's language: X a radius, numbers signed integers. */
    private static boolean thesis;

    private static String n(double mm) {
        double v = mm / unit;
        if (thesis) {
            return String.format(Locale.ROOT, "%+d", Math.round(v));
        }
        String t = String.format(Locale.ROOT, unit == 1 ? "%.3f" : "%.4f", v).replaceAll("0+$", "");
        return t.endsWith(".") ? t : t.contains(".") ? t : t + ".";
    }

    /** An X value (or U increment) given as a diameter, as the control reads X. */
    private static String x(double diameter) {
        return n(thesis ? diameter / 2 : diameter);
    }

    /** The findings of a compile from the part's blank (120 mm long), given in the profile's units ({@code perMm} of them a mm). */
    static List<String> run(MachineProfile m, Part p, String program, double perMm) throws Exception {
        double stickout = m.model().stock().orElseThrow().stickout();
        Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withStock(new StockSize(p.blank() * perMm, 120 * perMm, stickout)))),
                l -> { });
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.code().id() + "@" + d.span().line());
        }
        return out;
    }

    /**
     * Seeds a campaign found broken: cuts lost when the envelope had been lowered under a cut
     * before the polygons were cut (the lazy stock, {@code Stock#cut}).
     */
    private static final long[] FOUND = {517, 550, 586};

    @TestFactory
    Stream<DynamicTest> turnedPartsSimulateCleanAndMistakesAreFound() throws Exception {
        long first = Long.getLong("gcnc.part.seed", 20261123L);
        long count = Long.getLong("gcnc.part.count", 12);
        List<DynamicTest> tests = new ArrayList<>();
        List<Long> seeds = new ArrayList<>();
        for (long seed = first; seed < first + count; seed++) {
            seeds.add(seed);
        }
        for (long seed : FOUND) {
            seeds.add(seed);
        }
        for (long s : seeds) {
            tests.add(dynamicTest("part seed " + s, () -> {
                Random rnd = new Random(s);
                Part p = part(rnd);
                for (Machine m : MACHINES) {
                    if (m.thesis() && p.z()[p.z().length - 1] > 50) {
                        continue; // longer than the thesis's blank sticks out of its jaws
                    }
                    MachineProfile profile = ProfileLoader.load(m.name(), TableSource.builtIn(), TABLES);
                    List<String> what = new ArrayList<>();
                    String program = program(p, m, what);
                    assertEquals(List.of(), run(profile, p, program, m.profilePerMm()), "seed " + s + " on " + m.name() + ":\n" + program);

                    // facing, roughing and finishing run a second time: every move retraces cut material
                    int start = what.indexOf("rapid");
                    int end = what.contains("tool") ? what.indexOf("tool") : what.indexOf("tail");
                    List<String> all = List.of(program.split("\n"));
                    List<String> again = new ArrayList<>(all.subList(0, end));
                    again.addAll(all.subList(start, all.size()));
                    String twice = String.join("\n", again) + "\n";
                    assertEquals(List.of(), run(profile, p, twice, m.profilePerMm()), "seed " + s + " on " + m.name() + ", twice:\n" + twice);

                    // one rapid moved into the blank: the first roughing pass's approach goes to Z-5 at full depth
                    int rough = what.indexOf("rough");
                    if (rough > 0) {
                        List<String> lines = new ArrayList<>(List.of(program.split("\n")));
                        lines.add(rough, "G00 Z" + n(-5)); // before the cut: a rapid along the blank at the cut's diameter
                        String bad = String.join("\n", lines) + "\n";
                        List<String> found = run(profile, p, bad, m.profilePerMm());
                        assertTrue(found.contains("E305@" + (rough + 1)), "seed " + s + " on " + m.name() + ": " + found
                                + "\n" + bad);
                    }

                    // a cut back toward the tailstock: after the first roughing pass, down 4 mm at its shoulder
                    // and 10 mm back along Z, deeper than the 80-degree insert's trailing edge reaches (2.24 mm)
                    if (rough > 0 && !m.thesis()) {
                        List<String> lines = new ArrayList<>(List.of(program.split("\n")));
                        double c = mm(lines.get(rough - 1), 'X');
                        double pass = -mm(lines.get(rough), 'Z');
                        if (pass >= 25) {
                            lines.add(rough + 1, "G01 X" + x(c - 8));
                            lines.add(rough + 2, "G01 Z" + n(-pass + 10));
                            lines.add(rough + 3, "G01 X" + x(c));
                            String bad = String.join("\n", lines) + "\n";
                            List<String> found = run(profile, p, bad, m.profilePerMm());
                            assertTrue(found.contains("E320@" + (rough + 3)), "seed " + s + " on " + m.name() + ": " + found
                                    + "\n" + bad);
                        }
                    }

                    // an insert smaller than the 1 mm depth of cut: the holder ploughs through the stock
                    if (rough > 0 && !m.thesis()) {
                        String text = java.nio.file.Files.readString(java.nio.file.Path.of("tables/machines/" + m.name() + ".machine"))
                                .replaceAll("(?m)^(sim\\.tool|station)\\.1 = .*$", "") + "sim.tool.1 = C 0.5\n";
                        MachineProfile small = ProfileLoader.read(ProfileFile.parse(m.name() + "-small.machine", text),
                                TABLES, TableSource.builtIn(), null);
                        List<String> found = run(small, p, program, m.profilePerMm());
                        assertTrue(found.contains("E315@" + (rough + 1)), "seed " + s + " on " + m.name() + ": " + found);
                    }
                }
            }));
        }
        return tests.stream();
    }
}
