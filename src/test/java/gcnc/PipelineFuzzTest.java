package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
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
 * The whole pipeline (parse, check, both dialects, simulation) on seeded random turning programs:
 * plausible blocks with random values, some of them mutated. Nothing may throw; every finding is a
 * numbered diagnostic on a line of the program; a clean result has emitted a program ending in EN.
 * And in the galil dialect, on either machine, the replayed DMC follows the program: no
 * conformance finding (E308, E309, E311, E314), which would be the compiler's fault, not the
 * program's. A failure names its seed. Real-style programs mutated line by line go through the same
 * checks ({@link #mutatedRealProgramsNeverBreakThePipeline}). A longer campaign:
 * {@code gradle junitPlatformTest -PfuzzSeed=1 -PfuzzCount=100000} (10,000 programs take about 15 s here).
 */
class PipelineFuzzTest {
    private static final Tables TABLES = Tables.builtIn();
    /** Findings that mean the emitted DMC does not do what the checked program says. */
    private static final java.util.Set<String> COMPILER_FAULTS = java.util.Set.of("E308", "E309", "E311", "E314");
    /**
     * Seeds long campaigns found broken (arcs near a half or a full turn, I/K end
     * points off their circle within tolerance, R a little short, sub-count moves, arcs and circles;
     * 481 and 1043: a thread or a modal cycle under nose compensation reached the offset code; 5219: a G32
     * after a G41 whose block had an error, "G04 1P405" read as G41 P405 since spaces do not part words;
     * 5018: an arc beyond the controller's CR range after an error, which check judged and compile did not write;
     * 248 and 1087: a chain of blended arcs drifting a count off, the next sequence starting there (E308);
     * 1485: an arc the planner still held when a later block's error came, judged by check and never by compile).
     */
    private static final long[] FOUND = {212, 248, 481, 1043, 1087, 1485, 3269, 3287, 3873, 5018, 5219, 5730, 12893, 14770, 17282,
        23808, 88905, 113719, 276991};

    @TestFactory
    Stream<DynamicTest> randomProgramsNeverBreakThePipeline() throws Exception {
        MachineProfile generic = ProfileLoader.load("generic", TableSource.builtIn(), TABLES);
        MachineProfile thesis = ProfileLoader.load("thesis-2004", TableSource.builtIn(), TABLES);
        // The generic lathe with the axes swapped on the controller, X mirrored and a front post.
        String text = java.nio.file.Files.readString(java.nio.file.Path.of("tables/machines/generic.machine"))
                .replace("z.galil = X", "z.galil = Y").replace("x.galil = Y", "x.galil = X")
                .replace("x.sign = 1", "x.sign = -1").replace("tool_post = rear", "tool_post = front");
        MachineProfile mirrored = ProfileLoader.read(gcnc.machine.ProfileFile.parse("mirrored.machine", text), TABLES);
        assertEquals("X -1 Y front", mirrored.x().galil() + " " + mirrored.x().sign() + " " + mirrored.z().galil() + " "
                + (mirrored.rearToolPost() ? "rear" : "front"));
        MachineProfile haas = ProfileLoader.load("haas", TableSource.builtIn(), TABLES);
        MachineProfile fanuc = ProfileLoader.load("fanuc", TableSource.builtIn(), TABLES);
        long first = Long.getLong("gcnc.fuzz.seed", 20261122L);
        List<DynamicTest> tests = new ArrayList<>();
        List<Long> seeds = new ArrayList<>();
        long count = Long.getLong("gcnc.fuzz.count", 60);
        for (long seed = first; seed < first + count; seed++) {
            seeds.add(seed);
        }
        for (long seed : FOUND) {
            seeds.add(seed);
        }
        for (long s : seeds) {
            tests.add(dynamicTest("seed " + s, () -> {
                String program = program(new Random(s));
                run(program, generic, "galil", s);
                run(program, mirrored, "galil", s);
                run(program, thesis, "galil", s);
                run(program, thesis, "thesis", s);
                // The same program with modal round trips between its blocks (units, feed per
                // revolution, tools, work offsets, spindle, dwell): same path, more state.
                String busier = withRoundTrips(program, new Random(~s));
                run(busier, generic, "galil", s);
                run(busier, mirrored, "galil", s);
                // The same programs as a Haas and a Fanuc (system A) control write them.
                run(inSystemA(program, "M10"), haas, "galil", s);
                run(inSystemA(busier, "M10"), haas, "galil", s);
                run(inSystemA(program, "M11"), fanuc, "galil", s);
                run(inSystemA(busier, "M11"), fanuc, "galil", s);
                // With thread passes (geared to the spindle: docs/threading.md) among the moves.
                // on the haas, every other seed under M23: each G92/G76 pass ends with its chamfer
                run(withThreads(inSystemA(program, "M10"), new Random(s * 31), s % 2 == 0 ? "M23" : "M24"), haas,
                        "galil", s);
                run(withThreads(inSystemA(busier, "M11"), new Random(s * 37), "M24"), fanuc, "galil", s);
            }));
        }
        return tests.stream();
    }

    /**
     * Real-style programs (src/test/resources/fuzz: written for this test in the style of shop
     * programs: cycles, tool changes, a macro loop with a subprogram, an M97 local subprogram), each
     * clean on its machine, mutated as a hand or a bad transfer would: lines deleted, duplicated or
     * swapped, a digit changed, a decimal point dropped, a word inserted. Nothing may throw, and
     * check, compile and the replay of what compile wrote must agree ({@link #run}). The default run
     * makes a fifth as many mutants of each as there are random programs; -PfuzzCount raises both.
     */
    @TestFactory
    Stream<DynamicTest> mutatedRealProgramsNeverBreakThePipeline() throws Exception {
        MachineProfile haas = ProfileLoader.load("haas", TableSource.builtIn(), TABLES);
        MachineProfile fanuc = ProfileLoader.load("fanuc", TableSource.builtIn(), TABLES);
        long first = Long.getLong("gcnc.fuzz.seed", 20261122L);
        long count = Math.max(4, Long.getLong("gcnc.fuzz.count", 60) / 5);
        List<DynamicTest> tests = new ArrayList<>();
        for (String base : new String[] {"haas-bushing", "haas-box-local", "fanuc-thread-shaft", "fanuc-macro-grooves"}) {
            String program = java.nio.file.Files.readString(java.nio.file.Path.of("src/test/resources/fuzz", base + ".nc"));
            MachineProfile machine = base.startsWith("haas") ? haas : fanuc;
            tests.add(dynamicTest("fuzz/" + base + ".nc as written", () -> {
                Compiler.Result clean = Compiler.check(new StringReader(program), new Compiler.Settings(TABLES, machine,
                        Dialect.Kind.GALIL, Optional.empty()));
                assertEquals(List.of(), errors(clean, false), base + " is a clean base program");
                run(program, machine, "galil", 0);
            }));
            for (long seed = first; seed < first + count; seed++) {
                long s = seed;
                tests.add(dynamicTest("fuzz/" + base + ".nc seed " + s, () -> run(mutated(program, new Random(s)), machine, "galil", s)));
            }
        }
        return tests.stream();
    }

    /** One to three mutations of a program's lines (never of its first line, the % or O line). */
    static String mutated(String program, Random rnd) {
        List<String> lines = new ArrayList<>(program.lines().toList());
        for (int m = 1 + rnd.nextInt(3); m > 0 && lines.size() > 3; m--) {
            int i = 2 + rnd.nextInt(lines.size() - 2);
            String line = lines.get(i);
            switch (rnd.nextInt(6)) {
                case 0 -> lines.remove(i);
                case 1 -> lines.add(i, line);
                case 2 -> {
                    int j = i == lines.size() - 1 ? i - 1 : i + 1;
                    lines.set(i, lines.get(j));
                    lines.set(j, line);
                }
                case 3 -> lines.set(i, replaceOne(line, rnd, Character::isDigit, () -> (char) ('0' + rnd.nextInt(10))));
                case 4 -> lines.set(i, replaceOne(line, rnd, c -> c == '.', null));
                default -> {
                    String words = "GMXZUWIKRFSTPQL";
                    String word = words.charAt(rnd.nextInt(words.length())) + Integer.toString(rnd.nextInt(200))
                            + (rnd.nextBoolean() ? "." + rnd.nextInt(100) : "");
                    int at = rnd.nextInt(line.length() + 1);
                    lines.set(i, line.substring(0, at) + " " + word + " " + line.substring(at));
                }
            }
        }
        return String.join("\n", lines) + "\n";
    }

    /** {@code line} with one character that {@code which} picks replaced by {@code by} (removed when null). */
    private static String replaceOne(String line, Random rnd, java.util.function.IntPredicate which,
                                     java.util.function.Supplier<Character> by) {
        List<Integer> at = new ArrayList<>();
        for (int k = 0; k < line.length(); k++) {
            if (which.test(line.charAt(k))) {
                at.add(k);
            }
        }
        if (at.isEmpty()) {
            return line;
        }
        int k = at.get(rnd.nextInt(at.size()));
        return line.substring(0, k) + (by == null ? "" : String.valueOf(by.get())) + line.substring(k + 1);
    }

    /**
     * Excursions that end where they start, so the program's own arcs still fit where they are.
     * (Also a modal F after the header, so that more of the programs are clean to their end.)
     */
    private static final String[] ROUND_TRIPS = {
        "G20\nG01 U0.04 W-0.04 F4.\nG01 U-0.04 W0.04\nG21",
        "G99 G01 U1. W-1. F0.1\nG01 U-1. W1.\nG98",
        "T0202\nT0101",
        "G55\nG54",
        "M05\nM03",
        "G04 X0.3",
        "G00 U4.\nG00 U-4.",
        "G96 S120\nG01 W-0.5 F100.\nG01 W0.5\nG97 S1000",
        "G28 U0. W0.\nG29 U0. W0.",
    };

    /**
     * A program in Fanuc system A and Haas terms: no G90/G91 (X/Z absolute, U/W incremental in
     * any block), the chuck closed with the control's own code, G04 P in seconds on Haas.
     */
    static String inSystemA(String program, String chuckClose) {
        String a = program.replace("G21 G90 G98\n", "G21 G98\n").replace("\nM11\n", "\n" + chuckClose + "\n")
                .replace("G91 G01 U2. W-1. F80.\nG90\n", "G01 U2. W-1. F80.\n");
        if (chuckClose.equals("M10")) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("G04 P(\\d+)").matcher(a);
            StringBuilder sb = new StringBuilder();
            while (m.find()) {
                m.appendReplacement(sb, "G04 P" + Integer.parseInt(m.group(1)) / 1000.0);
            }
            a = m.appendTail(sb).toString();
        }
        return a;
    }

    /**
     * Thread excursions that end where they start: a G32 pass and back, a G92 pass (which returns
     * to its start by itself), a G76 of a few passes; {@code pullOut} first (Haas M23: each G92/G76
     * pass ends with a chamfer; M24: straight out) and a G97 speed the Z axis can follow.
     */
    private static final String[] THREADS = {
        "G32 U-0.5 W-2. F1.\nG00 U0.5 W2.",
        "G92 U-1. W-3. F1.5\nG00 U0.",
        "G76 X%s Z%s P600 Q250 F1.\nG00 U0.",
    };

    static String withThreads(String program, Random rnd, String pullOut) {
        StringBuilder out = new StringBuilder();
        List<String> lines = program.lines().toList();
        double[] at = {60, 5};
        for (int i = 0; i < lines.size(); i++) {
            out.append(lines.get(i)).append('\n');
            if (i == 5) {
                out.append(pullOut).append('\n');
            }
            boolean body = i >= 5 && i < lines.size() - 4 && !lines.get(i).startsWith("G91");
            if (body && rnd.nextInt(6) == 0) {
                String t = THREADS[rnd.nextInt(THREADS.length)];
                // the G76's thread: 3 mm below and 4 mm along from wherever the tool is (U/W relative)
                out.append(t.contains("%s") ? t.replace("X%s Z%s", "U-3. W-4.") : t).append('\n');
            }
        }
        return out.toString();
    }

    static String withRoundTrips(String program, Random rnd) {
        StringBuilder out = new StringBuilder();
        List<String> lines = program.lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            out.append(lines.get(i)).append('\n');
            if (i == 5) {
                out.append("G01 F100.\n"); // a modal feed, so that arcs before any F word can run
            }
            boolean body = i >= 5 && i < lines.size() - 4 && !lines.get(i).startsWith("G91");
            if (body && rnd.nextInt(5) == 0) {
                out.append(ROUND_TRIPS[rnd.nextInt(ROUND_TRIPS.length)]).append('\n');
            }
        }
        return out.toString();
    }

    private static void run(String program, MachineProfile profile, String dialect, long seed) throws Exception {
        List<String> out = new ArrayList<>();
        List<String> mapLines = new ArrayList<>();
        List<gcnc.dmc.Instruction> typed = new ArrayList<>();
        gcnc.dmc.SourceMap map = new gcnc.dmc.SourceMap(mapLines::add);
        Compiler.Result r;
        try {
            r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES, profile, Dialect.Kind.of(dialect),
                    Optional.of(SimOptions.defaults().withPath())), map.wrap(l -> {
                        out.add(l.text());
                        typed.add(l);
                    }));
        } catch (RuntimeException e) {
            throw new AssertionError("seed " + seed + " (" + dialect + ") threw on:\n" + program, e);
        }
        long lines = program.lines().count() + 1;
        for (Diagnostic d : r.diagnostics().sorted()) {
            assertTrue(d.span().line() >= 1 && d.span().line() <= lines, () -> "seed " + seed + ": " + d);
            assertTrue(d.code().number() >= 1, () -> "seed " + seed + ": " + d);
        }
        if (dialect.equals("galil")) {
            for (Diagnostic d : r.diagnostics().sorted()) {
                assertTrue(!COMPILER_FAULTS.contains(d.code().id()),
                        () -> "seed " + seed + " on " + profile.name() + ": " + d + "\n" + program);
            }
        }
        if (r.ok() && dialect.equals("galil")) {
            assertEquals("EN", out.get(out.size() - 1), "seed " + seed);
            assertTrue(r.simulation().isPresent(), "seed " + seed);
        }
        if (!r.ok()) {
            assertTrue(r.diagnostics().sorted().stream().anyMatch(d -> d.severity() == Severity.ERROR), "seed " + seed);
        }
        // One verdict: check reports every error compile reports, but the simulator's (E3xx)
        Compiler.Result checked = Compiler.check(new StringReader(program), new Compiler.Settings(TABLES, profile,
                Dialect.Kind.of(dialect), Optional.empty()));
        assertEquals(errors(r, false), errors(checked, false), () -> "check and compile differ, seed " + seed + " on "
                + profile.name() + " (" + dialect + "):\n" + program);
        // ... and replaying the DMC compile writes (its lines packed) with its source map finds what compile's simulation found
        if (r.ok() && dialect.equals("galil")) {
            List<String> packed = new ArrayList<>();
            List<String> packedMap = new ArrayList<>();
            gcnc.dmc.LinePacker packer = new gcnc.dmc.LinePacker(profile.controllerLimits().lineWidth(),
                    new gcnc.dmc.SourceMap(packedMap::add).wrapLines(l -> packed.add(l.text())));
            typed.forEach(packer);
            packer.flush();
            gcnc.diag.Diagnostics replayed = new gcnc.diag.Diagnostics();
            gcnc.sim.DmcReplay.replay(reader(packed), profile, SimOptions.defaults(), replayed, table(packedMap));
            assertEquals(errors(r, true), errors(new Compiler.Result(replayed, 0, Optional.empty()), true),
                    () -> "replay differs, seed " + seed + " on " + profile.name() + ":\n" + program);
            streamForm(typed, r, profile, seed, program);
        }
    }

    /** The same program in the stream form (docs/galil.md), its two files replayed: the same findings as compile's. */
    private static void streamForm(List<gcnc.dmc.Instruction> typed, Compiler.Result r, MachineProfile profile, long seed,
                                   String program) {
        List<String> stream = new ArrayList<>();
        List<String> streamMap = new ArrayList<>();
        gcnc.dmc.SourceMap sm = new gcnc.dmc.SourceMap(streamMap::add);
        int width = profile.controllerLimits().lineWidth();
        gcnc.dmc.StreamSplit split = new gcnc.dmc.StreamSplit(sm.wrap(l -> stream.add(l.text())), 4000, width);
        typed.forEach(split);
        gcnc.dmc.StreamSplit.Result s = split.finish();
        List<String> resident = new ArrayList<>();
        List<String> residentMap = new ArrayList<>();
        gcnc.dmc.SourceMap rm = new gcnc.dmc.SourceMap(residentMap::add);
        gcnc.dmc.LinePacker packer = new gcnc.dmc.LinePacker(width, rm.wrapLines(l -> resident.add(l.text())));
        s.resident().forEach(packer);
        packer.flush();
        for (String l : stream) {
            assertTrue(gcnc.dmc.StreamRole.of(gcnc.dmc.DmcReader.read(l, (c, a) -> { })) != gcnc.dmc.StreamRole.EMBED,
                    () -> "seed " + seed + ": " + l + " in the stream");
        }
        gcnc.diag.Diagnostics replayed = new gcnc.diag.Diagnostics();
        gcnc.sim.StreamReplay.replay(reader(resident), table(residentMap), reader(stream), table(streamMap), profile,
                SimOptions.defaults(), replayed);
        assertEquals(errors(r, true), errors(new Compiler.Result(replayed, 0, Optional.empty()), true),
                () -> "stream form replay differs, seed " + seed + " on " + profile.name() + ":\n" + program);
    }

    private static java.io.BufferedReader reader(List<String> lines) {
        return new java.io.BufferedReader(new StringReader(String.join("\n", lines)));
    }

    private static gcnc.dmc.SourceMap.Locator table(List<String> map) {
        try {
            return gcnc.dmc.SourceMap.read(reader(map)).at();
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** The errors of a result as code@line: the simulator's (E3xx) only, or all others. */
    private static List<String> errors(Compiler.Result r, boolean simulator) {
        List<String> e = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            boolean sim = d.code().number() >= 300 && d.code().number() < 400;
            if (d.severity() == Severity.ERROR && sim == simulator) {
                e.add(d.code().id() + "@" + d.span().line());
            }
        }
        return e;
    }

    /** A turning program: a valid header, then random blocks (a few of them mutated) that track the position. */
    static String program(Random rnd) {
        StringBuilder p = new StringBuilder("G21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X60. Z5.\n");
        double[] at = {60, 5}; // X diameter, Z, as programmed
        int blocks = 5 + rnd.nextInt(40);
        for (int i = 0; i < blocks; i++) {
            String b = block(rnd, at);
            if (rnd.nextInt(10) == 0) {
                b = mutate(b, rnd);
            }
            p.append(b).append('\n');
        }
        return p.append("G00 X100.\nZ50.\nM05\nM30\n").toString();
    }

    private static String block(Random rnd, double[] at) {
        double x = Math.round(rnd.nextDouble() * 80000) / 1000.0;
        double z = Math.round((5 - rnd.nextDouble() * 90) * 1000) / 1000.0;
        switch (rnd.nextInt(8)) {
            case 0: // retract, then rapid along Z above the stock
                at[0] = 50 + Math.round(rnd.nextDouble() * 30);
                return "G00 " + n("X", at[0]) + "\nG00 " + n("Z", at[1] = Math.round(z));
            case 1:
                at[0] = x;
                at[1] = z;
                return "G01 " + n("X", x) + " " + n("Z", z) + " F" + (20 + rnd.nextInt(200)) + ".";
            case 2: // an R arc that may or may not span its chord (E101)
                at[0] = x;
                at[1] = z;
                return "G02 " + n("X", x) + " " + n("Z", z) + " " + n("R", Math.round(rnd.nextDouble() * 6000) / 100.0 - 10);
            case 3: { // an I/K arc that ends on its circle, from wherever the tool is
                double i = Math.round(rnd.nextDouble() * 2000 - 1000) / 100.0;
                double k = Math.round(rnd.nextDouble() * 2000 - 1000) / 100.0;
                double a = rnd.nextDouble() * 2 * Math.PI;
                double r = Math.hypot(i, k);
                double cx = at[0] / 2 + i;
                double cz = at[1] + k;
                at[0] = Math.round(2 * (cx + r * Math.cos(a)) * 1e6) / 1e6;
                at[1] = Math.round((cz + r * Math.sin(a)) * 1e6) / 1e6;
                return (rnd.nextBoolean() ? "G02 " : "G03 ") + n("X", at[0]) + " " + n("Z", at[1]) + " " + n("I", i) + " " + n("K", k);
            }
            case 4:
                return "G04 P" + (1 + rnd.nextInt(900));
            case 5:
                at[0] += 2;
                at[1] -= 1;
                return "G91 G01 U2. W-1. F80.\nG90";
            case 6:
                return "M0" + (7 + rnd.nextInt(3));
            default:
                return "G96 S" + (50 + rnd.nextInt(200)) + "\nG97 S1000";
        }
    }

    private static String n(String letter, double v) {
        return letter + String.format(Locale.ROOT, "%.6f", v).replaceAll("0+$", "");
    }

    private static String mutate(String b, Random rnd) {
        int at = rnd.nextInt(b.length() + 1);
        String chars = "XZ.-+GM(;%$ \t0123456789";
        String junk = String.valueOf(chars.charAt(rnd.nextInt(chars.length())));
        return rnd.nextBoolean() ? b.substring(0, at) + junk + b.substring(at) : b.substring(0, Math.max(0, at - 1)) + b.substring(at);
    }
}
