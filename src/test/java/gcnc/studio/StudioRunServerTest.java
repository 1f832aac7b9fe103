package gcnc.studio;

import static gcnc.studio.StudioServerTest.request;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The Run endpoints with a plain HTTP client: each one refused without the token, from another
 * Origin or another Host; start refused without an arm, with another arm, a second time, and while
 * a run goes on; hold, resume, step and stop refused without a run; malformed requests answered
 * 400 and the studio serving on; a program that is not clean refused before any connection; and
 * a run on the studio's virtual controller followed over the event stream, held, resumed, stopped.
 */
class StudioRunServerTest {
    static Studio studio;
    static Path dir;

    static final List<String> POSTS = List.of("run/arm", "run/start", "run/hold", "run/resume", "run/step", "run/continue",
            "run/override", "run/stop");

    @BeforeAll
    static void start() throws Exception {
        dir = Files.createTempDirectory("gcnc-studio-run-api");
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        // five times real time, as StudioRunBrowserTest's: the bishop's 35 s take 7 s, long enough for a run to be
        // held, resumed and stopped (by requests that each take milliseconds), and a stopped one ends at once;
        // the resumed run to the end then takes 6 s instead of the 15 s it took at twice real time
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test", new Studio.Running(5, null)));
    }

    @AfterAll
    static void stop() {
        studio.close();
    }

    @BeforeEach
    void theBishop() throws IOException {
        Files.copy(Path.of("samples/bishop.nc"), dir.resolve("bishop.nc"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Files.deleteIfExists(dir.resolve("bishop.dmc"));
        Files.deleteIfExists(dir.resolve("bishop.dmc.map"));
    }

    @AfterEach
    void noRunLeft() throws Exception {
        post("run/stop", "{}"); // 409 when none: either way none is left for the next test
        waitUntil(() -> get("run").json().get("state").getAsString().equals("running") ? null : true);
    }

    static Map<String, String> good() {
        return StudioServerTest.good(studio);
    }

    static StudioServerTest.Reply post(String endpoint, String body) throws IOException {
        return request(studio, "POST", "/api/" + endpoint, good(), body);
    }

    static StudioServerTest.Reply get(String endpoint) throws IOException {
        return request(studio, "GET", "/api/" + endpoint, good(), null);
    }

    static final String VIRTUAL = "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"virtual\"}}";

    /** Polls {@code what} until it gives a value (at most 60 s). */
    static <T> T waitUntil(java.util.concurrent.Callable<T> what) throws Exception {
        long end = System.nanoTime() + 60_000_000_000L;
        while (System.nanoTime() < end) {
            T v = what.call();
            if (v != null) {
                return v;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("not in 60 s");
    }

    /** The events of the last run (GET /api/run) named {@code name}. */
    static List<JsonObject> events(String name) throws IOException {
        return get("run").json().getAsJsonArray("events").asList().stream().map(JsonElement::getAsJsonObject)
                .filter(e -> e.get("event").getAsString().equals(name)).toList();
    }

    static JsonObject arm(String body) throws IOException {
        StudioServerTest.Reply r = post("run/arm", body);
        assertEquals(200, r.status(), r.body());
        return r.json();
    }

    // ---- the guard ----

    @Test
    void everyRunEndpointIsRefusedWithoutTheTokenFromAnotherPageOrAnotherHost() throws IOException {
        for (String e : POSTS) {
            Map<String, String> noToken = good();
            noToken.remove(Guard.TOKEN_HEADER);
            assertEquals(403, request(studio, "POST", "/api/" + e, noToken, VIRTUAL).status(), e);
            Map<String, String> wrongToken = good();
            wrongToken.put(Guard.TOKEN_HEADER, studio.token().substring(1) + "0");
            assertEquals(403, request(studio, "POST", "/api/" + e, wrongToken, VIRTUAL).status(), e);
            Map<String, String> otherPage = good();
            otherPage.put("Origin", "http://evil.example");
            assertEquals(403, request(studio, "POST", "/api/" + e, otherPage, VIRTUAL).status(), e);
            Map<String, String> rebound = good();
            rebound.put("Host", "evil.example:" + studio.port());
            assertEquals(403, request(studio, "POST", "/api/" + e, rebound, VIRTUAL).status(), e);
        }
        Map<String, String> noToken = good();
        noToken.remove(Guard.TOKEN_HEADER);
        assertEquals(403, request(studio, "GET", "/api/run", noToken, null).status());
        // none of it armed anything, and nothing was compiled
        assertEquals("idle", get("run").json().get("state").getAsString());
        assertFalse(Files.exists(dir.resolve("bishop.dmc")));
    }

    @Test
    void startNeedsAnArmAndEveryCommandNeedsARun() throws IOException {
        StudioServerTest.Reply r = post("run/start", "{\"arm\":\"0123456789abcdef01234567\"}");
        assertEquals(409, r.status(), r.body());
        assertTrue(r.json().get("error").getAsString().contains("arm the program first"), r.body());
        for (String e : List.of("run/hold", "run/resume", "run/step", "run/stop")) {
            assertEquals(409, post(e, "{}").status(), e);
        }
        assertEquals(409, post("run/override", "{\"percent\":50}").status());
    }

    @Test
    void malformedRequestsAreAnswered400AndTheStudioServesOn() throws IOException {
        String[] arms = {
            "not json", "[]", "\"x\"", "{}", "{\"name\":\"bishop.nc\"}",
            "{\"name\":\"bishop.nc\",\"target\":\"virtual\"}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"ftp\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"tcp\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"tcp\",\"address\":\"a b\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"tcp\",\"address\":\"10.0.0.5:99999\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"tcp\",\"address\":\"[::1]:23\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"serial\",\"device\":\"dev/ttyS0\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"serial\",\"device\":\"/dev/../etc/passwd\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"serial\",\"device\":\"/dev/ttyS0\",\"baud\":1234}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"serial\",\"device\":\"/dev/ttyS0\",\"handshake\":\"x\"}}",
            // this studio was given no serial ports (the command line gives jSerialComm's)
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"serial\",\"device\":\"/dev/ttyS0\"}}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"virtual\"},\"step\":\"yes\"}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"virtual\"},\"resumeAt\":\"x\"}",
            "{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"virtual\"},\"resumeAt\":\"0\"}",
            "{\"name\":\"../bishop.nc\",\"target\":{\"kind\":\"virtual\"}}",
            "{\"name\":\"/etc/passwd\",\"target\":{\"kind\":\"virtual\"}}",
        };
        for (String body : arms) {
            StudioServerTest.Reply r = post("run/arm", body);
            assertEquals(400, r.status(), body + " -> " + r.body());
            assertTrue(r.json().has("error"), r.body());
        }
        for (String body : new String[] {"{}", "{\"arm\":5}", "nope"}) {
            assertEquals(400, post("run/start", body).status(), body);
        }
        for (String body : new String[] {"{}", "{\"percent\":500}", "{\"percent\":\"50\"}", "{\"percent\":50.5}"}) {
            assertEquals(400, post("run/override", body).status(), body);
        }
        assertEquals(400, post("run/hold", "[").status());
        assertEquals(405, get("run/arm").status());
        assertEquals(405, post("run", "{}").status());
        assertEquals(404, post("run/fly", "{}").status());
        assertEquals(404, post("run/arm", "{\"name\":\"none.nc\",\"target\":{\"kind\":\"virtual\"}}").status());
        assertEquals(200, get("info").status());
        assertEquals("idle", get("run").json().get("state").getAsString());
    }

    @Test
    void aProgramThatIsNotCleanIsRefusedAndNothingIsConnected() throws Exception {
        // the broken line of StudioBrowserTest: E006 on N135
        Files.writeString(dir.resolve("broken.nc"), Files.readString(dir.resolve("bishop.nc"))
                .replace("N135 G01 Z-04500", "N135 G01 Z-04500 Q"));
        try (ServerSocket controller = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            controller.setSoTimeout(300);
            JsonObject a = arm("{\"name\":\"broken.nc\",\"target\":{\"kind\":\"tcp\",\"address\":\"127.0.0.1:"
                    + controller.getLocalPort() + "\"}}");
            assertFalse(a.get("armed").getAsBoolean());
            assertTrue(a.get("refused").getAsString().contains("not clean"), a.toString());
            assertEquals("E006", a.getAsJsonObject("diagnostics").getAsJsonArray("diagnostics").get(0).getAsJsonObject()
                    .get("code").getAsString());
            assertFalse(a.has("arm"));
            assertThrows(SocketTimeoutException.class, controller::accept, "not one byte may reach the controller");
        }
        assertFalse(Files.exists(dir.resolve("broken.dmc")), "nothing written either, as gcnc run");
        assertEquals("idle", get("run").json().get("state").getAsString());
    }

    @Test
    void aControllerThatDoesNotAnswerIsNotArmed() throws Exception {
        int free;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            free = s.getLocalPort();
        }
        JsonObject a = arm("{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"tcp\",\"address\":\"127.0.0.1:" + free + "\"}}");
        assertFalse(a.get("armed").getAsBoolean());
        JsonObject f = a.getAsJsonArray("events").get(0).getAsJsonObject();
        assertEquals("E817", f.get("code").getAsString(), a.toString());
        assertEquals(409, post("run/start", "{\"arm\":\"x\"}").status());
    }

    @Test
    void oneRunAtATimeEachArmMovesOnceAndTheEventStreamCarriesTheRun() throws Exception {
        try (Socket sse = new Socket(InetAddress.getLoopbackAddress(), studio.port())) {
            sse.setSoTimeout(60000);
            sse.getOutputStream().write(("GET /api/events?token=" + studio.token() + " HTTP/1.1\r\nHost: 127.0.0.1:"
                    + studio.port() + "\r\n\r\n").getBytes(StandardCharsets.UTF_8));
            InputStream in = sse.getInputStream();
            StringBuilder seen = new StringBuilder();
            readUntil(in, seen, "event: files");

            JsonObject a = arm(VIRTUAL);
            assertTrue(a.get("armed").getAsBoolean(), a.toString());
            String id = a.get("arm").getAsString();
            assertEquals("armed", get("run").json().get("state").getAsString());
            // the dry run did not move the machine: pre-flight saw it at home, and the arm is still to start
            JsonObject preflight = a.getAsJsonArray("events").asList().stream().map(JsonElement::getAsJsonObject)
                    .filter(e -> e.get("event").getAsString().equals("preflight")).findFirst().orElseThrow();
            assertEquals("[0,0]", preflight.get("position").toString());
            assertEquals(200, post("run/start", "{\"arm\":\"" + id + "\"}").status());
            // a second start with the same arm, another arm and a second run are all refused while it goes on
            assertEquals(409, post("run/start", "{\"arm\":\"" + id + "\"}").status());
            assertEquals(409, post("run/arm", VIRTUAL).status());
            readUntil(in, seen, "\"event\":\"block\"");
            assertTrue(seen.toString().contains("event: run\ndata: {\"event\":\"connected\""), seen.toString());
            // hold (once), resume, override; step is for step mode only
            assertEquals(200, post("run/hold", "{}").status());
            assertEquals(409, post("run/hold", "{}").status());
            readUntil(in, seen, "{\"event\":\"hold\",\"held\":true");
            assertEquals(200, post("run/resume", "{}").status());
            assertEquals(409, post("run/resume", "{}").status());
            readUntil(in, seen, "{\"event\":\"hold\",\"held\":false");
            assertEquals(409, post("run/step", "{}").status());
            assertEquals(200, post("run/override", "{\"percent\":150}").status());
            readUntil(in, seen, "\"override\":1.5");
            // stopped during a hold: the sender's polls go on, so the block it names is the one the axes stand in
            assertEquals(200, post("run/hold", "{}").status());
            readUntil(in, seen, "{\"event\":\"hold\",\"held\":true,\"override\":1.5");
            Thread.sleep(500);
            assertEquals(200, post("run/stop", "{}").status());
            readUntil(in, seen, "\"event\":\"run-ended\",\"status\":3");
        }
        JsonObject stopped = events("stopped").get(0);
        assertEquals("E828", stopped.get("reason").getAsString());
        int at = stopped.get("executing").getAsInt();
        assertTrue(stopped.get("where").getAsString().matches("X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts -?\\d+,-?\\d+\\)"),
                stopped.toString());
        assertTrue(stopped.get("resume").getAsString().matches("gcnc run bishop\\.nc --machine thesis-2004 --tcp 127\\.0\\.0\\.1:\\d+"
                + " --resume-at " + stopped.get("resumeAt").getAsString()), stopped.toString());
        assertEquals(at, Integer.parseInt(stopped.get("resumeAt").getAsString().split(":")[0]));
        assertEquals("idle", get("run").json().get("state").getAsString());
        assertEquals(3, get("run").json().get("ended").getAsInt());
        // the stopped arm cannot start again: a resume is armed anew, from where the axes stand (not homed)
        JsonObject resume = arm("{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"virtual\"},\"resumeAt\":\""
                + stopped.get("resumeAt").getAsString() + "\"}");
        assertTrue(resume.get("armed").getAsBoolean(), resume.toString());
        assertFalse(resume.toString().contains("\"position\":[0,0]"), resume.toString());
        assertEquals(200, post("run/start", "{\"arm\":\"" + resume.get("arm").getAsString() + "\"}").status());
        waitUntil(() -> get("run").json().has("ended") ? true : null);
        assertEquals(0, get("run").json().get("ended").getAsInt(), get("run").body());
        assertEquals(1, events("finished").size());
    }

    @Test
    void aProgramChangedSinceItsArmMustBeArmedAgain() throws Exception {
        JsonObject a = arm(VIRTUAL);
        assertTrue(a.get("armed").getAsBoolean(), a.toString());
        Files.writeString(dir.resolve("bishop.nc"), Files.readString(dir.resolve("bishop.nc")).replace("F150", "F140"));
        StudioServerTest.Reply r = post("run/start", "{\"arm\":\"" + a.get("arm").getAsString() + "\"}");
        assertEquals(409, r.status(), r.body());
        assertTrue(r.json().get("error").getAsString().contains("changed since it was armed"), r.body());
        assertEquals(409, post("run/start", "{\"arm\":\"" + a.get("arm").getAsString() + "\"}").status(), "spent");
    }

    @Test
    void stepModeRunsABlockPerStep() throws Exception {
        JsonObject a = arm("{\"name\":\"bishop.nc\",\"target\":{\"kind\":\"virtual\"},\"step\":true}");
        assertTrue(a.get("armed").getAsBoolean(), a.toString());
        assertEquals(200, post("run/start", "{\"arm\":\"" + a.get("arm").getAsString() + "\"}").status());
        JsonObject first = waitUntil(() -> events("step-wait").isEmpty() ? null : events("step-wait").get(0));
        Thread.sleep(300);
        assertEquals(1, events("step-wait").size(), "it waits for the step");
        assertEquals(200, post("run/step", "{}").status());
        JsonObject second = waitUntil(() -> events("step-wait").size() < 2 ? null : events("step-wait").get(1));
        assertTrue(second.get("line").getAsInt() > first.get("line").getAsInt(), first + " " + second);
        assertEquals(200, post("run/stop", "{}").status());
        waitUntil(() -> get("run").json().has("ended") ? true : null);
        assertEquals(3, get("run").json().get("ended").getAsInt());
    }

    @Test
    void aProgramStopWaitsForCycleStartAndTheRunGoesOnAfterIt() throws Exception {
        // the bishop with an M00 after its tenth line: the run stops there, moves nothing, and goes on after continue
        List<String> lines = Files.readAllLines(Path.of("samples/bishop.nc"));
        lines.add(10, "M00 (CHECK THE PART)");
        Files.write(dir.resolve("stop.nc"), lines);
        assertEquals(409, post("run/continue", "{}").status(), "no run, no stop to go on from");
        JsonObject a = arm("{\"name\":\"stop.nc\",\"target\":{\"kind\":\"virtual\"}}");
        assertTrue(a.get("armed").getAsBoolean(), a.toString());
        assertEquals(200, post("run/start", "{\"arm\":\"" + a.get("arm").getAsString() + "\"}").status());
        JsonObject stop = waitUntil(() -> events("program-stop").isEmpty() ? null : events("program-stop").get(0));
        assertEquals(11, stop.get("line").getAsInt(), stop.toString());
        assertTrue(stop.toString().contains("CHECK THE PART"), stop.toString());
        assertTrue(events("program-stop-continued").isEmpty(), "it waits for the operator");
        assertEquals(200, post("run/continue", "{}").status());
        waitUntil(() -> events("program-stop-continued").isEmpty() ? null : true);
        waitUntil(() -> get("run").json().has("ended") ? true : null);
        assertEquals(0, get("run").json().get("ended").getAsInt(), get("run").body());
    }

    private static void readUntil(InputStream in, StringBuilder seen, String wanted) throws IOException {
        byte[] buf = new byte[8192];
        while (!seen.toString().contains(wanted)) {
            int n = in.read(buf);
            if (n < 0) {
                throw new IOException("the stream ended before " + wanted + ": " + seen);
            }
            seen.append(new String(buf, 0, n, StandardCharsets.UTF_8));
        }
    }
}
