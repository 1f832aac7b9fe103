package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.ir.Point;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class ProfileLoaderTest {
    private static final Tables TABLES = Tables.builtIn();

    private static MachineProfile load(String name) throws TableException {
        return ProfileLoader.load(name, TableSource.builtIn(), TABLES);
    }

    @Test
    void thesisProfileHoldsTheNumbersTableFiveTwoPins() throws Exception {
        MachineProfile p = load("thesis-2004");
        assertEquals(1.5, p.x().countsPerMm());
        assertEquals(1200, p.z().countsPerInch());
        assertEquals(new Point(-20000, -20000), p.workOffset(54).orElseThrow());
        assertEquals(20000, p.rapidSpeed());
        assertEquals(20, p.feedPerF());
        assertEquals(300, p.rpmPerVolt());
        assertTrue(p.maxRpm() >= 5000);
        assertFalse(p.diameterX());
        assertEquals(1, p.noPointMm());
        assertEquals(List.of("CB4", "SB3"), p.outputsFor(3));
        assertEquals(-1, p.x().sign());
    }

    @Test
    void genericProfileIsAMetricDiameterLathe() throws Exception {
        MachineProfile p = load(ProfileLoader.DEFAULT);
        assertTrue(p.diameterX());
        assertEquals(0.001, p.noPointMm());
        assertEquals(1000 * 25.4, p.x().countsPerInch(), 1e-9);
        assertEquals(150_000, p.workOffset(54).orElseThrow().z());
        assertEquals(200, p.toolOffset(3).orElseThrow().x(), 1e-9, "Table 8 row 3 is 0.2 mm");
        assertEquals(12, p.tools());
        assertEquals('X', p.z().galil());
    }

    @Test
    void aProfileFileByPath() throws Exception {
        Path f = Files.createTempFile("lathe", ".machine");
        Files.writeString(f, Files.readString(Path.of("tables/machines/generic.machine")).replace("name = generic", "name = my-lathe"));
        assertEquals("my-lathe", ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES).name());
    }

    @Test
    void faultsAreLocated() throws Exception {
        String good = Files.readString(Path.of("tables/machines/generic.machine"));
        assertFault(good.replace("x.counts_per_mm = 1000", "x.counts_per_mm = ten"), "x.counts_per_mm = ten", "not a number");
        assertFault(good.replace("x.sign = 1", "x.sign = 2"), "x.sign = 2", "1 or -1");
        assertFault(good.replace("m.5 = CB1", "m.5 = CLEAR1"), "m.5 = CLEAR1", "SBn or CBn");
        assertFault(good.replace("tool_post = rear", "tool_post = left"), "tool_post = left", "front, rear");
        assertFault(good + "x.sign = 1\n", "x.sign = 1\n", "given twice");
    }

    @Test
    void everyShippedProfileLoadsByNameAndByPath() throws Exception {
        List<Path> files;
        try (Stream<Path> s = Files.list(Path.of("tables/machines"))) {
            files = s.filter(p -> p.toString().endsWith(".machine")).sorted().toList();
        }
        assertEquals(List.of("fanuc.machine", "generic.machine", "haas.machine", "thesis-2004.machine"),
                files.stream().map(p -> p.getFileName().toString()).toList());
        for (Path p : files) {
            String name = p.getFileName().toString().replace(".machine", "");
            assertEquals(name, load(name).name());
            assertEquals(name, ProfileLoader.load(p.toString(), TableSource.builtIn(), TABLES).name());
        }
    }

    // ---- numbers ----

    @Test
    void nanAndInfinityAreNotNumbers() throws Exception {
        assertFault(GOOD.replace("home = 105, 340", "home = NaN, 340"), "home = NaN", "'NaN' is not a number (home)");
        assertFault(GOOD.replace("x.travel = -2, 110", "x.travel = -2, Infinity"), "x.travel =",
                "'Infinity' is not a number (x.travel)");
        assertFault(GOOD.replace("feed.max = 50000", "feed.max = -Infinity"), "feed.max =", "not a number");
        assertFault(GOOD.replace("spindle.max_rpm = 4000", "spindle.max_rpm = 1e999"), "spindle.max_rpm =", "not a number");
        assertFault(GOOD.replace("sim.centre_x = 0", "sim.centre_x = 0x10"), "sim.centre_x =", "not a number");
        assertFault(GOOD + "\nsim.tool.4.insert = NaN, 0; 6, 1; 2, 5\n", "sim.tool.4.insert", "'NaN' is not a number");
    }

    @Test
    void countsPerMmAndInchArePositive() throws Exception {
        assertFault(GOOD.replace("z.counts_per_mm = 1000", "z.counts_per_mm = 0"), "z.counts_per_mm", "greater than 0");
        assertFault(GOOD.replace("x.programming", "x.counts_per_inch = -25400\nx.programming"), "x.counts_per_inch",
                "'x.counts_per_inch' must be greater than 0");
    }

    @Test
    void travelMustFitTheControllersPositionRegister() throws Exception {
        assertFault(GOOD.replace("z.travel = 0, 350", "z.travel = 0, 3000000"), "z.travel",
                "z.travel 3000000 mm is 3000000000 counts: beyond the 32-bit position register");
    }

    // ---- positions ----

    @Test
    void homeMustBeInsideTheTravel() throws Exception {
        assertFault(GOOD.replace("home = 105, 340", "home = 105, 351"), "home =", "'home' Z 351 is outside z.travel (0 .. 350)");
        assertFault(GOOD.replace("home = 105, 340", "home = 110.5, 340"), "home =", "'home' X 110.5 is outside x.travel");
        assertEquals(new Point(110_000, 350_000), loadText(GOOD.replace("home = 105, 340", "home = 110, 350")).home(),
                "the ends of the travel are inside it");
    }

    @Test
    void machineZeroMustBeInsideTheTravel() throws Exception {
        assertFault(GOOD.replace("home = 105, 340", "home = 105, 340\nmachine_zero = 0, -1"), "machine_zero",
                "'machine_zero' Z -1 is outside z.travel (0 .. 350)");
    }

    // ---- the simulator's keys, checked at load time ----

    @Test
    void chuckFaceAtOrBeyondTheEndOfTheZTravelIsAFault() throws Exception {
        assertFault(GOOD.replace("chuck.face_z = 0 ", "chuck.face_z = 350 "), "chuck.face_z",
                "chuck.face_z 350 is at or beyond the end of z.travel (350): no tool could reach");
        loadText(GOOD.replace("chuck.face_z = 0 ", "chuck.face_z = -100 ")); // behind the travel: the jaws are out of reach, fine
    }

    @Test
    void aChuckIsGivenWholeOrNotAtAll() throws Exception {
        assertFault(GOOD.replace("chuck.jaw_length = 25", "# no jaw length"), "chuck.face_z",
                "'chuck.face_z' needs 'chuck.jaw_length' too");
        assertFault(GOOD.replace("# tailstock.quill_diameter = 40", "tailstock.quill_diameter = 40"),
                "tailstock.quill_diameter", "'tailstock.quill_diameter' needs 'tailstock.centre_z' too");
    }

    @Test
    void theTailstockCentreIsInFrontOfTheJaws() throws Exception {
        String tail = GOOD.replace("# tailstock.quill_diameter = 40", "tailstock.quill_diameter = 40");
        assertFault(tail.replace("# tailstock.centre_z = 300", "tailstock.centre_z = -5"), "tailstock.centre_z",
                "tailstock.centre_z -5 must be in front of chuck.face_z 0");
        assertEquals(300, loadText(tail.replace("# tailstock.centre_z = 300", "tailstock.centre_z = 300"))
                .model().tailstock().orElseThrow().centreZ());
    }

    @Test
    void theBlankReachesIntoTheJaws() throws Exception {
        assertFault(GOOD.replace("stock.stickout = 150", "stock.stickout = 200"), "stock.stickout",
                "stock.stickout 200 must be less than stock.length 200");
    }

    @Test
    void stockHeaderIsReadWithTheProfile() throws Exception {
        assertFault(GOOD + "stock.header = skip\n", "stock.header", "'stock.header' must be one of use, ignore (not 'skip')");
        assertFalse(load("thesis-2004").model().stockHeader());
        assertTrue(load(ProfileLoader.DEFAULT).model().stockHeader());
    }

    @Test
    void aWorkOffsetOnTheBlanksFaceFollowsTheBlankOfTheRun() throws Exception {
        MachineProfile p = load(ProfileLoader.DEFAULT);
        assertEquals(java.util.Set.of(54), p.model().workZero().atFace());
        assertEquals(new Point(0, 150_000), p.workOffset(54).orElseThrow(), "the profile's blank: 150 mm out");
        MachineProfile q = p.withStickout(80);
        assertEquals(new Point(0, 80_000), q.workOffset(54).orElseThrow(), "--stock 44,200,80: the face is 80 mm out");
        assertEquals(new Point(0, 140_000), q.workOffset(55).orElseThrow(), "G55 is pinned: it stays");
        assertTrue(q.model().workZero().given());
        assertFalse(p.model().workZero().given());
        assertTrue(p == p.withStickout(150), "the profile's own stick-out changes nothing");
        // 'x, face' keeps an X; thesis-2004 pins its offsets (counts of Table 5.2)
        assertEquals(new Point(5000, 150_000), loadText(GOOD.replace("work.G54 = face", "work.G54 = 5, face"))
                .workOffset(54).orElseThrow());
        assertTrue(load("thesis-2004").model().workZero().atFace().isEmpty());
        assertEquals(new Point(-20000, -20000), load("thesis-2004").withStickout(10).workOffset(54).orElseThrow());
        // the face needs the chuck and the profile's blank; a bad X is a fault at its line like any number
        String noBlank = GOOD.replace("stock.diameter = 44", "#").replace("stock.length = 200", "#")
                .replace("stock.stickout = 150", "#");
        assertFault(noBlank, "work.G54", "'work.G54' puts the work zero's Z on the face of the blank (face): that needs the chuck");
        assertFault(GOOD.replace("work.G54 = face", "work.G54 = ten, face"), "work.G54", "'ten' is not a number");
        assertFault(GOOD.replace("work.G54 = face", "work.G54 = fac"), "work.G54", "work.G54");
    }

    @Test
    void theToolTableDescribesEachStation() throws Exception {
        MachineProfile p = loadText(GOOD + String.join("\n",
                "station.2 = turn D 12.7, nose 0.4, tip 3",
                "station.4 = drill 10, angle 140, reach 60",
                "station.5 = groove 3, reach 12",
                "station.6 = part 3",
                "station.7 = thread 16",
                "station.8 = bore 16, nose 0.4, tip 2",
                "station.9 = centre 3.15",
                "station.10 = tap 10",
                "station.11 = puller",
                "station.12 = turn T 9.525, side -x", ""));
        MachineModel m = p.model();
        assertEquals(MachineModel.ToolKind.TURN, m.tools().get(2).kind());
        assertEquals("turn D 12.7", m.tools().get(2).name());
        assertEquals(MachineModel.ToolKind.DRILL, m.tools().get(4).kind());
        assertEquals(MachineModel.ToolKind.GROOVE, m.tools().get(5).kind());
        assertEquals(12, m.tools().get(5).insert().dx()[2], 1e-9, "the blade reaches 12 mm");
        assertEquals(MachineModel.ToolKind.PART, m.tools().get(6).kind());
        assertEquals(MachineModel.ToolKind.THREAD, m.tools().get(7).kind());
        assertEquals(MachineModel.ToolKind.BORE, m.tools().get(8).kind());
        assertEquals(MachineModel.ToolKind.CENTRE_DRILL, m.tools().get(9).kind());
        assertEquals(MachineModel.ToolKind.TAP, m.tools().get(10).kind());
        assertEquals(MachineModel.ToolKind.PULLER, m.tools().get(11).kind());
        assertEquals(-1, m.tools().get(12).side());
        assertEquals(1, m.tools().get(2).side());
        // the nose a station names is its tool offset's (T0202), as nose.2 would give it
        assertEquals(0.4 * p.x().countsPerMm(), p.nose(2).radius(), 1e-9);
        assertEquals(3, p.nose(2).tip());
        assertEquals(2, p.nose(8).tip());
        assertEquals(0, p.nose(4).radius());
        assertFalse(m.tools().containsKey(3), "station 3 is not described");
        assertTrue(m.tools().containsKey(1), "generic describes station 1");
    }

    @Test
    void theToolTableMayBeAFileBesideTheProfile() throws Exception {
        Path dir = Files.createTempDirectory("shop");
        Path profile = dir.resolve("lathe.machine");
        Files.writeString(profile, GOOD + "tools.file = turret.tools\n");
        Files.writeString(dir.resolve("turret.tools"), "# our turret\nstation.4 = drill 10\nstation.7 = tap 10, reach 15\n");
        MachineProfile p = ProfileLoader.load(profile.toString(), TableSource.builtIn(), TABLES);
        assertEquals(MachineModel.ToolKind.DRILL, p.model().tools().get(4).kind());
        assertEquals(MachineModel.ToolKind.TAP, p.model().tools().get(7).kind());
        assertTrue(p.model().tools().containsKey(1), "the profile's own station 1 stays");
        // a fault in the file is at its own line
        Files.writeString(dir.resolve("turret.tools"), "station.4 = drill 10\nstation.7 = tap ten\n");
        TableException bad = assertThrows(TableException.class,
                () -> ProfileLoader.load(profile.toString(), TableSource.builtIn(), TABLES));
        assertEquals(2, bad.diagnostic().span().line());
        assertTrue(bad.getMessage().contains("turret.tools"), bad.getMessage());
        Files.writeString(dir.resolve("turret.tools"), "station.4 = drill 10\nhome = 0, 0\n");
        assertTrue(assertThrows(TableException.class,
                () -> ProfileLoader.load(profile.toString(), TableSource.builtIn(), TABLES)).english()
                .contains("a tool table file holds station.<n> lines only (not 'home')"));
        Files.writeString(dir.resolve("turret.tools"), "station.1 = drill 10\n");
        assertTrue(assertThrows(TableException.class,
                () -> ProfileLoader.load(profile.toString(), TableSource.builtIn(), TABLES)).english()
                .contains("'station.1' is number 1 again"));
        Files.delete(dir.resolve("turret.tools"));
        assertFault(GOOD + "tools.file = turret.tools\n", "tools.file", "turret.tools does not exist");
    }

    @Test
    void aBadStationIsAFaultAtItsLine() throws Exception {
        String form = "describes a turret station: a kind and its size";
        assertFault(GOOD + "station.3 = mill 10\n", "station.3", form + " (turn C 12.7; turn with C D V W T or S;");
        assertFault(GOOD + "station.3 = turn Q 12.7\n", "station.3", "(not 'turn Q 12.7')");
        assertFault(GOOD + "station.3 = turn C\n", "station.3", form);
        assertFault(GOOD + "station.3 = drill -4\n", "station.3", form);
        assertFault(GOOD + "station.3 = drill ten\n", "station.3", "'ten' is not a number");
        assertFault(GOOD + "station.3 = drill 10, colour red\n", "station.3", form);
        assertFault(GOOD + "station.3 = drill 10, reach 0\n", "station.3", form);
        assertFault(GOOD + "station.3 = turn C 12.7, side left\n", "station.3", form);
        assertFault(GOOD + "station.3 = turn C 12.7, tip 10\n", "station.3", "a tip direction is a whole number 0 to 9 (not 10) (station.3)");
        assertFault(GOOD + "station.3 = turn C 12.7, nose 30\n", "station.3", "a nose radius is at least 0 and below 25 mm (not 30)");
        assertFault(GOOD + "station.3 = drill 10, angle 200\n", "station.3", "a point angle is a drill's: more than 60");
        assertFault(GOOD + "station.3 = turn C 12.7, angle 90\n", "station.3", "a point angle is a drill's");
        assertFault(GOOD + "station.0 = drill 10\n", "station.0", "turret stations are numbered from 1 ('station.0')");
        assertFault(GOOD + "station.3 = drill 10\nstation.03 = tap 10\n", "station.03", "'station.03' is number 3 again");
        assertFault(GOOD + "station.100 = drill 10\n", "station.100", "the tool table is station.<n> = kind size; options");
        // one description per station; and one nose per tool offset
        assertFault(GOOD + "sim.tool.1 = D 12.7\n", "sim.tool.1", "station 1 is described twice: by station.1 and by sim.tool.1");
        assertFault(GOOD + "station.3 = turn C 12.7, nose 0.8, tip 3\nnose.3 = 0.4, 3\n", "station.3",
                "the nose of tool offset 3 is given twice: by nose.3 and by station.3");
        // an outline redraws a station: allowed
        loadText(GOOD + "sim.tool.1.holder = 0, 20; 10, 20; 10, 40; 0, 40\n");
    }

    // ---- speeds, counts, channels ----

    @Test
    void speedsAndRatesArePositiveAndFitAGalilRegister() throws Exception {
        assertFault(GOOD.replace("rapid.speed = 100000", "rapid.speed = 0"), "rapid.speed", "must be greater than 0");
        assertFault(GOOD.replace("rapid.speed = 100000", "rapid.speed = 3000000000"), "rapid.speed",
                "'rapid.speed' is a vector speed (VS) in counts/s: 1 to 2147483647 (not 3000000000)");
        assertFault(GOOD.replace("vector.acceleration = 999424", "vector.acceleration = 0.4"), "vector.acceleration",
                "1 to 2147483647 (not 0.4)");
        assertFault(GOOD.replace("vector.deceleration = 999424", "vector.deceleration = -5"), "vector.deceleration",
                "must be greater than 0");
        assertFault(GOOD.replace("spindle.max_rpm = 4000", "spindle.max_rpm = 0"), "spindle.max_rpm", "greater than 0");
        assertFault(GOOD.replace("spindle.rpm_per_volt = 410", "spindle.rpm_per_volt = -400"), "spindle.rpm_per_volt",
                "greater than 0");
    }

    @Test
    void toolsCountIsAWholeNumberFromOne() throws Exception {
        assertFault(GOOD.replace("tools.count = 12", "tools.count = 0"), "tools.count",
                "tools.count is a whole number of turret stations from 1 to 99 (not 0)");
        assertFault(GOOD.replace("tools.count = 12", "tools.count = 2.5"), "tools.count", "(not 2.5)");
    }

    @Test
    void aNoseIsARadiusAndATipDirectionOfAToolOffset() throws Exception {
        MachineProfile p = ProfileLoader.read(ProfileFile.parse("t.machine", GOOD + "nose.2 = 0.8, 3\n"), TABLES);
        assertEquals(0.8 * p.x().countsPerMm(), p.nose(2).radius(), 1e-9);
        assertEquals(3, p.nose(2).tip());
        assertEquals(0, p.nose(3).radius());
        assertEquals(0, p.nose(0).radius());
        assertFault(GOOD + "nose.2 = 0.8, 10\n", "nose.2", "a tip direction is a whole number 0 to 9 (not 10) (nose.2)");
        assertFault(GOOD + "nose.2 = 0.8, 2.5\n", "nose.2", "(not 2.5)");
        assertFault(GOOD + "nose.2 = -0.8, 3\n", "nose.2", "a nose radius is at least 0 and below 25 mm (not -0.8)");
        assertFault(GOOD + "nose.0 = 0.8, 3\n", "nose.0", "nose radii are per tool offset: numbered from 1");
        assertFault(GOOD + "nose.2 = 0.8\n", "nose.2", "needs two numbers");
        assertFault(GOOD + "nose.2 = 0.8, 3\nnose.02 = 0.4, 3\n", "nose.02", "'nose.02' is number 2 again");
        assertFault(GOOD + "nose.100 = 0.8, 3\n", "nose.100", "nose radii are nose.<n> = radius; tip");
    }

    @Test
    void theAxesAndTheSpindleAreThreeChannels() throws Exception {
        assertFault(GOOD.replace("x.galil = Y", "x.galil = A"), "z.galil", "x.galil and z.galil are the same Galil channel");
        assertFault(GOOD.replace("spindle.axis = C", "spindle.axis = Y"), "spindle.axis",
                "spindle.axis Y is the channel that drives lathe X (x.galil = Y)");
    }

    @Test
    void aSpindleEncoderIsAWholeCountOnAChannelThatDoesNotMoveTheTool() throws Exception {
        assertFault(GOOD + "spindle.encoder = 4.5\n", "spindle.encoder",
                "spindle.encoder is the encoder's counts per spindle revolution: a whole number from 4 to 1048576");
        assertFault(GOOD + "spindle.encoder = 2\n", "spindle.encoder", "a whole number from 4 to 1048576");
        assertFault(GOOD + "spindle.encoder = 4096\nspindle.encoder_axis = Y\n", "spindle.encoder_axis",
                "spindle.encoder_axis Y is the channel that drives lathe X (x.galil = Y)");
        assertFault(GOOD + "spindle.encoder_axis = D\n", "spindle.encoder_axis",
                "spindle.encoder_axis needs spindle.encoder");
        MachineProfile p = ProfileLoader.read(ProfileFile.parse("t.machine", GOOD + "spindle.encoder = 2048\n"), TABLES);
        assertEquals(new SpindleEncoder(2048, 'C'), p.encoder().orElseThrow());
        assertTrue(ProfileLoader.read(ProfileFile.parse("t.machine", GOOD), TABLES).encoder().isEmpty());
        assertEquals(4096, load("haas").encoder().orElseThrow().countsPerRev());
        assertEquals(4096, load("fanuc").encoder().orElseThrow().countsPerRev());
        assertTrue(load("generic").encoder().isEmpty());
        assertTrue(load("thesis-2004").encoder().isEmpty());
    }

    @Test
    void theThreadChamferIsALengthInLeadsAndAnAngleToZ() throws Exception {
        assertFault(GOOD + "thread.chamfer_leads = -1\n", "thread.chamfer_leads",
                "thread.chamfer_leads is the length of the chamfered pull-out in leads: 0 to 100 (not -1; 0 pulls straight out)");
        assertFault(GOOD + "thread.chamfer_leads = 101\n", "thread.chamfer_leads", "(not 101;");
        assertFault(GOOD + "thread.chamfer_angle = 90\n", "thread.chamfer_angle",
                "thread.chamfer_angle is the angle of the chamfered pull-out to the Z axis in degrees: more than 0 and "
                        + "less than 90 (not 90)");
        assertFault(GOOD + "thread.chamfer_angle = 0\n", "thread.chamfer_angle", "(not 0)");
        assertFault(GOOD + "thread.chamfer_angle = steep\n", "thread.chamfer_angle", "'steep' is not a number");
        MachineProfile p = ProfileLoader.read(ProfileFile.parse("t.machine",
                GOOD + "thread.chamfer_leads = 0\nthread.chamfer_angle = 30\n"), TABLES);
        assertEquals(new ThreadChamfer(0, 30), p.threadChamfer());
        assertFalse(p.threadChamfer().cuts());
        // Haas's Settings 95 and 96 as shipped: in the haas profile, and the default of every other
        assertEquals(ThreadChamfer.HAAS, load("haas").threadChamfer());
        assertEquals(new ThreadChamfer(1.0, 45), load("generic").threadChamfer());
        assertEquals(1, load("haas").threadChamfer().slope(), 1e-12);
    }

    @Test
    void oneNumberTwiceIsAFault() throws Exception {
        assertFault(GOOD + "m.05 = CB1\n", "m.05", "'m.05' is number 5 again ('m.5' on line");
        assertFault(GOOD + "sim.tool.3.insert = 0, 0; 1, 1; 0, 1\nsim.tool.03.holder = 0, 0; 1, 1; 0, 1\n",
                "sim.tool.03", "'sim.tool.03.holder' is tool 3 again");
    }

    // ---- encoding ----

    @Test
    void aByteOrderMarkIsAccepted() throws Exception {
        Path f = Files.createTempFile("bom", ".machine");
        Files.write(f, concat(new byte[] {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF}, GOOD.getBytes(StandardCharsets.UTF_8)));
        assertEquals("generic", ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES).name());
    }

    @Test
    void aByteThatIsNotUtf8IsAFaultAtItsLineAndColumn() throws Exception {
        Path f = Files.createTempFile("latin1", ".machine");
        String text = GOOD.replace("name = generic", "name = torno-peque\u00f1o"); // ñ in Latin-1: one byte 0xF1
        Files.write(f, text.getBytes(StandardCharsets.ISO_8859_1));
        TableException e = assertThrows(TableException.class, () -> ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES));
        assertEquals(f.toString(), e.path());
        assertEquals(lineOf(text, "name = torno"), e.diagnostic().span().line());
        assertEquals("name = torno-peque".length() + 1, e.diagnostic().span().column());
        assertTrue(e.english().contains("byte 0xF1 is not UTF-8"), e.getMessage());
    }

    private static final String GOOD = readGeneric();

    private static String readGeneric() {
        try {
            return Files.readString(Path.of("tables/machines/generic.machine"));
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static MachineProfile loadText(String text) throws TableException {
        return ProfileLoader.read(ProfileFile.parse("t.machine", text), TABLES);
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    static int lineOf(String text, String badLine) {
        return text.substring(0, text.lastIndexOf(badLine)).split("\n", -1).length;
    }

    static void assertFault(String text, String badLine, String message) throws Exception {
        Path f = Files.createTempFile("bad", ".machine");
        Files.writeString(f, text);
        TableException e = assertThrows(TableException.class, () -> ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES));
        assertEquals(Code.E400_TABLE, e.diagnostic().code());
        assertEquals(lineOf(text, badLine), e.diagnostic().span().line(), e.getMessage());
        assertTrue(e.english().contains(message), e.english());
    }

    @Test
    void theShippedMachinesAreTheProfilesInTheTables() throws Exception {
        try (Stream<Path> files = Files.list(Path.of("tables/machines"))) {
            assertEquals(files.map(f -> f.getFileName().toString()).filter(n -> n.endsWith(".machine"))
                    .map(n -> n.substring(0, n.length() - ".machine".length())).sorted().toList(), ProfileLoader.SHIPPED);
        }
    }

    @Test
    void aMisspeltMachineOrControlNameGetsTheNearestShippedOne() {
        String hass = assertThrows(TableException.class, () -> load("hass")).english();
        assertTrue(hass.contains("no machine profile 'hass': did you mean 'haas'? (shipped: fanuc, generic, haas, thesis-2004"), hass);
        String okuma = assertThrows(TableException.class, () -> load("okuma")).english();
        assertTrue(okuma.contains("no machine profile 'okuma' (shipped: fanuc, generic, haas, thesis-2004"), okuma);
        assertFalse(okuma.contains("did you mean"), okuma);
        String control = assertThrows(TableException.class,
                () -> ProfileLoader.load("fanuc", TableSource.builtIn(), TABLES, "fanuc-c")).english();
        assertTrue(control.contains("no control 'fanuc-c': did you mean 'fanuc-a'?"), control);
    }
}
