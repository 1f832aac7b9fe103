package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.galil.Dialect;
import gcnc.machine.ProfileLoader;
import gcnc.machine.Units;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Numbers in the program's terms first (issue 22): the envelope as the program writes X (a
 * diameter or a radius), Z from work zero, in its units; the machine frame beside it; the tools'
 * use for a setup sheet; and a drawing a setup person works from.
 */
class ProgramTermsTest {
    private static final Tables TABLES = Tables.builtIn();
    /** One pass at X40. from Z2. to Z-30., in mm. */
    private static final String MM = "O2\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X46. Z2.\n"
            + "G01 X40. F100.\nG01 Z-30.\nG00 X46.\nM05\nM30\n";
    /** The same pass in inches: X1.5 (38.1 mm) from Z0.1 to Z-1.2. */
    private static final String INCH = "O3\nG20 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X1.8 Z0.1\n"
            + "G01 X1.5 F4.\nG01 Z-1.2\nG00 X1.8\nM05\nM30\n";

    static SimReport simulate(String program, String machine, SimOptions options) throws Exception {
        Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES,
                ProfileLoader.load(machine, TableSource.builtIn(), TABLES), Dialect.Kind.GALIL, Optional.of(options)), l -> { });
        return r.simulation().orElseThrow();
    }

    static SimReport simulate(String program, String machine) throws Exception {
        return simulate(program, machine, SimOptions.defaults());
    }

    @Test
    void xIsADiameterWhereTheControlReadsOneAndARadiusWhereItDoesNot() throws Exception {
        ProgramEnvelope diameter = simulate(MM, "generic").program();
        assertTrue(diameter.diameter());
        assertEquals(40, diameter.xMin(), 0.002, "X40. as written, a diameter");
        assertEquals(-30, diameter.zMin(), 0.002);
        assertEquals(Units.MM, diameter.units());
        // thesis-2004 reads X as a radius: the same X40. is 40, a radius
        ProgramEnvelope radius = simulate(MM, "thesis-2004").program();
        assertFalse(radius.diameter());
        assertEquals(40, radius.xMin(), 0.002, "X40. as written, a radius");
        assertEquals("radius", radius.xMode());
    }

    @Test
    void theMachineFrameStaysBesideIt() throws Exception {
        SimReport r = simulate(MM, "generic");
        // generic: X is a radius from the centreline; G54's work zero is the blank's face at Z 150
        assertEquals(20, r.xMinMm(), 0.002);
        assertEquals(120, r.zMinMm(), 0.002);
    }

    @Test
    void anInchProgramIsMeasuredInInchesAndTheMachineInMillimetres() throws Exception {
        SimReport inch = simulate(INCH, "generic");
        ProgramEnvelope p = inch.program();
        assertEquals(Units.INCH, p.units());
        assertEquals("in", p.unit());
        assertEquals(1.5, p.xMin(), 0.0001);
        assertEquals(-1.2, p.zMin(), 0.0001);
        assertEquals(19.05, inch.xMinMm(), 0.002, "1.5 in as a diameter is a 19.05 mm radius");
        assertEquals(150 - 30.48, inch.zMinMm(), 0.002);
    }

    @Test
    void theEnvelopeIsWrittenAsTheProgramWritesItNotAsTheCountsRoundIt() throws Exception {
        // haas: 984.252 counts/mm; X-1.6 (a diameter) is -787.4 counts, replayed at -787: X-1.5992
        String facing = "O7\nG21 G99\nG50 S2500\nM10\nT0101\nG97 S1000 M03\nG00 X44. Z2.\nG01 Z0. F0.2\n"
                + "X-1.6 F0.15\nG00 Z2.\nM05\nM30\n";
        ProgramEnvelope p = simulate(facing, "haas").program();
        assertEquals(-1.6, p.xMin(), "exactly as written");
        assertEquals(-1.6, ProgramTerms.written(-1.5992, 0.001, 3));
        assertEquals(-1.599, ProgramTerms.written(-1.5992, 0.0003, 3), "not further than half a count");
        assertEquals(12.3456789, ProgramTerms.written(12.3456789, 1e-9, 3), "finer than the places: as it is");
    }

    @Test
    void aProgramSwitchingUnitsIsGivenInItsFirstUnits() throws Exception {
        // samples/units.nc starts in mm and cuts to Z-1.5 under G20: -38.1 mm
        SimReport r = simulate(Files.readString(Path.of("samples/units.nc")), "generic");
        assertEquals(Units.MM, r.program().units());
        assertEquals(-38.1, r.program().zMin(), 0.002);
    }

    @Test
    void aDmcReplayedByItselfHasNoProgramTerms() throws Exception {
        StringBuilder dmc = new StringBuilder();
        Compiler.compile(new StringReader(MM), new Compiler.Settings(TABLES,
                ProfileLoader.load("generic", TableSource.builtIn(), TABLES), Dialect.Kind.GALIL, Optional.empty()),
                l -> dmc.append(l.text()).append('\n'));
        SimReport r = DmcReplay.replay(new BufferedReader(new StringReader(dmc.toString())),
                ProfileLoader.load("generic", TableSource.builtIn(), TABLES), SimOptions.defaults(),
                new gcnc.diag.Diagnostics());
        assertNull(r.program(), "the work offsets are not in a DMC");
        assertEquals(20, r.xMinMm(), 0.002);
    }

    @Test
    void eachToolsFirstAndLastLineAndItsShareOfTheCycle() throws Exception {
        String two = "O4\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X46. Z2.\nG01 X40. F100.\n"
                + "G01 Z-30.\nG00 X46.\nT0202\nG00 X38. Z2.\nG01 Z-20. F80.\nG00 X46.\nM05\nM30\n";
        SimReport r = simulate(two, "generic");
        List<ToolUse> tools = r.setup().tools();
        assertEquals(2, tools.size(), tools.toString());
        assertEquals(1, tools.get(0).station());
        assertEquals(7, tools.get(0).firstLine());
        assertEquals(10, tools.get(0).lastLine());
        assertEquals(2, tools.get(1).station());
        assertEquals(12, tools.get(1).firstLine());
        assertEquals(14, tools.get(1).lastLine());
        assertEquals(r.cycleSeconds(), tools.get(0).seconds() + tools.get(1).seconds(), 1e-9);
        assertTrue(tools.get(0).seconds() > tools.get(1).seconds(), "the longer pass takes longer");
    }

    @Test
    void theSetupFactsGiveTheBlankAndTheWorkZero() throws Exception {
        SetupFacts s = simulate(MM, "generic", SimOptions.defaults().withStock(new StockSize(44, 200, 150))).setup();
        assertEquals(44, s.blank().orElseThrow().diameter());
        assertEquals(0, s.chuckFaceMm(), 1e-9);
        assertEquals(150, s.workZeroFromFaceMm(), 1e-6, "G54 is the blank's face, 150 mm out of the jaws");
    }

    @Test
    void travelIsExceededAtAPlaceAsTheProgramWritesItThenInTheMachineFrame() throws Exception {
        // SimFixture's tiny lathe: 1 count/mm, X travel -2..100 (a radius), work zero at X 0 Z 100
        // with X written as a diameter (0.5 counts per unit); the arc's top, X 105, is X210. as written
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 95, 150);
        gcnc.ir.ProgramFrame frame = new gcnc.ir.ProgramFrame(new gcnc.ir.Point(0, 100), 0.5, 1, "110", null);
        f.sim.block(new gcnc.ir.CheckedBlock(3, java.util.OptionalDouble.empty(), java.util.OptionalInt.empty(),
                List.of(), List.of(new gcnc.ir.Motion.Arc(false, new gcnc.ir.Point(95, 150), new gcnc.ir.Point(95, 130),
                        new gcnc.ir.Point(95, 140), 10, SimFixture.FEED, new gcnc.ir.Motion.ArcWords(10.0, null, null))),
                List.of(), new gcnc.ir.Point(95, 130), frame),
                SimFixture.lines(3, "VS 100", "CR 10,0,180", "VE", "BGS", "AMS"));
        gcnc.diag.Diagnostic d = f.diagnostics.sorted().get(0);
        assertEquals("X travel exceeded at X210. (N110; machine X 105 mm is outside -2 .. 100 mm)",
                TABLES.messages().render(d.code(), d.args(), gcnc.tables.ErrorMessages.Lang.EN));
        assertEquals("recorrido de X excedido en X210. (N110; máquina X 105 mm está fuera de -2 .. 100 mm)",
                TABLES.messages().render(d.code(), d.args(), gcnc.tables.ErrorMessages.Lang.ES));
    }

    // ---- the drawing ----

    @Test
    void aTailstockNearThePartIsInTheViewAndAFarOneIsNamedUnderIt() throws Exception {
        // SimFixture's lathe: blank z -20..100, the tailstock's centre at z 200 (quill r 15)
        SimFixture near = new SimFixture(SimFixture.PROFILE, SimOptions.defaults().withPath());
        near.start();
        near.move(true, 30, 102);
        near.move(false, 18, 60);
        SvgView v = SvgView.of(near.sim.report().drawing());
        assertTrue(v.zMax() >= 200, "the centre's point is in the view: " + v.zMax());
        SimFixture far = new SimFixture(SimFixture.PROFILE.replace("tailstock.centre_z = 200", "tailstock.centre_z = 290"),
                SimOptions.defaults().withPath());
        far.start();
        far.move(true, 30, 102);
        far.move(false, 18, 60);
        SimReport r = far.sim.report();
        assertTrue(SvgView.of(r.drawing()).zMax() < 290);
        assertTrue(svg(r, null).contains("the tailstock's centre, beyond the view, at Z 290 mm"));
    }

    private static String svg(SimReport r, String number) throws Exception {
        StringWriter w = new StringWriter();
        SvgWriter.write(r, "part.nc", number, w, true);
        return w.toString();
    }

    private static double[] size(String svg) {
        Matcher m = Pattern.compile("width=\"(\\d+)\" height=\"(\\d+)\"").matcher(svg);
        assertTrue(m.find());
        return new double[] {Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2))};
    }

    @Test
    void aShortWidePartIsNotDrawnAsATallColumn() throws Exception {
        // a 200 mm flange 30 mm long, 15 mm out of the jaws: the old view was 1000 x 7000 px
        String flange = "O5\nG21 G90 G99\nG50 S1000\nM11\nT0101\nG97 S300 M03\nG00 X204. Z2.\nG01 Z0. F0.2\n"
                + "X50.\nG00 Z2.\nX196.\nG01 Z-10.\nX204.\nG00 Z5.\nM05\nM30\n";
        SimReport r = simulate(flange, "generic", SimOptions.defaults().withStock(new StockSize(200, 30, 15)).withPath());
        double[] wh = size(svg(r, "O5"));
        assertEquals(1000, wh[0]);
        assertTrue(wh[1] <= SvgView.MAX_HEIGHT + SvgTitle.HEIGHT, "height " + wh[1]);
        // and a long thin one is not a sliver
        String bar = "O6\nG21 G90 G99\nG50 S2500\nM11\nT0101\nG97 S800 M03\nG00 X12. Z2.\nG01 X9. F0.1\n"
                + "Z-140.\nG00 X12.\nM05\nM30\n";
        double[] thin = size(svg(simulate(bar, "generic", SimOptions.defaults().withStock(new StockSize(10, 200, 150))
                .withPath()), "O6"));
        assertTrue(thin[1] >= SvgView.MIN_HEIGHT + SvgTitle.HEIGHT, "height " + thin[1]);
    }

    @Test
    void theDrawingShowsTheJawsTheTravelTheToolAtAFindingAndATitleBlock() throws Exception {
        // a rapid back into the blank at N110 (as DrawingTest's program)
        String program = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nN60 G00 X46. Z2.\nN70 G00 X41.\n"
                + "N80 G01 Z-30. F100.\nN90 G00 U2.\nN100 G00 Z2.\nN110 G00 X30. Z-20.\nN120 G00 X60.\nM05\nM30\n";
        SimReport r = simulate(program, "generic", SimOptions.defaults().withPath());
        String svg = svg(r, "O1");
        SvgView v = SvgView.of(r.drawing());
        assertTrue(v.zMin() < r.drawing().machine().chuckFace(), "the jaws' face is in the view");
        assertTrue(svg.contains("<g id=\"travel\">"), "the travel box");
        Matcher tools = Pattern.compile("<g id=\"tools\">\n(.*?)</g>", Pattern.DOTALL).matcher(svg);
        assertTrue(tools.find() && tools.group(1).contains("<polygon"), "the tool's outline at the finding");
        assertTrue(svg.contains(">O1</text>") && svg.contains(">part.nc</text>")
                && svg.contains(">generic / thesis-2004</text>") && svg.contains(">mm (G21), X diameter</text>"), svg);
        assertTrue(svg.contains("from work zero (right = +Z)"), "the view's extent in program terms");
        assertEquals(svg, svg(simulate(program, "generic", SimOptions.defaults().withPath()), "O1"),
                "no date nor anything else that changes between runs");
    }
}
