package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.machine.GalilModel.Limit;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * tables/galil_models.csv loads and is checked like the other tables; a machine profile's
 * galil.model picks its row, an unknown one is E420 with the nearest name, and a profile that asks
 * its model for what it does not have is refused at the line that asks (E421-E425).
 */
class GalilModelsTest {
    private static final Tables TABLES = Tables.builtIn();
    private static final GalilModels MODELS = GalilModels.builtIn();
    private static final String GENERIC = read(Path.of("tables/machines/generic.machine"));

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void theTableLoadsWithEveryFamilyTheIssueNames() {
        List<String> names = MODELS.all().stream().map(GalilModel::name).toList();
        for (String n : List.of("DMC-4010", "DMC-4080", "DMC-4113", "DMC-4183", "DMC-2113", "DMC-2183", "DMC-30010",
                "DMC-1816", "DMC-1886", "DMC-1700")) {
            assertTrue(names.contains(n), n);
        }
        GalilModel m = MODELS.find("DMC-4040").orElseThrow();
        assertEquals("DMC-40x0", m.family());
        assertEquals(4, m.axes());
        assertEquals(8, m.digitalOutputs());
        assertEquals(16, MODELS.find("DMC-4080").orElseThrow().digitalOutputs());
        assertEquals(1000, m.sampleMicros());
        assertEquals(2000, m.range(Limit.PROGRAM_LINES).max());
        assertEquals(4000, m.withFirmware12a().range(Limit.PROGRAM_LINES).max());
        assertEquals(1024, m.range(Limit.ACCELERATION).step());
        assertEquals(0, m.analogOutputCount().orElseThrow());
        assertTrue(MODELS.find("DMC-30010").orElseThrow().analogOutputCount().isEmpty(), "not verified: left blank");
        assertFalse(MODELS.find("DMC-1846").orElseThrow().hasFirmware12a());
    }

    /**
     * Every row against the reference, so that a slip in one of 34 rows (a digit dropped, a column
     * shifted) fails here: the command ranges are the same on every model COMALL covers, the axes
     * are the model number's digit, the outputs follow the axes, and only the families whose
     * firmware reaches 1.2a get the larger memory.
     */
    @Test
    void everyRowHoldsTheReferencesFigures() {
        for (GalilModel m : MODELS.all()) {
            String why = m.name() + " (galil_models.csv:" + m.row() + ")";
            assertEquals(new GalilModel.Range(2, 15_000_000, 2), m.range(Limit.VECTOR_SPEED), why);
            assertEquals(m.range(Limit.VECTOR_SPEED), m.range(Limit.SEGMENT_SPEED), why);
            assertEquals(new GalilModel.Range(1024, 1_073_740_800, 1024), m.range(Limit.ACCELERATION), why);
            assertEquals(8_388_607, m.range(Limit.SEGMENT_LENGTH).max(), why);
            assertEquals(new GalilModel.Range(10, 6_000_000, 1), m.range(Limit.ARC_RADIUS), why);
            assertEquals(450_000_000, m.range(Limit.ARC_LENGTH).max(), why);
            assertEquals(new GalilModel.Range(2, 2_147_483_646, 2), m.range(Limit.DWELL), why);
            assertEquals(80, m.range(Limit.LINE_LENGTH).max(), why);
            assertEquals(510, m.range(Limit.LABELS).max(), why);
            assertEquals(7, m.range(Limit.LABEL_LENGTH).max(), why);
            assertEquals(1L << 30, m.range(Limit.SEQUENCE_LENGTH).max(), why);
            assertEquals(511, m.range(Limit.BUFFER_SEGMENTS).max(), why);
            assertEquals(2000, m.range(Limit.PROGRAM_LINES).max(), why);
            assertEquals(16_000, m.range(Limit.ARRAY_ELEMENTS).max(), why);
            assertEquals(1000, m.sampleMicros(), why);
            assertEquals(m.axes() <= 4 ? 8 : 16, m.digitalOutputs(), why);
            boolean fw12a = List.of("DMC-40x0", "DMC-41x3", "DMC-30010").contains(m.family());
            assertEquals(fw12a, m.hasFirmware12a(), why);
            assertEquals(fw12a ? 4000 : 2000, m.withFirmware12a().range(Limit.PROGRAM_LINES).max(), why);
            assertEquals(fw12a ? 24_000 : 16_000, m.withFirmware12a().range(Limit.ARRAY_ELEMENTS).max(), why);
            if (m.family().contains("x") && !m.name().equals("DMC-1700")) { // the thesis names the series, not a model
                // DMC-40x0: DMC-40<n>0; DMC-41x3: DMC-41<n>3; the x is the axis count
                int x = m.family().indexOf('x');
                assertEquals(m.axes(), m.name().charAt(x) - '0', why);
                assertTrue(m.name().startsWith(m.family().substring(0, x)), why);
            }
        }
        assertEquals(1, MODELS.find("DMC-30010").orElseThrow().axes());
        assertEquals(8, MODELS.find("DMC-1700").orElseThrow().axes(), "the series' most: any channel the thesis used passes");
    }

    @Test
    void eachShippedProfileNamesAModelThatExists() throws Exception {
        Pattern key = Pattern.compile("(?m)^galil\\.model *= *([^\\s#]+)");
        List<Path> files;
        try (Stream<Path> s = Files.list(Path.of("tables/machines"))) {
            files = s.filter(p -> p.toString().endsWith(".machine")).sorted().toList();
        }
        assertFalse(files.isEmpty());
        for (Path p : files) {
            Matcher m = key.matcher(read(p));
            assertTrue(m.find(), p + " names its controller");
            assertTrue(MODELS.find(m.group(1)).isPresent(), p + ": " + m.group(1));
            String name = p.getFileName().toString().replace(".machine", "");
            assertEquals(m.group(1), ProfileLoader.load(name, TableSource.builtIn(), TABLES).galilModel().name());
        }
    }

    @Test
    void aProfileWithoutTheKeyIsOnADmc4040() throws Exception {
        MachineProfile p = ProfileLoader.read(ProfileFile.parse("t.machine",
                GENERIC.replace("galil.model = DMC-4030\n", "")), TABLES);
        assertEquals("DMC-4040", p.galilModel().name());
        assertEquals(GalilModels.DEFAULT, p.galilModel().name());
    }

    /** The generic profile with {@code key}'s line set to {@code value} (added when absent). */
    private static String with(String key, String value) {
        Matcher m = Pattern.compile("(?m)^" + Pattern.quote(key) + " *=.*$").matcher(GENERIC);
        return m.find() ? m.replaceFirst(Matcher.quoteReplacement(key + " = " + value)) : GENERIC + key + " = " + value + "\n";
    }

    /** Loading {@code text} fails with {@code code} at the line holding {@code line}, the English message containing {@code text}. */
    private static TableException refused(String text, String line, Code code, String message) {
        TableException e = assertThrows(TableException.class,
                () -> ProfileLoader.read(ProfileFile.parse("t.machine", text), TABLES), line);
        assertEquals(code, e.diagnostic().code(), e.getMessage());
        assertEquals(ProfileLoaderTest.lineOf(text, line), e.diagnostic().span().line(), e.getMessage());
        assertTrue(e.english().contains(message), e.english());
        return e;
    }

    @Test
    void anUnknownModelIsE420AtItsLineWithTheNearestName() {
        TableException e = refused(with("galil.model", "DMC-4404"), "galil.model = DMC-4404", Code.E420_UNKNOWN_GALIL_MODEL,
                "galil.model = DMC-4404: no such Galil model: did you mean 'DMC-4040'?");
        assertTrue(e.english().contains("DMC-4010..DMC-4080"), e.english());
        assertTrue(e.english().contains("DMC-30010"), e.english());
        ErrorMessages m = TABLES.messages();
        assertTrue(m.render(e.diagnostic().code(), e.diagnostic().args(), ErrorMessages.Lang.ES)
                .startsWith("galil.model = DMC-4404: no existe ese modelo Galil: ¿quiso decir 'DMC-4040'?"));
        // written as the controller's label reads it: without the dash
        refused(with("galil.model", "DMC40400"), "galil.model = DMC40400", Code.E420_UNKNOWN_GALIL_MODEL,
                "did you mean 'DMC-4040'?");
        refused(with("galil.model", "dmc4030"), "galil.model = dmc4030", Code.E420_UNKNOWN_GALIL_MODEL,
                "did you mean 'DMC-4030'?");
        // nothing near: no suggestion, the list
        TableException far = refused(with("galil.model", "Accelera"), "galil.model = Accelera",
                Code.E420_UNKNOWN_GALIL_MODEL, "galil.model = Accelera: no such Galil model (gcnc knows DMC-4010..DMC-4080");
        assertFalse(far.english().contains("did you mean"), far.english());
    }

    @Test
    void aChannelTheModelDoesNotHaveIsE421AtItsLine() {
        refused(with("galil.model", "DMC-4020"), "spindle.axis = C", Code.E421_CHANNEL_BEYOND_MODEL,
                "spindle.axis = C: the DMC-4020 has no such channel (its channels are A-B (X, Y))");
        // without spindle.axis its default C is what the model lacks: shown at galil.model
        refused(with("galil.model", "DMC-4020").replace("spindle.axis = C", "# no spindle.axis"),
                "galil.model = DMC-4020", Code.E421_CHANNEL_BEYOND_MODEL, "spindle.axis = C: the DMC-4020");
        String twoAxes = with("galil.model", "DMC-4020").replace("spindle.axis = C", "spindle.axis = D");
        refused(twoAxes, "spindle.axis = D", Code.E421_CHANNEL_BEYOND_MODEL, "spindle.axis = D: the DMC-4020");
        refused(with("galil.model", "DMC-30010"), "x.galil = Y", Code.E421_CHANNEL_BEYOND_MODEL,
                "x.galil = Y: the DMC-30010 has no such channel (its channels are A (X))");
        String encoder = with("spindle.encoder", "4096") + "spindle.encoder_axis = E\n";
        refused(encoder, "spindle.encoder_axis = E", Code.E421_CHANNEL_BEYOND_MODEL,
                "spindle.encoder_axis = E: the DMC-4030");
        // the same channel on a larger model is fine
        assertEquals('E', assertLoads(with("galil.model", "DMC-4050") + "spindle.encoder = 4096\nspindle.encoder_axis = E\n")
                .encoder().orElseThrow().channel());
    }

    @Test
    void anAccelerationOrSpeedTheModelCannotTakeIsE422OrE423AtItsLine() {
        refused(with("vector.acceleration", "1000"), "vector.acceleration = 1000", Code.E422_ACCELERATION_BEYOND_MODEL,
                "vector.acceleration = 1000: the DMC-4030's VA and VD take 1024 to 1073740800 counts/s^2");
        refused(with("vector.deceleration", "1073741824"), "vector.deceleration = 1073741824",
                Code.E422_ACCELERATION_BEYOND_MODEL, "1024 to 1073740800");
        refused(with("rapid.speed", "20000000"), "rapid.speed = 20000000", Code.E423_SPEED_BEYOND_MODEL,
                "rapid.speed = 20000000: the DMC-4030's VS takes 2 to 15000000 counts/s");
        refused(with("feed.max", "1.5"), "feed.max = 1.5", Code.E423_SPEED_BEYOND_MODEL, "2 to 15000000");
        // at the bounds: taken (VA 1024, VS 15000000); not a multiple of 1024 is the backend's warning, not a fault
        assertLoads(with("vector.acceleration", "1024"));
        assertLoads(with("rapid.speed", "15000000"));
        assertLoads(with("vector.acceleration", "1000001"));
    }

    @Test
    void anOutputTheModelDoesNotHaveIsE424AtItsLine() {
        refused(with("m.8", "SB9"), "m.8 = SB9", Code.E424_OUTPUT_BEYOND_MODEL,
                "m.8: output SB9 is not one of the 8 digital outputs of the DMC-4030");
        refused(with("m.9", "CB3, CB 0"), "m.9 = CB3, CB 0", Code.E424_OUTPUT_BEYOND_MODEL, "output CB 0");
        assertLoads(with("galil.model", "DMC-4050").replace("m.8 = SB3", "m.8 = SB16"));
    }

    @Test
    void theFirmwareRevisionPicksTheProgramMemory() throws Exception {
        MachineProfile old = assertLoads(GENERIC);
        assertEquals(2000, old.galilModel().range(Limit.PROGRAM_LINES).max(), "without galil.firmware: the smaller memory");
        assertEquals(4000, assertLoads(with("galil.firmware", "1.2a")).galilModel().range(Limit.PROGRAM_LINES).max());
        assertEquals(4000, assertLoads(with("galil.firmware", "Rev 1.3e")).galilModel().range(Limit.PROGRAM_LINES).max());
        assertEquals(2000, assertLoads(with("galil.firmware", "1.1b")).galilModel().range(Limit.PROGRAM_LINES).max());
        assertEquals(2000, assertLoads(with("galil.firmware", "1.0")).galilModel().range(Limit.PROGRAM_LINES).max());
        refused(with("galil.firmware", "new"), "galil.firmware = new", Code.E425_FIRMWARE_REVISION,
                "galil.firmware = new: not a firmware revision such as 1.2a");
    }

    private static MachineProfile assertLoads(String text) {
        try {
            return ProfileLoader.read(ProfileFile.parse("t.machine", text), TABLES);
        } catch (TableException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    @Test
    void aBrokenTableIsAFaultAtItsLineAndColumn() throws Exception {
        String table = read(Path.of("tables/galil_models.csv"));
        String header = table.lines().filter(l -> l.startsWith("model,")).findFirst().orElseThrow();
        String row = table.lines().filter(l -> l.startsWith("DMC-4040,")).findFirst().orElseThrow();
        assertFault(header + "\n" + row + "\n" + row + "\n", 3, "model DMC-4040 is listed twice (first on line 2)");
        assertFault(header + "\n" + row.replace("DMC-4040,", "4040,") + "\n", 2, "'4040' is not a Galil model name");
        assertFault(header + "\n" + row.replace(",511,", ",5x1,") + "\n", 2, "'5x1' is not a whole number (buffer_segments)");
        assertFault(header + "\n" + row.replace("DMC-40x0,4,", "DMC-40x0,9,") + "\n", 2, "axes = 9: the column takes 1 to 8");
        assertFault(header + "\n" + row.replace(",2000,4000,", ",2000,1000,") + "\n", 2,
                "program_lines_12a is smaller than program_lines");
        assertFault(header + "\n" + row.replace(",10,6000000,", ",6000001,6000000,") + "\n", 2,
                "lower limit above upper limit");
    }

    private static void assertFault(String csv, int line, String message) throws Exception {
        Path dir = Files.createTempDirectory("gcnc-models");
        Files.writeString(dir.resolve(GalilModels.FILE), csv);
        TableException e = assertThrows(TableException.class, () -> GalilModels.load(TableSource.directory(dir)));
        assertEquals(Code.E400_TABLE, e.diagnostic().code());
        assertEquals(line, e.diagnostic().span().line(), e.getMessage());
        assertTrue(e.getMessage().contains(GalilModels.FILE + ":" + line + ":"), e.getMessage());
        assertTrue(e.english().contains(message), e.english());
    }
}
