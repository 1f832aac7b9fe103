package gcnc.studio;

import static gcnc.studio.StudioServerTest.request;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.TestCut;
import gcnc.cli.WearOffsetsTest;
import gcnc.tables.ErrorMessages;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The studio's test cut (POST /api/wear and /api/wear/cut, docs/studio.md "Test cut"): guarded as every
 * other endpoint; the wear is the one {@code gcnc offsets wear} computes (gcnc.TestCut, the same code),
 * saved as one line of the offsets file, in force for the next arm (its pre-flight names it); a typo
 * and a wear that makes a collision are refused with their finding and nothing is written. The
 * programs are WearOffsetsTest's, on the fanuc profile with an offsets file of the folder's.
 */
class StudioTestCutTest {
    static Studio studio;
    static Path dir;
    static Path offsets;
    static final String BEFORE = "# the shop's wear\nwear.8 = -0.02, 0   # boring bar\n";

    /** A studio per test, on the offsets file as BEFORE writes it: each test starts with no wear for T01. */
    @BeforeEach
    void start() throws Exception {
        dir = Files.createTempDirectory("gcnc-studio-wear");
        offsets = dir.resolve("shop.offsets");
        Files.writeString(offsets, BEFORE);
        Files.writeString(dir.resolve("part.nc"), WearOffsetsTest.METRIC);
        Files.writeString(dir.resolve("close.nc"), WearOffsetsTest.CLOSE);
        Session s = Session.open(Session.Options.defaults().withMachine("fanuc").withOffsets(offsets));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test", new Studio.Running(5, null)));
    }

    @AfterEach
    void stop() {
        studio.close();
    }

    static StudioServerTest.Reply post(String endpoint, String body) throws Exception {
        return request(studio, "POST", "/api/" + endpoint, StudioServerTest.good(studio), body);
    }

    static JsonObject ok(String endpoint, String body) throws Exception {
        StudioServerTest.Reply r = post(endpoint, body);
        assertEquals(200, r.status(), r.body());
        return r.json();
    }

    @Test
    void bothEndpointsAreRefusedWithoutTheTokenFromAnotherPageOrAnotherHost() throws Exception {
        String cut = "{\"name\":\"part.nc\",\"offset\":1,\"measuredX\":\"39.96\",\"programmedX\":\"40.\"}";
        for (String e : List.of("wear", "wear/cut")) {
            Map<String, String> noToken = StudioServerTest.good(studio);
            noToken.remove(Guard.TOKEN_HEADER);
            assertEquals(403, request(studio, "POST", "/api/" + e, noToken, cut).status(), e);
            Map<String, String> otherPage = StudioServerTest.good(studio);
            otherPage.put("Origin", "http://evil.example");
            assertEquals(403, request(studio, "POST", "/api/" + e, otherPage, cut).status(), e);
            Map<String, String> rebound = StudioServerTest.good(studio);
            rebound.put("Host", "evil.example:" + studio.port());
            assertEquals(403, request(studio, "POST", "/api/" + e, rebound, cut).status(), e);
            assertEquals(405, request(studio, "GET", "/api/" + e, StudioServerTest.good(studio), null).status(), e);
        }
        assertEquals(BEFORE, Files.readString(offsets), "nothing written");
    }

    @Test
    void theFormListsTheProgramsToolOffsetsAndWhereTheWearIsSaved() throws Exception {
        JsonObject f = ok("wear", "{\"name\":\"part.nc\"}");
        assertEquals("mm", f.get("units").getAsString());
        assertTrue(f.get("diameter").getAsBoolean());
        assertEquals("shop.offsets", f.get("file").getAsString());
        List<Integer> tools = f.getAsJsonArray("tools").asList().stream().map(t -> t.getAsJsonObject().get("offset").getAsInt())
                .toList();
        assertEquals(List.of(1), tools); // T0101 only: the boring bar's wear.8 is not this program's
        assertEquals(400, post("wear", "{}").status());
        assertEquals(404, post("wear", "{\"name\":\"none.nc\"}").status());
    }

    @Test
    void aTestCutIsTheCommandLinesWearSavedAndTheNextArmUsesIt() throws Exception {
        // what gcnc offsets wear computes for the same measurement: the library's own, not a second computation
        TestCut.Measurement m = TestCut.Measurement.parse("X39.96", "X40.").orElseThrow();
        assertEquals(0.04, m.change(), 1e-12);
        JsonObject r = ok("wear/cut", "{\"name\":\"part.nc\",\"offset\":1,\"measuredX\":\"39.96\",\"programmedX\":\"40.\","
                + "\"measuredZ\":\"\",\"programmedZ\":\"\"}");
        assertTrue(r.get("saved").getAsBoolean(), r.toString());
        JsonObject c = r.getAsJsonArray("changes").get(0).getAsJsonObject();
        assertEquals("X", c.get("axis").getAsString());
        assertEquals("0.000", c.get("before").getAsString());
        assertEquals("+0.040", c.get("step").getAsString());
        assertEquals("+0.040", c.get("after").getAsString());
        assertEquals("T01 X+0.040 Z0.000 (diameter, mm)", r.get("wear").getAsString());
        assertEquals(0, r.get("errors").getAsInt());
        // one line added, the file's own lines and comments kept
        assertEquals(BEFORE + "wear.1 = 0.04, 0\n", Files.readString(offsets));
        // in force at once: the form shows it, and the next arm's pre-flight names it
        JsonObject f = ok("wear", "{\"name\":\"part.nc\"}");
        assertEquals(0.04, f.getAsJsonArray("tools").get(0).getAsJsonObject().get("x").getAsDouble(), 1e-12);
        JsonObject arm = ok("run/arm", "{\"name\":\"part.nc\",\"target\":{\"kind\":\"virtual\"}}");
        List<JsonObject> wear = arm.getAsJsonArray("events").asList().stream().map(JsonElement::getAsJsonObject)
                .filter(e -> e.get("event").getAsString().equals("wear")).toList();
        assertEquals(1, wear.size(), arm.toString());
        assertEquals(1, wear.get(0).get("offset").getAsInt());
        assertEquals(0.04, wear.get(0).get("x").getAsDouble(), 1e-12);
        assertTrue(wear.get(0).get("file").getAsString().endsWith("shop.offsets"), wear.toString());
        // the next cut adds to it (and is held to the total)
        r = ok("wear/cut", "{\"name\":\"part.nc\",\"offset\":1,\"measuredZ\":\"-30.05\",\"programmedZ\":\"-30.\"}");
        assertTrue(r.get("saved").getAsBoolean(), r.toString());
        assertEquals(BEFORE + "wear.1 = 0.04, 0.05\n", Files.readString(offsets));
    }

    @Test
    void aTypoIsRefusedNamingTheLimitAndNothingIsWritten() throws Exception {
        // 2.5 typed where 0.025 was meant
        JsonObject r = ok("wear/cut", "{\"name\":\"part.nc\",\"offset\":1,\"measuredX\":\"37.5\",\"programmedX\":\"40.\"}");
        assertFalse(r.get("saved").getAsBoolean(), r.toString());
        assertEquals("E872", r.get("code").getAsString());
        assertEquals("shop.offsets", r.get("file").getAsString());
        assertTrue(r.get("message").getAsString().contains("+2.500 mm (programmed X40. minus measured X37.5): more than"
                + " wear.max_step = 0.5 mm"), r.toString());
        assertEquals(BEFORE, Files.readString(offsets));
    }

    @Test
    void aWearThatMakesACollisionIsRefusedWithTheSimulatorsFinding() throws Exception {
        // -0.5 on the diameter: the rapid 0.2 mm above the blank (on the radius) now enters it
        JsonObject r = ok("wear/cut", "{\"name\":\"close.nc\",\"offset\":1,\"measuredX\":\"40.5\",\"programmedX\":\"40.\"}");
        assertFalse(r.get("saved").getAsBoolean(), r.toString());
        assertEquals("E874", r.get("code").getAsString());
        assertEquals("close.nc", r.get("file").getAsString());
        assertEquals(7, r.get("line").getAsInt(), r.toString());
        assertEquals(BEFORE, Files.readString(offsets));
    }

    @Test
    void aMalformedMeasurementIsA400() throws Exception {
        assertEquals(400, post("wear/cut", "{\"name\":\"part.nc\",\"offset\":1}").status());
        assertEquals(400, post("wear/cut", "{\"name\":\"part.nc\",\"offset\":1,\"measuredX\":\"39.96\"}").status());
        assertEquals(400, post("wear/cut", "{\"name\":\"part.nc\",\"offset\":1,\"measuredX\":\"abc\",\"programmedX\":\"40\"}")
                .status());
        assertEquals(400, post("wear/cut", "{\"name\":\"part.nc\",\"offset\":100,\"measuredX\":\"1\",\"programmedX\":\"1\"}")
                .status());
        assertEquals(BEFORE, Files.readString(offsets));
    }
}
