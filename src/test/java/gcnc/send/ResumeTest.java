package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.diag.Code;
import gcnc.machine.MachineProfile;
import java.io.BufferedReader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The resume program: the header, the state the program set before the resume point, the rest of an
 * interrupted motion re-planned from where the axes stopped, then the program's own lines.
 */
class ResumeTest {
    /** Line 6 a straight feed of 1000 counts, line 7 a quarter arc of radius 1000 (clockwise), line 8 M05. */
    static final List<String> DMC = List.of("#GCNC", "SH XY", "VM XY", "VA 2000000", "VD 2000000",
            "TOOL=1", "OF ,,3.0000", "CB2", "SB1",
            "VS 1000", "VP 1000,0", "VE", "BGS", "AMS",
            "VS 500", "CR 1000,90,-90", "VE", "BGS", "AMS",
            "CB1", "EN");
    static final String MAP = "# source part.nc\n1 0\n6 4\n7 5\n10 6\n15 7\n20 8\n21 0\n";

    static DmcProgram program() throws Exception {
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        return DmcProgram.read(DMC, MapReader.read(new BufferedReader(new StringReader(MAP))), haas);
    }

    static double[] home(DmcProgram p) {
        return p.sequences().get(0).start();
    }

    static double[] plus(double[] a, double dx, double dz) {
        return new double[] {a[0] + dx, a[1] + dz};
    }

    @Test
    void atTheBlocksStartTheStateComesFirstThenTheProgramFromThere() throws Exception {
        DmcProgram p = program();
        Download r = new Resume(p, 3).plan(new ResumePoint(6, 0), home(p));
        assertEquals(List.of("#GCNC", "SH XY", "VM XY", "VA 2000000", "VD 2000000",
                "TOOL=1", "SB1", "CB2", "OF ,,3.0000", "WT 2000",
                "VS 1000", "VP 1000,0", "VE", "BGS", "AMS", "VS 500", "CR 1000,90,-90", "VE", "BGS", "AMS", "CB1", "EN"),
                texts(r));
        // every line maps back to the compiled program's line it stands for
        assertEquals(9, r.originOf(10));
        assertEquals(6, p.sourceLine(r.originOf(10)));
    }

    @Test
    void halfWayAlongALineTheRestOfItIsReplanned() throws Exception {
        DmcProgram p = program();
        Download r = new Resume(p, 3).plan(new ResumePoint(6, 0), plus(home(p), 400, 1));
        List<String> l = texts(r);
        int vs = l.indexOf("VS 1000");
        assertEquals(List.of("VS 1000", "VP 600,-1", "VE", "BGS", "AMS", "VS 500"), l.subList(vs, vs + 6));
        assertEquals(6, p.sourceLine(r.originOf(vs + 1)));
    }

    @Test
    void onAnArcTheRestOfTheArcIsReplannedFromTheStopAngle() throws Exception {
        DmcProgram p = program();
        double[] arcStart = plus(home(p), 1000, 0);
        double[] centre = plus(arcStart, 0, -1000);
        double[] at = plus(centre, Math.round(1000 * Math.cos(Math.toRadians(30))), Math.round(1000 * Math.sin(Math.toRadians(30))));
        Download r = new Resume(p, 3).plan(new ResumePoint(7, 0), at);
        List<String> l = texts(r);
        int vs = l.indexOf("VS 500");
        String cr = l.get(vs + 1);
        // from the stop's angle (30 degrees, to the rounding of the axes' whole counts) to the arc's end at 0
        String[] a = cr.substring(3).split(",");
        assertEquals("1000", a[0], cr);
        assertEquals(30, Double.parseDouble(a[1]), 0.05, cr);
        assertEquals(-Double.parseDouble(a[1]), Double.parseDouble(a[2]), 1e-9, cr);
        // the arc from the stop ends where the programmed one does, or a closing VP takes it there
        assertTrue(l.get(vs + 2).equals("VE") || l.get(vs + 2).startsWith("VP "), l.toString());
        assertEquals("CB1", l.get(l.size() - 2));
    }

    @Test
    void atTheEndOfTheMotionTheProgramGoesOnAfterIt() throws Exception {
        DmcProgram p = program();
        Download r = new Resume(p, 3).plan(new ResumePoint(6, 0), plus(home(p), 1000, 0));
        assertEquals("VS 500", texts(r).get(texts(r).indexOf("WT 2000") + 1));
    }

    @Test
    void offThePathNothingIsInvented() throws Exception {
        DmcProgram p = program();
        RunFault f = assertThrows(RunFault.class, () -> new Resume(p, 3).plan(new ResumePoint(7, 0), plus(home(p), 500, 500)));
        assertEquals(Code.E827_CANNOT_RESUME, f.code());
        assertTrue(f.args().get(1).contains("not on the path of line 7"), f.args().toString());
        RunFault none = assertThrows(RunFault.class, () -> new Resume(p, 3).plan(new ResumePoint(3, 0), home(p)));
        assertTrue(none.args().get(1).contains("has no block"), none.args().toString());
        RunFault k = assertThrows(RunFault.class, () -> new Resume(p, 3).plan(new ResumePoint(7, 2), home(p)));
        assertTrue(k.args().get(1).contains("makes 1 motion"), k.args().toString());
    }

    /**
     * Lines 6 and 7 blended into one sequence (line 6's segment ends at 500 counts/s into line 7's
     * corner), and the spindle raised on the way, 1,500 counts along the path ({@code AV}).
     */
    static final List<String> BLENDED = List.of("#GCNC", "SH XY", "VM XY", "VA 2000000", "VD 2000000",
            "TOOL=1", "OF ,,3.0000", "CB2", "SB1",
            "VS 1000", "VP 1000,0 <1000 >500", "VP 1000,1000 <800", "VE", "BGS", "AV 1500", "OF ,,4.0000", "AMS",
            "CB1", "EN");
    static final String BLENDED_MAP = "# source part.nc\n1 0\n6 4\n7 5\n10 6\n12 7\n18 8\n19 0\n";

    static DmcProgram blended() throws Exception {
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        return DmcProgram.read(BLENDED, MapReader.read(new BufferedReader(new StringReader(BLENDED_MAP))), haas);
    }

    @Test
    void aBlockInsideABlendedSequenceStartsANewSequenceThere() throws Exception {
        DmcProgram p = blended();
        assertEquals(1, p.sequences().size());
        List<DmcProgram.Motion> seven = p.motionsOf(7);
        assertEquals(1, seven.size());
        assertEquals(1, seven.get(0).from(), "line 7's motion is the sequence's second segment");
        Download r = new Resume(p, 3).plan(new ResumePoint(7, 0), plus(home(p), 1000, 0));
        List<String> l = texts(r);
        int vs = l.indexOf("VS 1000");
        // the VP measured from the new origin, its own speed kept; the spindle change moved back by the 1000 counts run
        assertEquals(List.of("VS 1000", "VP 0,1000 <800", "VE", "BGS", "AV 500", "OF ,,4.0000", "AMS", "CB1", "EN"),
                l.subList(vs, l.size()));
        assertEquals(7, p.sourceLine(r.originOf(vs + 1)), "the segment maps to line 7 for _CSS");
        assertEquals("OF ,,3.0000", l.get(vs - 2), "the spindle as it was when the sequence began");
    }

    @Test
    void pastASpindleChangeOnTheWayItIsPartOfTheState() throws Exception {
        DmcProgram p = blended();
        Download r = new Resume(p, 3).plan(new ResumePoint(7, 0), plus(home(p), 1000, 600));
        List<String> l = texts(r);
        int vs = l.indexOf("VS 1000");
        assertEquals(List.of("OF ,,4.0000", "WT 2000"), l.subList(vs - 2, vs));
        assertEquals(List.of("VS 1000", "VP 0,400 <800", "VE", "BGS", "AMS", "CB1", "EN"), l.subList(vs, l.size()));
    }

    @Test
    void partWayAlongTheFirstBlockOfASequenceItsRestAndTheNextBlocksSegmentsFollow() throws Exception {
        DmcProgram p = blended();
        Download r = new Resume(p, 3).plan(new ResumePoint(6, 0), plus(home(p), 400, 0));
        List<String> l = texts(r);
        int vs = l.indexOf("VS 1000");
        assertEquals(List.of("VS 1000", "VP 600,0 <1000 >500", "VP 600,1000 <800", "VE", "BGS", "AV 1100", "OF ,,4.0000",
                "AMS", "CB1", "EN"), l.subList(vs, l.size()));
        assertEquals(List.of(6, 7), List.of(p.sourceLine(r.originOf(vs + 1)), p.sourceLine(r.originOf(vs + 2))));
        // the controller's segments of the new sequence name lines 6 and 7 (_CSS 0 and 1: the segment
        // counter starts at zero, DMC-40x0 User Manual p.86); after the end, either reading names line 7
        Download.Segments seg = r.segmentsAt(l.indexOf("AMS"), p);
        assertEquals(6, p.sourceLine(seg.executing(0)));
        assertEquals(7, p.sourceLine(seg.executing(1)));
        assertEquals(7, p.sourceLine(seg.executing(2)));
        assertTrue(seg.begun());
        assertTrue(!r.segmentsAt(vs + 1, p).begun(), "before BGS the motion has not begun");
    }

    /**
     * Two changes on the way: AV is relative (command reference AV, "from the start of a coordinated move
     * sequence or from the last AV command"), so the second trips at 1,500 + 300 = 1,800 counts. Resumed
     * 1,000 counts along, the first is written from the new sequence's start and the second as it was.
     */
    @Test
    void aSecondAvOnTheWayMeasuresFromTheFirstAfterAResumeToo() throws Exception {
        List<String> two = new ArrayList<>(BLENDED);
        two.addAll(two.indexOf("AMS"), List.of("AV 300", "OF ,,5.0000"));
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        DmcProgram p = DmcProgram.read(two, MapReader.read(new BufferedReader(new StringReader(
                "# source part.nc\n1 0\n6 4\n7 5\n10 6\n12 7\n18 8\n19 0\n"))), haas);
        Download r = new Resume(p, 3).plan(new ResumePoint(7, 0), plus(home(p), 1000, 0));
        List<String> l = texts(r);
        int vs = l.indexOf("VS 1000");
        assertEquals(List.of("VS 1000", "VP 0,1000 <800", "VE", "BGS", "AV 500", "OF ,,4.0000", "AV 300", "OF ,,5.0000",
                "AMS", "CB1", "EN"), l.subList(vs, l.size()));
        // resumed 1,600 counts along: the first change has happened, the second is 200 counts ahead
        Download past = new Resume(p, 3).plan(new ResumePoint(7, 0), plus(home(p), 1000, 600));
        List<String> q = texts(past);
        int at = q.indexOf("VS 1000");
        assertEquals(List.of("VS 1000", "VP 0,400 <800", "VE", "BGS", "AV 200", "OF ,,5.0000", "AMS", "CB1", "EN"),
                q.subList(at, q.size()));
    }

    /** A block of two segments blended (a G71-like pass and its step, one G-code line): N:K names the segment. */
    @Test
    void theStopNamesTheSegmentOfABlockAndTheResumeStartsFromIt() throws Exception {
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        DmcProgram p = DmcProgram.read(BLENDED, MapReader.read(new BufferedReader(new StringReader(
                "1 0\n6 4\n7 5\n10 6\n18 8\n19 0\n"))), haas);
        assertEquals(2, p.motionsOf(6).size());
        Progress progress = new Progress(p, BlockTable.none(), e -> { });
        progress.at(BLENDED.indexOf("VP 1000,1000 <800"), null, new Operator());
        assertEquals(new ResumePoint(6, 2), progress.resumePoint(), "executing the block's second segment");
        assertEquals(5, progress.completedLine());
        progress.at(BLENDED.indexOf("VP 1000,0 <1000 >500"), null, new Operator());
        assertEquals(new ResumePoint(6, 0), progress.resumePoint(), "its first: the block's start");
        Download r = new Resume(p, 3).plan(new ResumePoint(6, 2), plus(home(p), 1000, 300));
        List<String> l = texts(r);
        int vs = l.indexOf("VS 1000");
        assertEquals(List.of("VS 1000", "VP 0,700 <800", "VE", "BGS", "AV 200", "OF ,,4.0000", "AMS"), l.subList(vs, vs + 7));
    }

    /**
     * Line 7's segment refused while the sequence was still being queued (issue 33): nothing of the
     * sequence moved, the axes stand at its start, so the resume point is its first block (line 6), not
     * the segment the host had reached; once the axes have moved along it, the executing segment's block.
     */
    @Test
    void aSequenceOfWhichNothingMovedResumesAtItsFirstBlock() throws Exception {
        DmcProgram p = blended();
        Progress progress = new Progress(p, BlockTable.none(), e -> { });
        progress.at(BLENDED.indexOf("VP 1000,1000 <800"), home(p), new Operator());
        assertEquals(new ResumePoint(6, 0), progress.resumePoint(), "the axes at the sequence's start");
        progress.settle(plus(home(p), 1000, 200)); // the axes read after the stop
        assertEquals(new ResumePoint(7, 0), progress.resumePoint(), "the axes on line 7's segment");
        // and that point resumes from where the axes are: the sequence whole
        Download r = new Resume(p, 3).plan(new ResumePoint(6, 0), home(p));
        List<String> l = texts(r);
        assertEquals(List.of("VS 1000", "VP 1000,0 <1000 >500", "VP 1000,1000 <800", "VE", "BGS"),
                l.subList(l.indexOf("VS 1000"), l.indexOf("VS 1000") + 5));
    }

    /**
     * A controller that ran on after the link dropped (a downloaded program goes on without its host)
     * is resumed from where its axes are read again: at the end of the sequence it finished, and the
     * report says what it did without the host.
     */
    @Test
    void aControllerThatRanOnIsResumedWhereItStandsAndTheReportSaysWhatItDid() throws Exception {
        Compiled c = compiled(TURN);
        // the host last saw line 7; the controller went on and finished the corner of line 9 (its end: X46 Z-33)
        Resume resume = new Resume(c.program(), c.blocks(), 3);
        Download r = resume.plan(new ResumePoint(7, 0), c.galil(9, 46, -33));
        assertEquals("the controller finished the sequence's blocks: line 7 to 9", resume.ranOn().orElse(null));
        // what is resumed starts after line 9: line 10's move out, never the contour again
        int first = -1;
        for (int i = 0; i < r.commands().size() && first < 0; i++) {
            if (gcnc.send.DmcProgram.isSegment(r.commands().get(i))) {
                first = c.program().sourceLine(r.originOf(i));
            }
        }
        assertEquals(10, first, texts(r).toString());
        // at the point itself nothing is said
        Resume still = new Resume(c.program(), c.blocks(), 3);
        still.plan(new ResumePoint(7, 0), c.program().motionsOf(7).get(0).start());
        assertTrue(still.ranOn().isEmpty());
    }

    /**
     * Under G96 the spindle is restored as the surface speed, not as the r/min last set: resumed part
     * way out along line 9's face at X46, S200 m/min gives 1000 x 200 / (pi x 46) = 1383.9 r/min, on
     * haas's drive (OF of C) 1383.9 / 410 = 3.3755 V (the program's last speed was set for X40).
     */
    @Test
    void underG96TheSpindleIsRestoredAsTheSurfaceSpeedWhereTheAxesAre() throws Exception {
        String css = String.join("\n", "O1005", "G21 G99", "G50 S2500", "T0101", "G96 S200 M03", "G00 X42. Z2.",
                "G01 X40. F0.2", "G01 Z-30.", "G01 X50.", "G00 X60. Z5.", "M05", "M30", "");
        Compiled c = compiled(css);
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        Resume resume = new Resume(c.program(), c.blocks(), 3).spindle(haas);
        resume.plan(new ResumePoint(9, 0), c.galil(9, 46, -30));
        double volts = Double.NaN;
        for (gcnc.dmc.Command r : resume.restored()) {
            if (r instanceof gcnc.dmc.Command.Offset o) {
                volts = o.volts().value();
            }
        }
        assertEquals(1000 * 200 / (Math.PI * 46) / 410, volts, 0.0001, resume.restored().toString());
        // without the machine's spindle the resume restores the r/min last set (not the surface speed's here)
        Resume plain = new Resume(c.program(), c.blocks(), 3);
        plain.plan(new ResumePoint(9, 0), c.galil(9, 46, -30));
        double last = Double.NaN;
        for (gcnc.dmc.Command r : plain.restored()) {
            if (r instanceof gcnc.dmc.Command.Offset o) {
                last = o.volts().value();
            }
        }
        assertTrue(Math.abs(last - volts) > 0.1, last + " against " + volts);
    }

    @Test
    void resumePointsAreWrittenNOrNK() {
        assertEquals(new ResumePoint(37, 0), ResumePoint.parse("37"));
        assertEquals(new ResumePoint(37, 4), ResumePoint.parse("37:4"));
        assertEquals("37:4", new ResumePoint(37, 4).toString());
        assertThrows(IllegalArgumentException.class, () -> ResumePoint.parse("x"));
        assertThrows(IllegalArgumentException.class, () -> ResumePoint.parse("0"));
    }

    /** A turning tool: approach at X42 Z2 (line 6), in to X40, along to Z-30 (line 8), a corner (line 9), out. */
    static final String TURN = String.join("\n", "O1002", "G21 G99", "G50 S2500", "T0101", "G97 S1200 M03",
            "G00 X42. Z2.", "G01 X40. F0.2", "G01 Z-30.", "G02 X46. Z-33. R3.", "G01 X50.", "G00 X60. Z5.", "M05", "M30", "");
    /** A boring bar: approach at X20 Z2 (line 6), into the bore to Z-20, out to X24 (line 8), back to Z2 (line 9). */
    static final String BORE = String.join("\n", "O1003", "G21 G99", "G50 S2500", "T0101", "G97 S1200 M03",
            "G00 X20. Z2.", "G01 Z-20. F0.1", "G01 X24.", "G01 Z2.", "G00 X60. Z5.", "M05", "M30", "");

    /** A G-code program compiled for the haas profile, with the checker's frames of its lines. */
    record Compiled(DmcProgram program, BlockTable blocks) {
        /** Galil counts of program X (diameter), Z in the frame of line {@code line}. */
        double[] galil(int line, double x, double z) {
            gcnc.ir.ProgramFrame f = blocks.at(line).frame();
            return program.plane().galil(f.origin().x() + x * f.perX(), f.origin().z() + z * f.perZ());
        }

        RunFault refusal(int line, double[] axes) {
            return assertThrows(RunFault.class, () -> new Resume(program, blocks, 3).plan(new ResumePoint(line, 0), axes));
        }
    }

    static Compiled compiled(String text) throws Exception {
        Session session = Session.open(Session.Options.defaults().withMachine("haas"));
        CompiledRun seen = new CompiledRun();
        session.compile(new StringReader(text), java.util.Optional.of(session.simulation()), false, line -> { }, seen);
        return new Compiled(seen.program(session.profile()), seen.blocks(text));
    }

    @Test
    void offThePathTheAdviceIsInProgramTermsAndRetractsXOutwardFirst() throws Exception {
        Compiled c = compiled(TURN);
        // jogged into the stock: X30 Z-15, while line 9's corner starts at X40 Z-30
        RunFault f = c.refusal(9, c.galil(9, 30, -15));
        String why = f.args().get(1);
        assertEquals(Code.E827_CANNOT_RESUME, f.code());
        assertTrue(why.startsWith("the axes are at X30.000 Z-15.000 (Galil counts " + PositionText.counts(c.galil(9, 30, -15))
                + "), not on the path of line 9 (X40.000 Z-30.000 (Galil counts "), why);
        // out to the approach's X42 (line 6) at the axes' Z, then along Z, then in: never straight through the part.
        // The approach's X is where the controller ends it: from the whole counts it stands on at home, which
        // on the haas are a fraction of a count from the profile's home (X41.999 in the program's terms)
        double approach = c.blocks().at(6).program(c.program().plane().machine(c.program().sequencesOf(6).get(0).end()))[0];
        String x = String.format(java.util.Locale.ROOT, "X%.3f", approach);
        assertEquals("X41.999", x);
        assertTrue(why.contains(": move X away from the part first, to " + x + " Z-15.000 (Galil counts "
                + PositionText.counts(c.galil(9, approach, -15)) + "), then Z, to " + x + " Z-30.000 (Galil counts "
                + PositionText.counts(c.galil(9, approach, -30)) + "), then X, to X40.000 Z-30.000 (Galil counts "
                + PositionText.counts(c.galil(9, 40, -30)) + ") and resume again"), why);
        assertTrue(!why.contains("jog them to"), why);
        // axes already farther out than the approach stay out
        String out = c.refusal(9, c.galil(9, 80, -15)).args().get(1);
        assertTrue(out.contains("first, to X80.000 Z-15.000 (Galil counts " + PositionText.counts(c.galil(9, 80, -15))
                + "), then Z, to X80.000 Z-30.000"), out);
    }

    @Test
    void inABoreTheRetractIsTowardTheCentreLine() throws Exception {
        Compiled c = compiled(BORE);
        // line 9 starts at X24 Z-20 in the bore; the bar went in at X20, so away from the wall is toward X20
        String why = c.refusal(9, c.galil(9, 26, -10)).args().get(1);
        // (X20 to the approach's whole counts)
        assertEquals(20, retractX(why, "move X away from the part first, to X", " Z-10.000 (Galil counts "), 0.005, why);
        assertEquals(20, retractX(why, "), then Z, to X", " Z-20.000 (Galil counts "), 0.005, why);
        // at the bottom of the bore (line 8 starts at X20 Z-20, the approach's X): still toward the centre line,
        // the side opposite to where the bar went from its approach
        String at8 = c.refusal(8, c.galil(8, 22, -10)).args().get(1);
        assertEquals(20, retractX(at8, "first, to X", " Z-10.000"), 0.005, at8);
        // axes nearer the centre line than the approach stay there
        String inner = c.refusal(9, c.galil(9, 10, -10)).args().get(1);
        assertTrue(inner.contains("first, to X10.000 Z-10.000"), inner);
    }

    @Test
    void theApproachItselfRetractsToWhereTheToolCameFrom() throws Exception {
        Compiled c = compiled(TURN);
        double[] from = c.program().sequences().get(0).start();
        double[] p = c.blocks().at(6).program(c.program().plane().machine(from));
        // line 6 is the tool's first motion: the clear X is its start's, where the tool came from
        String why = c.refusal(6, c.galil(6, 50, -10)).args().get(1);
        assertTrue(why.contains(String.format(java.util.Locale.ROOT, "first, to X%.3f Z-10.000", p[0])), why);
        assertTrue(why.contains(String.format(java.util.Locale.ROOT, "then X, to X%.3f Z%.3f", p[0], p[1])), why);
    }

    /** The X of an advice's step written {@code before}X...{@code after}, or NaN when there is none. */
    static double retractX(String advice, String before, String after) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile(java.util.regex.Pattern.quote(before) + "(-?[0-9.]+)"
                + java.util.regex.Pattern.quote(after)).matcher(advice);
        return m.find() ? Double.parseDouble(m.group(1)) : Double.NaN;
    }

    /** The piece's commands as printed, one each (the download packs them into lines). */
    private static List<String> texts(Download r) {
        return r.commands().stream().map(gcnc.dmc.DmcPrinter::print).toList();
    }
}
