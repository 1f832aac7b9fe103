package gcnc.studio;

import static gcnc.studio.StudioServerTest.body;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.machine.GFunction;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableSource;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * The studio's hover, scrub and Configure endpoints over plain HTTP: what each answers for the
 * samples (against the control's tables, the checker's arithmetic and the simulator's own
 * findings), and that each is guarded like the rest of the API.
 */
class StudioWorkbenchTest {
    Studio studio;
    Path dir;

    Studio start(String machine) throws Exception {
        dir = Files.createTempDirectory("gcnc-workbench");
        Session s = Session.open(Session.Options.defaults().withMachine(machine));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test"));
        return studio;
    }

    @AfterEach
    void stop() {
        if (studio != null) {
            studio.close();
        }
    }

    StudioServerTest.Reply post(String endpoint, JsonObject body) throws IOException {
        return StudioServerTest.request(studio, "POST", "/api/" + endpoint, StudioServerTest.good(studio), body.toString());
    }

    StudioServerTest.Reply get(String target) throws IOException {
        return StudioServerTest.request(studio, "GET", target, StudioServerTest.good(studio), null);
    }

    JsonObject hover(String text, int line, String word) throws IOException {
        JsonObject req = body("name", "part.nc", "text", text);
        req.addProperty("line", line);
        if (word != null) {
            req.addProperty("word", word);
        }
        StudioServerTest.Reply r = post("hover", req);
        assertEquals(200, r.status(), r.body());
        return r.json();
    }

    // ---- hover ----

    @Test
    void hoverNamesTheFunctionOnThisControlAndTheModalStateAfterTheBlock() throws Exception {
        start("generic");
        String text = Files.readString(Path.of("samples/dwell-css.nc"));
        GFunction g96 = Session.open(Session.Options.defaults().withMachine("generic"))
                .profile().control().g().get(96);
        JsonObject css = hover(text, 9, "G96"); // N80 G96 S150
        assertEquals("G96", css.getAsJsonObject("function").get("code").getAsString());
        assertEquals(g96.english(), css.getAsJsonObject("function").get("text").getAsString());
        assertEquals("G04", hover(text, 8, "G4").getAsJsonObject("function").get("code").getAsString()); // as the control names it
        assertFalse(hover(text, 8, "X1.5").has("function"), "an axis word names no function");
        assertTrue(hover(text, 8, "G123").getAsJsonObject("function").get("unknown").getAsBoolean());
        assertEquals("M03", hover(text, 6, "M03").getAsJsonObject("function").get("code").getAsString());

        // N90 G01 X40. F0.15 under G96 S150: the rpm the control gives at X40 (a diameter), feed per revolution
        JsonObject at40 = hover(text, 10, "G01").getAsJsonObject("state");
        assertTrue(at40.get("css").getAsBoolean());
        assertEquals(150, at40.get("surfaceSpeed").getAsDouble());
        assertEquals(150 * 1000 / (Math.PI * 40), at40.get("blockRpm").getAsDouble(), 0.01);
        assertTrue(at40.get("feedPerRev").getAsBoolean());
        assertEquals(0.15, at40.get("feed").getAsDouble());
        assertEquals("mm", at40.get("units").getAsString());
        assertEquals("G54", at40.get("workOffset").getAsString());
        assertEquals(1, at40.get("tool").getAsInt());
        assertEquals(40, at40.getAsJsonObject("at").get("x").getAsDouble(), 1e-6);
        assertEquals("G01", at40.get("motion").getAsString());
        // N130 G01 X10.: 4,775 rpm at X10 is above G50 S3000: clamped
        JsonObject at10 = hover(text, 14, null).getAsJsonObject("state");
        assertEquals(3000, at10.get("blockRpm").getAsDouble(), 1e-6);
        assertEquals(3000, at10.get("rpmClamp").getAsDouble(), 1e-6);
        // N150 G97 S800: constant surface speed off, 800 rpm
        JsonObject rpm = hover(text, 16, null).getAsJsonObject("state");
        assertFalse(rpm.get("css").getAsBoolean());
        assertEquals(800, rpm.get("rpm").getAsDouble(), 1e-6);
        // N170 G98: feed per minute again
        assertFalse(hover(text, 19, null).getAsJsonObject("state").get("feedPerRev").getAsBoolean());
        assertFalse(hover(text + "\n\n", 30, null).has("state"), "no block on that line");
    }

    // ---- scrub ----

    JsonObject stock(String text, int line) throws IOException {
        JsonObject req = body("name", "bishop.nc", "text", text);
        req.addProperty("line", line);
        StudioServerTest.Reply r = post("stock", req);
        assertEquals(200, r.status(), r.body());
        return r.json();
    }

    /** The outline's X at the point nearest to {@code z}. */
    /** The outline's X at z: its points joined by straight lines, the largest where a face stands at z. */
    static double xAt(JsonObject outline, double z) {
        JsonArray zs = outline.getAsJsonArray("z");
        JsonArray xs = outline.getAsJsonArray("x");
        double best = Double.NaN;
        for (int i = 0; i + 1 < zs.size(); i++) {
            double z0 = zs.get(i).getAsDouble();
            double z1 = zs.get(i + 1).getAsDouble();
            double x0 = xs.get(i).getAsDouble();
            double x1 = xs.get(i + 1).getAsDouble();
            if (Math.min(z0, z1) <= z && z <= Math.max(z0, z1)) {
                double x = z0 == z1 ? Math.max(x0, x1) : x0 + (x1 - x0) * (z - z0) / (z1 - z0);
                best = Double.isNaN(best) ? x : Math.max(best, x);
            }
        }
        return best;
    }

    @Test
    void theScrubGivesTheStockBeforeAndAfterABlockAndTheToolThere() throws Exception {
        start("thesis-2004");
        String text = Files.readString(Path.of("samples/bishop.nc"));
        // N135 G01 Z-04500 at X+2034 (a radius on the thesis's lathe): the first pass takes the bar from 2200 to 2034
        JsonObject n135 = stock(text, 6);
        assertTrue(n135.get("found").getAsBoolean());
        assertEquals(2200, xAt(n135.getAsJsonObject("before"), -2000), 0.01);
        assertEquals(2200, xAt(n135.getAsJsonObject("before"), -4400), 0.01);
        assertEquals(2034, xAt(n135.getAsJsonObject("after"), -2000), 0.01);
        assertEquals(2200, xAt(n135.getAsJsonObject("after"), -9000), 0.01, "beyond the pass the bar is whole");
        // the insert sits where the pass ended, its tip at Z-4500 X2034
        JsonObject insert = n135.getAsJsonObject("insert");
        assertNotNull(insert);
        double nearest = Double.MAX_VALUE;
        for (int i = 0; i < insert.getAsJsonArray("z").size(); i++) {
            nearest = Math.min(nearest, Math.hypot(insert.getAsJsonArray("z").get(i).getAsDouble() + 4500,
                    insert.getAsJsonArray("x").get(i).getAsDouble() - 2034));
        }
        assertTrue(nearest < 1, "a corner of the insert at the tip: " + nearest);
        assertEquals(n135.get("first").getAsInt(), n135.get("last").getAsInt(), "one move on that line");
        // the next pass (N145 G01 Z-03550 at X1934) starts from what N135 left
        JsonObject n145 = stock(text, 9);
        assertEquals(2034, xAt(n145.getAsJsonObject("before"), -2000), 0.01);
        assertEquals(1934, xAt(n145.getAsJsonObject("after"), -2000), 0.01);
        // a rapid in the air removes nothing; a line without motion is not found
        JsonObject n100 = stock(text, 2);
        assertTrue(n100.get("found").getAsBoolean());
        assertEquals(n100.get("before"), n100.get("after"));
        assertFalse(stock(text, 4).get("found").getAsBoolean()); // G50 S5000 M11 M03 F150
    }

    @Test
    void aMoveOfACalledProgramNamesItsFile() throws Exception {
        start("haas");
        Files.writeString(dir.resolve("O1000.nc"), String.join("\n", StudioWorkbenchBrowserTest.O1000) + "\n");
        String main = String.join("\n", StudioWorkbenchBrowserTest.MAIN) + "\n";
        JsonArray moves = post("simulate", body("name", "main.nc", "text", main)).json().getAsJsonObject("drawing")
                .getAsJsonArray("moves");
        List<String> seen = new ArrayList<>();
        for (JsonElement m : moves) {
            JsonObject o = m.getAsJsonObject();
            seen.add((o.has("file") ? o.get("file").getAsString() + ":" : "") + o.get("line").getAsInt());
        }
        // G00 X46. Z2. (line 7), O1000's pass and retract (its lines 3, 4), G00 X100. Z100. (line 9)
        assertEquals(List.of("7", "O1000.nc:3", "O1000.nc:4", "9"), seen);
        // and so do the DMC commands of those blocks (each command of a packed line)
        JsonArray dmc = post("simulate", body("name", "main.nc", "text", main)).json().getAsJsonArray("dmc");
        List<String> called = new ArrayList<>();
        for (JsonElement l : dmc) {
            for (JsonElement part : l.getAsJsonObject().getAsJsonArray("parts")) {
                JsonObject c = part.getAsJsonObject();
                if (c.has("file")) {
                    called.add(c.get("file").getAsString() + ":" + c.get("line").getAsInt());
                }
            }
        }
        assertTrue(called.contains("O1000.nc:3") && called.stream().allMatch(c -> c.startsWith("O1000.nc:")), called.toString());
    }

    // ---- Configure ----

    static JsonObject values(String... pairs) {
        JsonObject v = new JsonObject();
        for (int i = 0; i < pairs.length; i += 2) {
            v.addProperty(pairs[i], pairs[i + 1]);
        }
        return v;
    }

    JsonObject impact(JsonObject values, String text) throws IOException {
        JsonObject req = text == null ? new JsonObject() : body("name", "bishop.nc", "text", text);
        req.add("values", values);
        StudioServerTest.Reply r = post("profile/impact", req);
        assertEquals(200, r.status(), r.body());
        return r.json();
    }

    static List<String> lineAndCode(JsonArray findings) {
        List<String> out = new ArrayList<>();
        for (JsonElement e : findings) {
            out.add(e.getAsJsonObject().get("line").getAsInt() + " " + e.getAsJsonObject().get("code").getAsString());
        }
        return out;
    }

    @Test
    void configureShowsTheProfileAndWhatAnEditChangesBeforeSavingIt() throws Exception {
        start("thesis-2004");
        String text = Files.readString(Path.of("samples/bishop.nc"));
        JsonObject form = get("/api/profile").json();
        assertEquals("thesis-2004", form.get("machine").getAsString());
        assertEquals("x.travel", form.getAsJsonArray("travel").get(0).getAsJsonObject().get("key").getAsString());
        assertEquals("-30000.0008, 880000.88888", form.getAsJsonArray("travel").get(1).getAsJsonObject().get("value").getAsString());
        assertEquals(6, form.getAsJsonArray("work").size());
        assertEquals(20, form.getAsJsonArray("toolOffsets").size()); // tools.count = 20: the thesis's 20 offsets
        assertEquals("counts", form.get("offsetsUnit").getAsString());

        // Z travel down to -15000 mm: the passes that reach below it (Z-4500 from a face at -13333.333)
        // become the checker's E015 (the control's own travel check, before any simulation)
        JsonObject shorter = impact(values("z.travel", "-15000, 880000.88888"), text);
        assertTrue(shorter.get("valid").getAsBoolean(), shorter.toString());
        List<String> became = lineAndCode(shorter.getAsJsonArray("became"));
        assertTrue(became.contains("6 E015"), became.toString()); // N135 G01 Z-04500
        assertTrue(became.contains("9 E015"), became.toString()); // N145 G01 Z-03550: -16883 mm
        assertFalse(became.contains("2 E015"), became.toString()); // N100 stays near the face
        assertFalse(became.contains("7 E015"), became.toString()); // N137 G00 back to Z+00100
        assertEquals(0, shorter.getAsJsonArray("gone").size());
        JsonObject same = impact(values("z.travel", "-30000.0008, 880000.88888"), text);
        assertEquals(0, same.getAsJsonArray("became").size());

        // what the loader refuses is refused here, at its key
        JsonObject reversed = impact(values("z.travel", "880000, -15000"), null);
        assertFalse(reversed.get("valid").getAsBoolean());
        assertEquals("z.travel", reversed.get("key").getAsString());
        JsonObject word = impact(values("work.G55", "left, 0"), null);
        assertFalse(word.get("valid").getAsBoolean());
        assertEquals("work.G55", word.get("key").getAsString());
        assertTrue(word.get("error").getAsString().contains("left"), word.toString());
        JsonObject home = impact(values("x.travel", "100, 200"), null); // home = 0, 0 is then outside X's travel
        assertFalse(home.get("valid").getAsBoolean());
        assertEquals("home", home.get("key").getAsString());

        // saved under the folder, as one file the loader reads; from then on the studio uses it
        JsonObject save = new JsonObject();
        save.addProperty("file", "lathe.machine");
        save.add("values", values("z.travel", "-15000, 880000.88888", "tool.2", "10, -20"));
        StudioServerTest.Reply saved = post("profile/save", save);
        assertEquals(200, saved.status(), saved.body());
        String written = Files.readString(dir.resolve("lathe.machine"));
        assertTrue(written.contains("z.travel = -15000, 880000.88888"), written);
        assertTrue(written.contains("\ntool.2 = 10, -20\n"), written);
        assertTrue(written.contains("# CCuentasMM"), "the profile's comments stay");
        Session reloaded = Session.open(Session.Options.defaults().withMachine(dir.resolve("lathe.machine").toString()));
        assertEquals(-15000, reloaded.profile().z().min() / reloaded.profile().z().countsPerMm(), 1e-6);
        JsonObject simulated = post("simulate", body("name", "bishop.nc", "text", text)).json();
        assertTrue(simulated.toString().contains("\"code\":\"E015\""), "the saved profile is in use");
        assertEquals("lathe.machine", get("/api/info").json().get("profileFile").getAsString());
        assertEquals("-15000, 880000.88888", get("/api/profile").json().getAsJsonArray("travel").get(1).getAsJsonObject()
                .get("value").getAsString());
        // and the way back: with the old travel those findings stop being
        JsonObject back = impact(values("z.travel", "-30000.0008, 880000.88888"), text);
        assertEquals(became, lineAndCode(back.getAsJsonArray("gone")));
        assertEquals(0, back.getAsJsonArray("became").size());
        // a second save of the same name asks first (force)
        StudioServerTest.assertRefused(409, post("profile/save", save));
        save.addProperty("force", true);
        assertEquals(200, post("profile/save", save).status());
        assertTrue(TableSource.builtIn().read("machines/thesis-2004.machine").contains("z.travel = -30000.0008"),
                "the shipped profile is never written");
    }

    @Test
    void theNewEndpointsAreGuardedAndRefuseMalformedRequests() throws Exception {
        start("thesis-2004");
        Path outside = Files.createTempDirectory("gcnc-outside");
        String hoverBody = "{\"name\":\"a.nc\",\"text\":\"G00 X1\\nM30\",\"line\":1}";
        String impactBody = "{\"values\":{\"x.travel\":\"-1, 1\"}}";
        String saveBody = "{\"file\":\"p.machine\",\"values\":{}}";
        String[][] posts = {{"hover", hoverBody}, {"stock", hoverBody}, {"profile/impact", impactBody},
            {"profile/save", saveBody}};
        for (String[] p : posts) {
            Map<String, String> noToken = StudioServerTest.good(studio);
            noToken.remove(Guard.TOKEN_HEADER);
            StudioServerTest.assertRefused(403, StudioServerTest.request(studio, "POST", "/api/" + p[0], noToken, p[1]));
            Map<String, String> otherPage = StudioServerTest.good(studio);
            otherPage.put("Origin", "http://evil.example");
            StudioServerTest.assertRefused(403, StudioServerTest.request(studio, "POST", "/api/" + p[0], otherPage, p[1]));
            Map<String, String> rebound = StudioServerTest.good(studio);
            rebound.put("Host", "evil.example:" + studio.port());
            StudioServerTest.assertRefused(403, StudioServerTest.request(studio, "POST", "/api/" + p[0], rebound, p[1]));
            StudioServerTest.assertRefused(405, get("/api/" + p[0]));
            StudioServerTest.assertRefused(400, StudioServerTest.request(studio, "POST", "/api/" + p[0],
                    StudioServerTest.good(studio), "{not json"));
        }
        Map<String, String> noToken = StudioServerTest.good(studio);
        noToken.remove(Guard.TOKEN_HEADER);
        StudioServerTest.assertRefused(403, StudioServerTest.request(studio, "GET", "/api/profile", noToken, null));
        StudioServerTest.assertRefused(405, post("profile", new JsonObject()));
        assertFalse(Files.exists(dir.resolve("p.machine")));

        // the line: a whole number from 1
        for (String line : new String[] {"0", "-3", "1.5", "\"six\"", "null", "1e12"}) {
            StudioServerTest.assertRefused(400, StudioServerTest.request(studio, "POST", "/api/hover", StudioServerTest.good(studio),
                    "{\"name\":\"a.nc\",\"text\":\"M30\",\"line\":" + line + "}"));
            StudioServerTest.assertRefused(400, StudioServerTest.request(studio, "POST", "/api/stock", StudioServerTest.good(studio),
                    "{\"name\":\"a.nc\",\"text\":\"M30\",\"line\":" + line + "}"));
        }
        // Configure edits its own keys only, one line each
        StudioServerTest.assertRefused(400, post("profile/impact", new JsonObject()));
        for (String[] bad : new String[][] {{"galil.model", "DMC-4040"}, {"name", "x"}, {"x.travel", "-1, 1\nm.3 = SB1"},
            {"x.travel", "-1, 1 # comment"}}) {
            JsonObject req = new JsonObject();
            req.add("values", values(bad));
            StudioServerTest.assertRefused(400, post("profile/impact", req));
        }
        // a profile is written under the folder only, as NAME.machine, never through a link
        Files.createSymbolicLink(dir.resolve("link.machine"), outside.resolve("target.machine"));
        Files.createSymbolicLink(dir.resolve("out"), outside);
        for (String[] name : new String[][] {{"../x.machine", "400"}, {outside.resolve("x.machine").toString(), "400"},
            {"bishop.nc", "400"}, {".machine", "400"}, {"link.machine", "403"}, {"out/x.machine", "403"}}) {
            JsonObject req = new JsonObject();
            req.addProperty("file", name[0]);
            req.add("values", new JsonObject());
            StudioServerTest.assertRefused(Integer.parseInt(name[1]), post("profile/save", req));
        }
        try (var files = Files.list(outside)) {
            assertEquals(List.of(), files.toList(), "nothing written outside the folder");
        }
        // a refused profile is not written
        JsonObject req = new JsonObject();
        req.addProperty("file", "bad.machine");
        req.add("values", values("z.travel", "1, 0"));
        StudioServerTest.assertRefused(400, post("profile/save", req));
        assertFalse(Files.exists(dir.resolve("bad.machine")));
        assertEquals(200, get("/api/info").status());
    }
}
