package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * No false alarms on everyday moves (issue 9): the most common lathe moves compile and simulate
 * clean whatever their numbers, and a cut the tool cannot make is still found.
 */
class TrustTest {
    private static final Tables TABLES = Tables.builtIn();
    /** The thesis-2004 control's header on the generic machine (blank D44 x 200, 150 out of the chuck). */
    private static final String HEAD = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\n";

    static List<String> compile(MachineProfile p, String program) throws Exception {
        Compiler.Result r = Compiler.compile(new StringReader(program),
                new Compiler.Settings(TABLES, p, Dialect.Kind.GALIL, Optional.of(SimOptions.defaults())), l -> { });
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.code().id() + "@" + d.span().line());
        }
        return out;
    }

    static List<String> compile(String program) throws Exception {
        return compile(ProfileLoader.load("generic", TableSource.builtIn(), TABLES), program);
    }

    /** A pass along Z and the usual retract (G00 U2.), wherever the pass ends. */
    @ParameterizedTest(name = "pass to Z{0}")
    @ValueSource(strings = {"-30.", "-29.5", "-17.3", "-25.", "-10.", "-41.25"})
    void aPassAndItsRetractAreClean(String z) throws Exception {
        String p = HEAD + "N60 G00 X46. Z2.\nN70 G00 X41.\nN80 G01 Z" + z + " F100.\nN90 G00 U2.\nN100 G00 Z2.\nM05\nM30\n";
        assertEquals(List.of(), compile(p));
    }

    /**
     * Facing below Z0 and retracting along Z, at every depth a facing pass takes. (Deeper than the
     * C insert's end edge reaches past the centre, 4.5 mm here, the pass leaves a pip at the
     * centre that the retract then touches: the model's insert has no nose radius.)
     */
    @ParameterizedTest(name = "face at Z{0}")
    @ValueSource(strings = {"-0.1", "-0.5", "-1.", "-2.3", "-4."})
    void facingBelowZeroAndRetractingIsClean(String z) throws Exception {
        String p = HEAD + "G00 X46. Z2.\nG00 Z" + z + "\nG01 X-1.6 F100.\nG00 Z2.\nG00 X46.\nM05\nM30\n";
        assertEquals(List.of(), compile(p));
    }

    @Test
    void aMultiPassRoughingIsClean() throws Exception {
        StringBuilder p = new StringBuilder(HEAD).append("G00 X46. Z2.\n");
        for (double d = 40; d >= 20; d -= 4) {
            p.append(String.format(java.util.Locale.ROOT, "G00 X%.1f\nG01 Z-40. F120.\nG01 U2.\nG00 Z2.\n", d));
        }
        p.append("G00 X46.\nM05\nM30\n");
        assertEquals(List.of(), compile(p.toString()));
    }

    @Test
    void aPartOffWithABladeIsClean() throws Exception {
        String p = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0909\nS800 M03\nG00 X46. Z-33.\nG01 X-1. F40.\nG00 X46.\nM05\nM30\n";
        String blade = "sim.tool.9 = P 3";
        assertEquals(List.of(), compile(machineWith(blade), p));
    }

    /**
     * A groove deeper than the blade reaches: its clamp block, wider than the blade, meets the
     * groove's walls (a blade 10 mm deep plunging 20 mm into the radius), and not when it reaches.
     */
    @Test
    void aGrooveDeeperThanTheBladeReachesPutsItsClampInTheWalls() throws Exception {
        String p = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0909\nS800 M03\nG00 X46. Z-20.\nG01 X4. F40.\nG00 X46.\nM05\nM30\n";
        assertEquals(List.of("E315@8"), compile(machineWith("sim.tool.9 = G 3 10"), p));
        assertEquals(List.of(), compile(machineWith("sim.tool.9 = G 3 25"), p));
    }

    @Test
    void anInchPassIsClean() throws Exception {
        String p = "O1\nG20 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X1.8 Z0.1\nG00 X1.6\nG01 Z-1.2 F4.\n"
                + "G00 U0.08\nG00 Z0.1\nM05\nM30\n";
        assertEquals(List.of(), compile(p));
    }

    @Test
    void aRapidIntoUncutMaterialIsFoundOnItsBlock() throws Exception {
        String p = HEAD + "G00 X46. Z2.\nG00 X40.\nG00 Z-10.\nG00 X46.\nM05\nM30\n";
        assertEquals(List.of("E305@9"), compile(p));
    }

    /** A finding says where, as the program writes it (X a diameter, Z from work zero), with its N word, then the machine frame. */
    @Test
    void aFindingIsPlacedInProgramCoordinatesFirst() throws Exception {
        String p = HEAD + "N60 G00 X46. Z2.\nN70 G00 X40.\nN110 G00 Z-40.\nN120 G00 X46.\nM05\nM30\n";
        MachineProfile m = ProfileLoader.load("generic", TableSource.builtIn(), TABLES);
        Compiler.Result r = Compiler.compile(new StringReader(p),
                new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL, Optional.of(SimOptions.defaults())), l -> { });
        Diagnostic d = r.diagnostics().sorted().get(0);
        assertEquals(gcnc.diag.Code.E305_SIM_RAPID_INTO_STOCK, d.code());
        String text = TABLES.messages().render(d.code(), d.args(), gcnc.tables.ErrorMessages.Lang.EN);
        assertEquals(true, text.matches("rapid move enters the blank at X4[0-4]\\.?[0-9]* Z-[0-9.]+ \\(N110; machine X2[01][0-9.]* Z1[0-4][0-9.]* mm\\)"), text);
    }

    /** A 10 mm radial cut with an insert 5 mm tall: the holder ploughs through the stock. */
    @Test
    void aCutDeeperThanTheInsertPutsTheHolderInTheStock() throws Exception {
        String p = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0202\nS1000 M03\nG00 X24. Z2.\nG01 Z-30. F100.\nG00 X46.\nM05\nM30\n";
        assertEquals(List.of("E315@8"), compile(machineWith("sim.tool.2 = C 5"), p));
        assertEquals(List.of(), compile(machineWith("sim.tool.2 = C 12.7"), p));
    }

    /**
     * Turning back toward the tailstock along a shoulder just plunged: the 80° C insert's trailing
     * edge rises 10° and reaches 2.24 mm above its tip, so a 2 mm step back is cut by that edge
     * and a 5 mm step meets the insert's back (E320); a 35° V insert's trailing edge reaches 13.6 mm
     * and cuts the 5 mm step. The DMC's replay finds what the compile found.
     */
    @ParameterizedTest(name = "down to X{0} with {1}")
    @CsvSource({"30., C 12.7, E320@11", "36., C 12.7, ''", "30., V 9.525, ''"})
    void turningBackDeeperThanTheTrailingEdgeReachesCutsWithTheBackOfTheInsert(String x, String tool, String found)
            throws Exception {
        String p = HEAD + "G00 X46. Z2.\nG00 X40.\nG01 Z-30. F100.\nG01 X" + x + "\nG01 Z-10.\nG00 X46.\nG00 Z2.\nM05\nM30\n";
        MachineProfile m = machineWith("sim.tool.1 = " + tool);
        List<String> expected = found.isEmpty() ? List.of() : List.of(found);
        assertEquals(expected, compile(m, p));
        StringBuilder dmc = new StringBuilder();
        StringBuilder map = new StringBuilder();
        Compiler.compile(new StringReader(p), new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL, Optional.empty()),
                new gcnc.dmc.SourceMap(l -> map.append(l).append('\n')).wrap(l -> dmc.append(l.text()).append('\n')));
        gcnc.diag.Diagnostics replayed = new gcnc.diag.Diagnostics();
        DmcReplay.replay(new java.io.BufferedReader(new StringReader(dmc.toString())), m, SimOptions.defaults(), replayed,
                gcnc.dmc.SourceMap.read(new java.io.BufferedReader(new StringReader(map.toString()))).at());
        List<String> fromReplay = new ArrayList<>();
        replayed.sorted().forEach(d -> fromReplay.add(d.code().id() + "@" + d.span().line()));
        assertEquals(expected, fromReplay, "the replay of the DMC");
    }

    /**
     * An arc that climbs back toward the tailstock from a shoulder just plunged meets the insert's
     * back too, and the verdict is the same whether or not the path is kept for a drawing (which
     * cuts the arc into finer pieces): the bands of all its pieces are judged together.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"G02", "G03"})
    void anArcBackTowardTheTailstockIsJudgedAsAWhole(String g) throws Exception {
        String p = HEAD + "G00 X46. Z2.\nG00 X40.\nG01 Z-30. F100.\nG01 X30.\n" + g + " X36. Z-27. R3.\nG00 X46.\n"
                + "G00 Z2.\nM05\nM30\n";
        MachineProfile m = ProfileLoader.load("generic", TableSource.builtIn(), TABLES);
        List<String> plain = compile(m, p);
        List<String> drawn = new ArrayList<>();
        Compiler.compile(new StringReader(p), new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withPath())), l -> { }).diagnostics().sorted()
                .forEach(d -> drawn.add(d.code().id() + "@" + d.span().line()));
        assertEquals(List.of("E320@11"), plain);
        assertEquals(plain, drawn);
    }

    /**
     * A boring bar opens a tube's bore to 32 mm and steps out to 36 mm at the bottom; pulled back
     * toward the tailstock it meets the wall it has not cut with the insert's back (E320), while
     * stepping out at the mouth and boring toward the chuck is clean.
     */
    @Test
    void aBoringBarPulledBackIntoUncutWallCutsWithItsBack() throws Exception {
        String head = "G21 G18 G40 G99\nT0808\nG97 S800 M03\nG00 X28. Z5.\nG00 Z2.\nG01 X32. Z0. F0.1\nZ-20.\n";
        String back = head + "X36.\nZ-5.\nX28.\nG00 Z5.\nG00 X70. Z50.\nM30\n";
        String forward = head + "X28.\nG00 Z2.\nG01 X36. Z0.\nZ-20.\nX28.\nG00 Z5.\nG00 X70. Z50.\nM30\n";
        MachineProfile fanuc = ProfileLoader.load("fanuc", TableSource.builtIn(), TABLES);
        SimOptions tube = SimOptions.defaults().withStock(new StockSize(65, 150, 100, 30));
        assertEquals(List.of("E320@9"), codes(Compiler.compile(new StringReader(back),
                new Compiler.Settings(TABLES, fanuc, Dialect.Kind.GALIL, Optional.of(tube)), l -> { })));
        assertEquals(List.of(), codes(Compiler.compile(new StringReader(forward),
                new Compiler.Settings(TABLES, fanuc, Dialect.Kind.GALIL, Optional.of(tube)), l -> { })));
    }

    @Test
    void withoutABlankTheStockChecksAreSkippedWithANote() throws Exception {
        String noStock = java.nio.file.Files.readString(java.nio.file.Path.of("tables/machines/generic.machine"))
                .replaceAll("(?m)^stock\\.\\w+ = .*$", "").replace("work.G54 = face", "work.G54 = 0, 150");
        String p = HEAD + "G00 X46. Z2.\nG00 X40.\nG00 Z-10.\nG00 X46.\nM05\nM30\n";
        assertEquals(List.of("E316@1"), compile(machine(noStock), p));
    }

    /**
     * A second operation or a casting: no bar describes the blank, so the shop says there is none
     * (--stock none); the stock checks are skipped with the note even where the profile has a blank,
     * and the DMC says so, so that its replay skips them too.
     */
    @Test
    void noBlankSkipsTheStockChecksWhateverTheProfileSays() throws Exception {
        String p = HEAD + "G00 X46. Z2.\nG00 X40.\nG00 Z-10.\nG00 X46.\nM05\nM30\n";
        MachineProfile m = ProfileLoader.load("generic", TableSource.builtIn(), TABLES);
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = Compiler.compile(new StringReader(p), new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withoutBlank())), l -> dmc.append(l.text()).append('\n'));
        List<String> codes = new ArrayList<>();
        r.diagnostics().sorted().forEach(d -> codes.add(d.code().id() + "@" + d.span().line()));
        assertEquals(List.of("E316@1"), codes, "the rapid into the blank is not judged without one");
        assertEquals(true, dmc.toString().contains("\nNO STOCK NONE\n"), dmc.toString());
        assertEquals(List.of("E305@9"), compile(m, p), "with the profile's blank it is");
    }

    /**
     * A tube (a blank with a bore: --stock D,L,S,BORE): a boring bar opens the 30 mm bore to 32 mm
     * clean; from a solid bar the same pass puts the bar into the material. The DMC carries the bore,
     * and its replay agrees.
     */
    @Test
    void aBoringPassInATubeIsCleanAndInABarIsNot() throws Exception {
        String p = "G21 G18 G40 G99\nT0808\nG97 S800 M03\nG00 X28. Z5.\nG00 Z2.\nG01 X32. Z0. F0.1\nZ-20.\nX28.\n"
                + "G00 Z5.\nG00 X70. Z50.\nM30\n";
        MachineProfile fanuc = ProfileLoader.load("fanuc", TableSource.builtIn(), TABLES);
        StringBuilder dmc = new StringBuilder();
        Compiler.Result tube = Compiler.compile(new StringReader(p), new Compiler.Settings(TABLES, fanuc, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withStock(new gcnc.sim.StockSize(65, 150, 100, 30)))),
                l -> dmc.append(l.text()).append('\n'));
        assertEquals(List.of(), codes(tube));
        assertEquals(true, dmc.toString().contains("\nNO STOCK D65 L150 S100 B30\n"), dmc.toString());
        Compiler.Result bar = Compiler.compile(new StringReader(p), new Compiler.Settings(TABLES, fanuc, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withStock(new gcnc.sim.StockSize(65, 150, 100)))), l -> { });
        assertEquals(List.of("E315@7"), codes(bar));
        assertEquals(new gcnc.dmc.Command.Stock(Optional.of(new gcnc.machine.MachineModel.Blank(65, 150, 100, 30))),
                gcnc.dmc.DmcReader.read("NO STOCK D65 L150 S100 B30", (c, a) -> { }));
        assertEquals(new gcnc.dmc.Command.Stock(Optional.of(new gcnc.machine.MachineModel.Blank(65, 150, 100, 0))),
                gcnc.dmc.DmcReader.read("NO STOCK D65 L150 S100", (c, a) -> { }));
    }

    private static List<String> codes(Compiler.Result r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.code().id() + "@" + d.span().line());
        }
        return out;
    }

    /** check and compile give one verdict: the backend's limits are found by check too. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"G01 Z-10. F0.001|E207@8", "G04 X-1.|E122@8", "G04 P-5|E013@8"})
    void checkFindsWhatCompileFinds(String spec) throws Exception {
        String[] p = spec.split("\\|");
        String program = HEAD + "G00 X46. Z2.\n" + p[0] + "\nM05\nM30\n";
        MachineProfile m = ProfileLoader.load("generic", TableSource.builtIn(), TABLES);
        Compiler.Result checked = Compiler.check(new StringReader(program),
                new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL, Optional.empty()));
        List<String> fromCheck = new ArrayList<>();
        for (Diagnostic d : checked.diagnostics().sorted()) {
            fromCheck.add(d.code().id() + "@" + d.span().line());
        }
        assertEquals(List.of(p[1]), fromCheck);
        assertEquals(fromCheck, compile(program));
    }

    /** The generic machine with one more line; a {@code sim.tool.N} line replaces the station's own tool table line. */
    private static MachineProfile machineWith(String line) throws Exception {
        String generic = java.nio.file.Files.readString(java.nio.file.Path.of("tables/machines/generic.machine"));
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("sim\\.tool\\.([0-9]+) =").matcher(line);
        if (m.lookingAt()) {
            generic = generic.replaceAll("(?m)^station\\." + m.group(1) + " =", "# station." + m.group(1) + " =");
        }
        return machine(generic + line + "\n");
    }

    private static MachineProfile machine(String text) throws Exception {
        return ProfileLoader.read(gcnc.machine.ProfileFile.parse("variant.machine", text), TABLES);
    }
}
