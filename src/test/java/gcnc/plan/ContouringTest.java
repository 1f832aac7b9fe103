package gcnc.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import gcnc.Compiler;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.dmc.SourceMap;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.DmcReplay;
import gcnc.sim.SimOptions;
import gcnc.sim.SimReport;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * Continuous contouring (docs/galil.md): what joins one sequence, where the machine stops and why,
 * the corner speeds the planner writes, and the simulator holding them to the machine.
 */
class ContouringTest {
    private static final Tables TABLES = Tables.builtIn();

    /** A compile's DMC, its source map, its result and the instructions written. */
    record Out(String dmc, List<String> map, Compiler.Result result, List<gcnc.dmc.Instruction> instructions) {
        List<String> lines() {
            return dmc.lines().toList();
        }

        long sequences() {
            return lines().stream().filter(l -> l.equals("BGS")).count();
        }

        List<String> stops() {
            return map.stream().filter(l -> l.startsWith(SourceMap.STOP)).map(l -> l.substring(l.lastIndexOf(' ') + 1))
                    .collect(Collectors.toList());
        }
    }

    static MachineProfile profile(String name) throws Exception {
        return ProfileLoader.load(name, TableSource.builtIn(), TABLES);
    }

    static Out compile(String program, MachineProfile p) throws Exception {
        StringBuilder dmc = new StringBuilder();
        List<String> map = new ArrayList<>();
        List<gcnc.dmc.Instruction> written = new ArrayList<>();
        SourceMap mapper = new SourceMap(map::add);
        Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES, p, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withoutBlank())), mapper.wrap(l -> {
                    dmc.append(l.text()).append('\n');
                    written.add(l);
                }));
        assertTrue(r.ok(), () -> r.diagnostics().sorted() + "\n" + dmc);
        return new Out(dmc.toString(), map, r, written);
    }

    static String read(String name) throws Exception {
        return Files.readString(Path.of("src/test/resources/plan", name), StandardCharsets.UTF_8);
    }

    /** A CAM finishing pass of 1,000 chords, as a post writes it (issue 33). */
    static String camFinish(int chords) {
        StringBuilder b = new StringBuilder("G21 G18 G40 G99\nT0101\nG97 S1200 M03\nG00 X48. Z1.\nG01 Z0. F0.2\n");
        for (int k = 1; k <= chords; k++) {
            b.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%n", 46 + Math.sin(k / 40.0), -k * 0.05));
        }
        return b.append("G00 X60.\nZ5.\nM05\nM30\n").toString();
    }

    @Test
    void aThousandChordFinishIsOneSequenceFedWhileItRuns() throws Exception {
        Out o = compile(camFinish(1000), profile("haas"));
        // no stop for its length: rapid in, the pass, rapid out (before issue 33: "buffer" every 255 chords)
        assertEquals(List.of("rapid-feed", "rapid-feed", "output"), o.stops());
        List<gcnc.dmc.Command> cs = o.instructions().stream().map(gcnc.dmc.Instruction::command).toList();
        int bgs = -1;
        int segments = 0;
        int before = 0;
        int waits = 0;
        for (int i = 0; i < cs.size(); i++) {
            gcnc.dmc.Command c = cs.get(i);
            if (c instanceof gcnc.dmc.Command.VectorSpeed) {
                segments = 0;
            } else if (c instanceof gcnc.dmc.Command.VectorPosition || c instanceof gcnc.dmc.Command.CircularArc) {
                segments++;
            } else if (c instanceof gcnc.dmc.Command.BeginSequence && segments > 511) {
                fail("BGS after " + segments + " segments: more than the buffer holds");
            } else if (c instanceof gcnc.dmc.Command.BeginSequence && cs.get(i - 1) instanceof gcnc.dmc.Command.VectorEnd) {
                continue;
            } else if (c instanceof gcnc.dmc.Command.BeginSequence) {
                bgs = i;
                before = segments;
            } else if (c instanceof gcnc.dmc.Command.Call call && call.label().equals("LMWAIT")) {
                waits++;
            }
        }
        assertEquals(510, before, "the first fill: every slot but VE's");
        assertEquals(5, waits, "a wait for room before each 100 segments after it");
        assertTrue(o.lines().contains("JP #LMWAIT,_LMS<101"), o.dmc());
        // the joins between the planner's windows keep the feed: no segment of the pass ends below it
        long slowJoins = o.lines().stream().flatMap(l -> java.util.Arrays.stream(l.split(";")))
                .filter(st -> st.startsWith("VP") && st.contains(">") && !st.contains(">3936")).count();
        assertTrue(slowJoins <= 2, "joins below the feed: " + slowJoins);
        assertTrue(bgs > 0);
    }

    /** The finishing contour: eight feed blocks with a chamfer, a fillet and a round run as one sequence at F. */
    @Test
    void aTangentFinishingContourIsOneSequenceAtItsFeed() throws Exception {
        Out o = compile(read("finish-contour.fanuc.nc"), profile("fanuc"));
        // the approach rapids, the eight feed blocks, the retract rapids: three sequences, not eleven
        assertEquals(3, o.sequences(), o.dmc());
        int from = o.lines().indexOf("VS 1000"); // F0.1 mm/rev at 1200 rpm
        assertTrue(from > 0, o.dmc());
        int ve = from + o.lines().subList(from, o.lines().size()).indexOf("VE");
        List<String> contour = o.lines().subList(from + 1, ve);
        assertEquals(8, contour.size(), contour.toString()); // one segment per block: VP, VP, VP, CR, VP, CR, VP, VP
        for (String seg : contour.subList(0, 7)) {
            assertTrue(seg.endsWith(" <1000 >1000"), "every joint keeps the feed: " + seg);
        }
        assertTrue(contour.get(7).endsWith(" <1000"), "the last stops: " + contour.get(7));
        assertEquals(List.of("rapid-feed", "rapid-feed", "output"), o.stops());
    }

    /** A 90-degree corner at 2000 mm/min slows to the junction speed of the machine, Grbl's formula. */
    /**
     * A zigzag of CAM chords whose last step before turning back moves X by a fraction of a count:
     * written as a pure Z move, the turn is a reversal, and the planner stops there as the written
     * path says (it once blended it from the unrounded direction, and the replay found E332).
     */
    @Test
    void aTurnBackAfterAMoveOfLessThanACountInXIsAReversal() throws Exception {
        Out o = compile("G21 G99\nG50 S2000\nT0101\nG97 S1200 M03\nG00 X38. Z2.\nG01 Z0. F0.2\n"
                + "G01 X37.006 Z-19.98\nG01 X37.003 Z-19.99\nG01 X37.001 Z0.\nG01 X37. Z-0.01\nG00 X50. Z5.\nM05\nM30\n",
                profile("haas"));
        assertTrue(o.stops().contains("reversal"), o.map().toString());
    }

    @Test
    void aSharpCornerSlowsToItsJunctionSpeed() throws Exception {
        MachineProfile fanuc = profile("fanuc");
        Out o = compile("G21 G98\nG50 S2000\nT0101\nG97 S1000 M03\nG00 X40. Z2.\nG01 Z-10. F2000.\nG01 X60.\n"
                + "G00 Z2.\nM05\nM30\n", fanuc);
        long feed = 2 * (long) Math.floor(Math.round(2000 / 60.0 * fanuc.z().countsPerMm()) / 2.0);
        String corner = o.lines().stream().filter(l -> l.startsWith("VP ") && l.contains("<" + feed + " >"))
                .findFirst().orElseThrow(() -> new AssertionError(o.dmc()));
        double a = Math.min(fanuc.acceleration(), fanuc.deceleration());
        double delta = 0.01 * Math.min(fanuc.x().countsPerMm(), fanuc.z().countsPerMm());
        double sinHalf = Math.sin(Math.toRadians(45));
        long expected = 2 * (long) Math.floor(0.9 * Math.sqrt(a * delta * sinHalf / (1 - sinHalf)) / 2);
        assertTrue(expected < feed, "the corner is slower than the feed");
        assertTrue(corner.endsWith(" >" + expected), corner + " (expected >" + expected + ")\n" + o.dmc());
        SimReport sim = o.result().simulation().orElseThrow();
        assertTrue(sim.cycleSeconds() < sim.exactStopSeconds(), "blending gains: " + sim);
    }

    @Test
    void aDwellAToolChangeAndM05EndTheSequenceWithTheirReason() throws Exception {
        Out o = compile(read("stops.fanuc.nc"), profile("fanuc"));
        assertEquals(List.of("rapid-feed", "dwell", "tool", "rapid-feed", "output", "end"), o.stops(), o.dmc());
    }

    @Test
    void blendingOffWritesEveryMotionAlone() throws Exception {
        MachineProfile off = ProfileLoader.read(ProfileFile.parse("off.machine",
                Files.readString(Path.of("tables/machines/fanuc.machine")) + "\nplan.blend = off\n"), TABLES);
        Out o = compile(read("finish-contour.fanuc.nc"), off);
        assertEquals(12, o.sequences()); // every motion of the program, the two rapids around the contour too
        assertTrue(o.lines().stream().noneMatch(l -> l.contains("<")), o.dmc());
    }

    /** A G96 finish: the new speed of each diameter is set on the way (AV, then OF), the feed goes on. */
    @Test
    void aConstantSurfaceSpeedIsFollowedWithoutStopping() throws Exception {
        Out o = compile("G21 G99\nG50 S2000\nT0101\nG96 S150 M03\nG00 X20. Z2.\nG01 Z0. F0.1\nG01 X30. Z-5.\n"
                + "G01 X40. Z-10.\nG00 X50. Z5.\nM05\nM30\n", profile("fanuc"));
        List<String> l = o.lines();
        int bgs = -1;
        for (int i = 0; i < l.size() - 2; i++) {
            if (l.get(i).equals("BGS") && l.get(i + 1).startsWith("AV ") && l.get(i + 2).startsWith("OF ")) {
                bgs = i;
            }
        }
        assertTrue(bgs > 0, o.dmc());
    }


    /** G09 stops its own block's move, G61 every move until G64; the rest blends (Haas and Fanuc manuals). */
    @Test
    void exactStopsTheProgramAsksForEndTheSequenceWithTheirReason() throws Exception {
        String head = "G21 G98\nG50 S2000\nT0101\nG97 S1000 M03\nG00 X40. Z2.\nG01 Z-10. F200.\n";
        assertEquals(List.of("rapid-feed", "rapid-feed", "output"),
                compile(head + "G01 X44. Z-12.\nG01 Z-20.\nG00 X50. Z5.\nM05\nM30\n", profile("fanuc")).stops());
        Out g09 = compile(head + "G09 G01 X44. Z-12.\nG01 Z-20.\nG00 X50. Z5.\nM05\nM30\n", profile("fanuc"));
        assertEquals(List.of("rapid-feed", "exact-stop-block", "rapid-feed", "output"), g09.stops());
        // the JSON's count of stops by reason (SimReport.stops) has the same
        assertEquals(java.util.Map.of("rapid-feed", 2, "exact-stop-block", 1, "output", 1),
                g09.result().simulation().orElseThrow().stops());
        assertEquals(List.of("rapid-feed", "exact-stop-mode", "exact-stop-mode", "rapid-feed", "output"),
                compile(head.replace("G01 Z-10.", "G61 G01 Z-10.") + "G01 X44. Z-12.\nG64 G01 Z-20.\nG01 X46.\n"
                        + "G00 X50. Z5.\nM05\nM30\n", profile("fanuc")).stops());
        // Haas: inch, feed per revolution; G61 alone on its line
        String haas = "G20 G99\nT0101\nG97 S500 M03\nG00 X2.2 Z0.1\nG01 Z-0.2 F0.01\n";
        assertEquals(List.of("rapid-feed", "exact-stop-block", "exact-stop-mode", "exact-stop-mode", "rapid-feed", "output"),
                compile(haas + "G09 X2.3\nG61\nZ-0.4\nX2.4\nG64\nZ-0.5\nX2.5\nG00 X3. Z1.\nM05\nM30\n",
                        profile("haas")).stops());
    }


    /** Coolant on and off inside a finishing pass: both switch on the way, the contour stays one sequence. */
    private static final String COOLANT = "G21 G98\nG50 S2000\nT0101\nG97 S1000 M03\nG00 X40. Z2.\nG01 Z-10. F200.\n"
            + "G01 X44. Z-12. M08\nG01 Z-20.\nM09\nG01 X48.\nG00 X50. Z5.\nM05\nM30\n";

    @Test
    void anM08InsideAContourDoesNotBreakItWhereTheProfileAllows() throws Exception {
        Out o = compile(COOLANT, profile("fanuc")); // fanuc: M08 = SB3, M09 = CB3, CB7; coolant flies by default
        assertEquals(List.of("rapid-feed", "rapid-feed", "output"), o.stops(), o.dmc());
        List<String> l = o.lines();
        int bgs = l.indexOf("VP -11000,2000 <1666") + 2;
        assertEquals("BGS", l.get(bgs), o.dmc());
        // M08 where the path reaches line 7 (12 mm of Z at 500 counts/mm); M09 where line 10 starts, at
        // 11,414 counts: 5,414 after the first trip point, since AV measures from the last AV (command
        // reference AV; DMC-40x0 User Manual p.86, "After Relative Vector distance")
        assertEquals(List.of("AV 6000", "SB3", "AV 5414", "CB3", "CB7", "AMS"), l.subList(bgs + 1, bgs + 7));
    }

    @Test
    void anOutputTheProfileDoesNotLetSwitchOnTheFlyEndsTheSequence() throws Exception {
        MachineProfile none = ProfileLoader.read(ProfileFile.parse("none.machine",
                Files.readString(Path.of("tables/machines/fanuc.machine")) + "\nplan.on_the_fly = none\n"), TABLES);
        Out o = compile(COOLANT, none);
        assertEquals(List.of("rapid-feed", "output", "output", "rapid-feed", "output"), o.stops(), o.dmc());
        assertTrue(o.lines().stream().noneMatch(x -> x.startsWith("AV ")), o.dmc());
        // M08 alone may fly, M09 may not: the sequence runs on through M08 and stops for M09
        MachineProfile on = ProfileLoader.read(ProfileFile.parse("m8.machine",
                Files.readString(Path.of("tables/machines/fanuc.machine")) + "\nplan.on_the_fly = M08\n"), TABLES);
        assertEquals(List.of("rapid-feed", "output", "rapid-feed", "output"), compile(COOLANT, on).stops());
    }

    /** Only an M code whose function is output may switch while the axes move: a spindle code is E253 at the key. */
    @Test
    void aSpindleCodeCannotSwitchOnTheFly() throws Exception {
        gcnc.tables.TableException e = org.junit.jupiter.api.Assertions.assertThrows(gcnc.tables.TableException.class,
                () -> ProfileLoader.read(ProfileFile.parse("m5.machine",
                        Files.readString(Path.of("tables/machines/fanuc.machine")) + "\nplan.on_the_fly = M08 M05\n"), TABLES));
        assertEquals(Code.E253_ON_THE_FLY_NOT_OUTPUT, e.diagnostic().code(), e.getMessage());
        assertTrue(e.getMessage().contains("M05") && e.getMessage().contains("spindle_stop"), e.getMessage());
    }

    /** The replay checks the trip points: one past the sequence's end (the program would wait for ever), one at another block. */
    @Test
    void aTripPointPastTheEndOrAtAnotherBlockIsFoundByTheSimulator() throws Exception {
        MachineProfile fanuc = profile("fanuc");
        Out o = compile(COOLANT, fanuc);
        assertEquals(List.of(), replayed(o, "AV 6000", 6000, fanuc));
        assertEquals(List.of(Code.E334_SIM_TRIP_PAST_END), replayed(o, "AV 5414", 90000, fanuc));
        // AV is relative: 6,500 counts is shorter than the 12,414 of the path, but after the first trip
        // point (6,000) it lies past the end
        assertEquals(List.of(Code.E334_SIM_TRIP_PAST_END), replayed(o, "AV 5414", 6500, fanuc));
        assertEquals(List.of(), replayed(o, "AV 5414", 6414, fanuc).stream()
                .filter(c -> c == Code.E334_SIM_TRIP_PAST_END).toList(), "the end of the path itself is reached");
        // M08 (line 7) switched where the path is still on line 6, and M09 with it (3,000 + 5,414: on line 8)
        assertEquals(List.of(Code.E335_SIM_SWITCHED_ELSEWHERE, Code.E335_SIM_SWITCHED_ELSEWHERE),
                replayed(o, "AV 6000", 3000, fanuc));
    }

    /** The compile's instructions replayed with the AV of {@code text} moved to {@code counts}: the codes found. */
    private static List<Code> replayed(Out o, String text, long counts, MachineProfile p) {
        List<gcnc.dmc.Instruction> tampered = new ArrayList<>();
        for (gcnc.dmc.Instruction i : o.instructions()) {
            tampered.add(i.text().equals(text)
                    ? new gcnc.dmc.Instruction(new gcnc.dmc.Command.AfterVector(counts), i.source()) : i);
        }
        Diagnostics d = new Diagnostics();
        gcnc.sim.Simulator sim = new gcnc.sim.Simulator(p, SimOptions.defaults().withoutBlank(), d);
        sim.replay(tampered);
        return d.sorted().stream().map(x -> x.code()).filter(c -> c == Code.E334_SIM_TRIP_PAST_END || c == Code.E335_SIM_SWITCHED_ELSEWHERE)
                .collect(Collectors.toList());
    }


    /**
     * A profile of 50,000 counts/mm on Z: the 298 mm rapids are 14.9 million counts, more than the
     * 8,388,607 a VP segment may be. Each is written as equal pieces in one sequence, and the replay
     * pairs them with their block (no conformance finding) and checks each joint on the line.
     */
    @Test
    void aStraightMoveLongerThanAVpSegmentIsSplitIntoEqualPiecesOfOneSequence() throws Exception {
        String text = Files.readString(Path.of("tables/machines/fanuc.machine"))
                .replaceFirst("(?m)^z.counts_per_mm = 500", "z.counts_per_mm = 50000");
        String program = "G21 G98\nG50 S2000\nT0101\nG97 S1000 M03\nG00 X40. Z300.\nG00 Z2.\nG01 Z-10. F20.\n"
                + "G00 X50.\nG00 Z300.\nM05\nM30\n";
        MachineProfile fine = ProfileLoader.read(ProfileFile.parse("fine.machine", text), TABLES);
        Out o = compile(program, fine);
        List<String> vp = o.lines().stream().filter(l -> l.startsWith("VP ")).collect(Collectors.toList());
        // the approach rapid (8.0 M counts, whole), then Z2. in two pieces of 7,450,000: one sequence
        assertEquals(List.of("VP -8000000,-95000 <200000 >200000", "VP -15450000,-95000 <200000 >200000",
                "VP -22900000,-95000 <200000", "VP -600000,0", "VP 0,2500 <200000 >3126",
                "VP 7750000,2500 <200000 >200000", "VP 15500000,2500 <200000"), vp, o.dmc());
        assertEquals(3, o.sequences());
        assertEquals(0, o.result().simulation().orElseThrow().findings());
        // every motion its own sequence: the long rapid is still one, of two pieces from rest to rest
        Out off = compile(program, ProfileLoader.read(ProfileFile.parse("off.machine", text + "\nplan.blend = off\n"), TABLES));
        assertEquals(5, off.sequences(), off.dmc());
        assertTrue(off.lines().contains("VP -7450000,0 <200000 >200000") && off.lines().contains("VP -14900000,0 <200000"),
                off.dmc());
        assertEquals(0, off.result().simulation().orElseThrow().findings());
    }


    /**
     * The corner report: the slowest corners, slowest first, where and why. F5000 on fanuc (41,666
     * counts/s): N60 (X70.) turns straight back into N70 (a reversal: the machine stops); the 90-degree
     * corners at N10 and N70 take the junction speed; N20 is 0.02 mm long, too short to get back up
     * from N10's corner before the slight turn into N30; the R1 arc of N50 is capped at √(a·r).
     */
    @Test
    void theCornerReportSaysWhereAndWhyTheMachineSlows() throws Exception {
        Out o = compile(read("corners.fanuc.nc"), profile("fanuc"));
        List<gcnc.sim.Corner> corners = o.result().simulation().orElseThrow().corners();
        List<String> seen = corners.stream().map(c -> "N" + c.number() + " " + c.why().key()).collect(Collectors.toList());
        assertEquals(List.of("N60 reversal", "N10 junction", "N70 junction", "N30 junction", "N20 acceleration",
                "N40 arc", "N50 arc"), seen, corners.toString());
        gcnc.sim.Corner reversal = corners.get(0);
        assertEquals(0, reversal.speedMmMin());
        assertEquals(180, reversal.angleDeg(), 0.01);
        assertEquals(13, reversal.line()); // N60, in the program's own file: no file named
        assertEquals(null, reversal.file());
        gcnc.sim.Corner square = corners.get(1);
        assertEquals(90, square.angleDeg(), 0.01);
        assertEquals(0.01, square.deviationMm(), 1e-9);
        assertEquals(0.02, corners.get(4).lengthMm(), 0.001);
        assertEquals(1.0, corners.get(5).radiusMm(), 0.001);
        // √(a·r) for r = 1 mm = 500 counts, as mm/min (a = the fanuc profile's 999,424 counts/s²)
        assertEquals(Math.sqrt(999424.0 * 500) / 500 * 60, corners.get(5).speedMmMin(), 1.0);
    }

    /** The simulator does not trust the planner: a corner written faster than the machine takes is E332 in a replay. */
    @Test
    void aCornerTooFastInTheDmcIsFoundByTheSimulator() throws Exception {
        MachineProfile fanuc = profile("fanuc");
        Out o = compile("G21 G98\nG50 S2000\nT0101\nG97 S1000 M03\nG00 X40. Z2.\nG01 Z-10. F2000.\nG01 X60.\n"
                + "G00 Z2.\nM05\nM30\n", fanuc);
        long feed = 2 * (long) Math.floor(Math.round(2000 / 60.0 * fanuc.z().countsPerMm()) / 2.0);
        String tampered = o.dmc().replaceFirst("<" + feed + " >\\d+", "<" + feed + " >" + feed);
        assertTrue(!tampered.equals(o.dmc()), o.dmc());
        Diagnostics d = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader(tampered)), fanuc, SimOptions.defaults().withoutBlank(), d);
        assertTrue(d.sorted().stream().anyMatch(x -> x.code() == Code.E332_SIM_CORNER_TOO_FAST), d.sorted().toString());
        Diagnostics clean = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader(o.dmc())), fanuc, SimOptions.defaults().withoutBlank(), clean);
        assertTrue(clean.sorted().stream().noneMatch(x -> x.code() == Code.E332_SIM_CORNER_TOO_FAST), clean.sorted().toString());
    }
}
