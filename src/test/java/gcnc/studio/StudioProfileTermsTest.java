package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.nio.file.Files;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Configure in the program's terms over plain HTTP ({@link ProfileTerms}): GET /api/profile?units=
 * gives each length in the program's units, X as the program writes it; POST /api/profile/impact
 * with {@code program} values says what the file would hold: exact millimetres (or counts), and
 * the file's own text for a part sent back as it was shown.
 */
class StudioProfileTermsTest {
    Studio studio;

    void start(String machine) throws Exception {
        Session s = Session.open(Session.Options.defaults().withMachine(machine));
        studio = Studio.start(new Studio.Config(Files.createTempDirectory("gcnc-terms"), 0, s, ErrorMessages.Lang.EN, "test"));
    }

    @AfterEach
    void stop() {
        if (studio != null) {
            studio.close();
        }
    }

    private JsonObject form(String units) throws IOException {
        StudioServerTest.Reply r = StudioServerTest.request(studio, "GET", "/api/profile" + (units == null ? "" : "?units=" + units),
                StudioServerTest.good(studio), null);
        assertEquals(200, r.status(), r.body());
        return r.json();
    }

    /** A field of the form: {@code [value as written, value in program terms]}. */
    private static String[] field(JsonObject form, String key) {
        for (String group : new String[] {"travel", "work", "toolOffsets", "geometry"}) {
            for (JsonElement e : form.getAsJsonArray(group)) {
                JsonObject f = e.getAsJsonObject();
                if (f.get("key").getAsString().equals(key)) {
                    return new String[] {f.get("value").getAsString(), f.has("program") ? f.get("program").getAsString() : null};
                }
            }
        }
        throw new AssertionError("no field " + key);
    }

    /** What the file would hold for each key typed in program terms. */
    private JsonObject written(String units, String... keyValues) throws IOException {
        JsonObject program = new JsonObject();
        for (int i = 0; i < keyValues.length; i += 2) {
            program.addProperty(keyValues[i], keyValues[i + 1]);
        }
        JsonObject req = new JsonObject();
        req.add("values", new JsonObject());
        req.add("program", program);
        req.addProperty("units", units);
        StudioServerTest.Reply r = StudioServerTest.request(studio, "POST", "/api/profile/impact", StudioServerTest.good(studio), req.toString());
        assertEquals(200, r.status(), r.body());
        assertEquals(true, r.json().get("valid").getAsBoolean(), r.body());
        return r.json().getAsJsonObject("written");
    }

    @Test
    void haasInInchesXAsADiameterExactBackInMillimetres() throws Exception {
        start("haas"); // x.travel = -4, 212 mm of radius; work.G55 = 0, 150; nose.1 = 0.794, 3; units = inch
        JsonObject form = form("in");
        assertEquals("in", form.get("units").getAsString());
        assertEquals(true, form.get("diameter").getAsBoolean());
        assertEquals("-4, 212", field(form, "x.travel")[0]);
        assertEquals("-0.314961, 16.692913", field(form, "x.travel")[1]);
        assertEquals("-0.787402, 20.19685", field(form, "z.travel")[1]);
        assertEquals("0, 5.905512", field(form, "work.G55")[1]);
        assertEquals("face", field(form, "work.G54")[1]); // a word stays as written
        assertEquals("0.03126, 3", field(form, "nose.1")[1]); // a nose radius is a radius, the tip a number
        assertEquals(null, field(form, "sim.tool.1")[1], "the insert's outline is its own text");
        // the page's default: the profile's power-up units (Haas: inch)
        assertEquals("-0.314961, 16.692913", field(form(null), "x.travel")[1]);
        assertEquals("-8, 424", field(form("mm"), "x.travel")[1]);

        // typed: exact millimetres of radius; a part sent back as shown keeps the file's text
        JsonObject w = written("in", "x.travel", "-0.5, 16.692913", "work.G55", "1.25, 5.905512", "nose.1", "0.03126, 2",
                "z.travel", "-0.787402, 20.19685");
        assertEquals("-6.35, 212", w.get("x.travel").getAsString());
        assertEquals("15.875, 150", w.get("work.G55").getAsString());
        assertEquals("0.794, 2", w.get("nose.1").getAsString());
        assertEquals("-20, 513", w.get("z.travel").getAsString(), "shown and sent back: no drift");
        assertEquals("-4, 215.9", written("in", "x.travel", "-0.314961, 17").get("x.travel").getAsString());
        assertEquals("-4, 215.9", written("mm", "x.travel", "-8, 431.8").get("x.travel").getAsString());
    }

    @Test
    void theThesisInCountsAndItsOwnInch() throws Exception {
        start("thesis-2004"); // offsets in counts; 1.5 counts per mm, 1200 per inch: its inch is 800 of its mm; X a radius
        JsonObject mm = form(null);
        assertEquals("mm", mm.get("units").getAsString());
        assertEquals("-30000.0008, 880000.88888", field(mm, "z.travel")[1]);
        assertEquals("-13333.333333, -13333.333333", field(mm, "work.G54")[1]); // -20000 counts
        JsonObject in = form("in");
        assertEquals(false, in.get("diameter").getAsBoolean());
        assertEquals("-16.666667, -16.666667", field(in, "work.G54")[1]);
        assertEquals("-19200, -20000", written("in", "work.G54", "-16, -16.666667").get("work.G54").getAsString());
        assertEquals("-37.500001, 1100.001111", field(in, "z.travel")[1]); // mm of the machine over its 800 mm inch
    }

    @Test
    void unitsAreInOrMm() throws Exception {
        start("haas");
        assertEquals(400, StudioServerTest.request(studio, "GET", "/api/profile?units=ft", StudioServerTest.good(studio), null).status());
    }
}
