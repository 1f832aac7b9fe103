package gcnc.galil;

import gcnc.dmc.Instruction;
import gcnc.dmc.SourceMap;

import static gcnc.galil.Fixtures.motions;
import static gcnc.galil.Fixtures.rapid;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;

class GalilDialectTest {
    private static final MachineProfile GENERIC = Fixtures.profile("generic");
    /** The generic machine starting at the machine origin, so positions read easily. */
    private static final MachineProfile AT_ORIGIN = Fixtures.mapped(GENERIC, 'Y', 1, 'X', 1, Point.ORIGIN);

    @Test
    void headerSequencePerMotionAndFooter() {
        Point a = new Point(1000, 2000);
        Point b = new Point(1000, 500.4);
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", AT_ORIGIN, d, motions(3, a, rapid(Point.ORIGIN, a)),
                motions(4, b, new Motion.Linear(false, a, b, new Feed(0.1, 1666.7))));
        // Generic: Galil X = lathe Z, Y = lathe X; VP is relative to where each sequence starts; the
        // feed of 1666.7 counts/s is written at VS's resolution, even and not faster: 1666.
        // The spindle's channel C is an open-loop output (zero gains, no error limit), zeroed; the
        // soft limits are the travel in counts; the program refuses to start away from home.
        // IT 1 on both plane axes: no smoothing (command reference IT: it filters VM motion, and is burnable)
        assertEquals(List.of("#GCNC", "SH XY", "VM XY", "IT 1", "IT ,1", "VA 999424", "VD 999424",
                "gline=0", "KP ,,0", "KI ,,0", "KD ,,0", "ER ,,-1", "SH C", "OF ,,0.0000",
                "BL 0,-2000", "FL 350000,110000", "JP #NOHOME,@ABS[_TPX-0]>10", "JP #NOHOME,@ABS[_TPY-0]>10",
                "gline=3", "VS 100000", "VP 2000,1000", "VE", "BGS", "AMS",
                "gline=4", "VS 1666", "VP -1500,0", "VE", "BGS", "AMS", "EN"), out.subList(0, out.indexOf("EN") + 1));
        assertEquals(HEADER, out.indexOf("gline=3"));
        assertEquals(0, d.size());
    }

    /** The generic profile's header: the vector setup, the spindle's output, the soft limits, the homing check. */
    static final int HEADER = 18;

    /** The lines the blocks wrote (and the zero volts of the end): between the header and EN. */
    static List<String> body(List<String> out) {
        return out.subList(HEADER, out.indexOf("EN"));
    }

    @Test
    void roundingNeverAccumulates() {
        // Three moves of 0.4 counts: a dialect that rounded each increment would never move.
        Point p0 = Point.ORIGIN;
        Point p1 = p0.plus(0, 0.4);
        Point p2 = p1.plus(0, 0.4);
        Point p3 = p2.plus(0, 0.4);
        List<String> out = Fixtures.run("galil", AT_ORIGIN, new Diagnostics(), motions(1, p1, rapid(p0, p1)),
                motions(2, p2, rapid(p1, p2)), motions(3, p3, rapid(p2, p3)));
        assertEquals(List.of("VP 1,0"), out.stream().filter(l -> l.startsWith("VP")).toList());
    }

    @Test
    void spindleToolOutputsAndDwellInBlockOrder() {
        CheckedBlock b = new CheckedBlock(9, OptionalDouble.of(1200), OptionalInt.of(3),
                List.of(new MCall(11), new MCall(3), new MCall(41)), List.of(new Motion.Dwell(0.25)),
                List.of(new MCall(9)), Point.ORIGIN);
        List<String> out = Fixtures.run("galil", AT_ORIGIN, new Diagnostics(), b);
        // 1200 rpm / 410 rpm per volt = 2.9268 V on C, the third channel; M41 has no outputs.
        // gline first; the spindle still turns at the end: zero volts before EN
        assertEquals(List.of("gline=9", "OF ,,2.9268", "TOOL=3", "CB4", "CB2", "SB1", "WT 250", "CB3", "CB7",
                "OF ,,0.0000"), body(out));
    }

    @Test
    void spindleAboveTenVoltsIsAnErrorAndJustBelowIsClamped() {
        Diagnostics d = new Diagnostics();
        CheckedBlock over = new CheckedBlock(5, OptionalDouble.of(4400), OptionalInt.empty(), List.of(),
                List.of(), List.of(), Point.ORIGIN);
        // 4100 rpm at the generic profile's 410 rpm per volt: 10 V, just above the 9.998 V written
        CheckedBlock max = new CheckedBlock(6, OptionalDouble.of(4100), OptionalInt.empty(), List.of(),
                List.of(), List.of(), Point.ORIGIN);
        List<String> out = Fixtures.run("galil", AT_ORIGIN, d, over, max);
        assertEquals(List.of("OF ,,9.9980", "OF ,,0.0000"), body(out).stream().filter(l -> l.startsWith("OF")).toList());
        List<Diagnostic> all = d.sorted();
        assertEquals(Code.E203_SPINDLE_VOLTS, all.get(0).code());
        assertEquals(Span.of(5, 1), all.get(0).span());
        assertEquals(Code.E204_SPINDLE_VOLTS_CLAMPED, all.get(1).code());
        assertEquals(Severity.WARNING, all.get(1).severity());
    }

    @Test
    void countsBeyondThirtyTwoBitsAreLocatedErrors() {
        Point far = new Point(0, 3_000_000_000.0);
        Point back = new Point(0, 1000);
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", AT_ORIGIN, d, motions(12, far, rapid(Point.ORIGIN, far)),
                motions(13, back, rapid(far, back)));
        assertEquals(1, d.errorCount());
        Diagnostic e = d.sorted().get(0);
        assertEquals(Code.E201_GALIL_RANGE, e.code());
        assertEquals(Span.of(12, 1), e.span());
        assertEquals(List.of("VP", "3000000000"), e.args());
        // The faulty move is left out; the next one starts from where the controller really is.
        assertEquals(List.of("VP 1000,0"), out.stream().filter(l -> l.startsWith("VP")).toList());
    }

    @Test
    void arcTooBigForFourDecimalAnglesIsALocatedError() {
        // r = 2e9 counts: one printed angle step (0.0001 deg) moves the end ~3500 counts.
        double r = 2e9;
        Point c = new Point(0, 0);
        Point from = new Point(0, r);
        double a = Math.toRadians(0.00012345);
        Point to = new Point(r * Math.sin(a), r * Math.cos(a));
        Diagnostics d = new Diagnostics();
        MachineProfile start = Fixtures.mapped(GENERIC, 'Y', 1, 'X', 1, from);
        Fixtures.run("galil", start, d, motions(7, to, new Motion.Arc(false, from, to, c, r, new Feed(1, 100),
                new Motion.ArcWords(null, 0.0, -r))));
        assertEquals(Code.E202_ARC_NOT_REPRESENTABLE, d.sorted().get(0).code());
        assertEquals(Span.of(7, 1), d.sorted().get(0).span());
    }

    @Test
    void everyLineFitsEightyCharactersAtTheExtremes() {
        double big = Integer.MAX_VALUE;
        Point a = new Point(-big, -big);
        Point b = new Point(big / 2, big / 2);
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", Fixtures.mapped(GENERIC, 'H', -1, 'G', -1, a), d,
                new CheckedBlock(1, OptionalDouble.of(3999.9), OptionalInt.of(99999), List.of(), List.of(
                        new Motion.Linear(false, a, b, new Feed(1, 1e9)),
                        new Motion.Dwell(1e6)), List.of(), b));
        assertTrue(out.contains("VM GH"), out.toString());
        for (String l : out) {
            assertTrue(l.length() <= 80, l);
        }
    }

    @Test
    void inlineSourceMapNamesEachBlocksLine() {
        List<Instruction> out = new ArrayList<>();
        Dialect g = Dialect.create(Dialect.Kind.GALIL, AT_ORIGIN, new Diagnostics(), true);
        Point a = new Point(10, 10);
        g.begin(out::add);
        g.block(motions(17, a, rapid(Point.ORIGIN, a)), out::add);
        g.block(motions(18, a), out::add); // nothing to emit: no comment either
        g.end(out::add);
        assertEquals("NO L17", out.get(HEADER).text());
        assertEquals(17, out.get(HEADER).source().line());
        assertEquals("gline=17", out.get(HEADER + 1).text(), "the line running, for the handlers, after the mark");
        assertEquals("VS 100000", out.get(HEADER + 2).text());
        assertEquals(17, out.get(HEADER + 2).source().line());
        assertEquals(0, out.get(HEADER + 2).source().motion(), "the VS carries out the block's first motion");
        Instruction end = out.stream().filter(l -> l.text().equals("EN")).findFirst().orElseThrow();
        assertEquals(gcnc.dmc.Source.NONE, end.source());
        assertEquals(1, out.stream().filter(l -> l.text().startsWith("NO")).count());
    }

    @Test
    void sideSourceMapListsOutputLinesOfBlocks() {
        List<String> mapLines = new ArrayList<>();
        SourceMap map = new SourceMap(mapLines::add);
        List<Instruction> out = new ArrayList<>();
        java.util.function.Consumer<Instruction> sink = map.wrap(out::add);
        Dialect g = Dialect.create(Dialect.Kind.GALIL, AT_ORIGIN, new Diagnostics());
        Point a = new Point(10, 10);
        g.begin(sink);
        g.block(motions(4, a, rapid(Point.ORIGIN, a)), sink);
        g.end(sink);
        // Lines 1-18 are the header, 19-24 gline and the sequence of line 4, 25 EN and the routines.
        assertEquals(List.of("1 0", "19 4", "25 0"), mapLines);
        assertEquals("EN", out.get(24).text());
        assertEquals(out.size(), map.lines());
    }

    @Test
    void unknownDialectIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> Dialect.Kind.of("fanuc"));
    }

    @Test
    void feedBelowOneCountPerSecondIsALocatedError() {
        Point a = new Point(0, 100);
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", AT_ORIGIN, d,
                motions(21, a, new Motion.Linear(false, Point.ORIGIN, a, new Feed(4, 0.1))));
        assertEquals(Code.E207_FEED_TOO_SLOW, d.sorted().get(0).code());
        assertEquals(Span.of(21, 1), d.sorted().get(0).span());
        assertEquals(List.of("0.1"), d.sorted().get(0).args());
        assertEquals(0, out.stream().filter(l -> l.startsWith("VP")).count());
    }
}
