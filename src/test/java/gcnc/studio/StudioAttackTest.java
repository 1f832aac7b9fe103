package gcnc.studio;

import static gcnc.studio.StudioServerTest.assertRefused;
import static gcnc.studio.StudioServerTest.body;
import static gcnc.studio.StudioServerTest.good;
import static gcnc.studio.StudioServerTest.request;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * What an attack on the studio found (issue 35): two pages saving on one version at the same moment,
 * a program past the size limit, and requests a browser never sends. Each test failed before its fix.
 */
class StudioAttackTest {
    static Studio studio;
    static Path dir;

    @BeforeAll
    static void start() throws Exception {
        dir = Files.createTempDirectory("gcnc-studio-attack");
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test"));
    }

    @AfterAll
    static void stop() {
        studio.close();
    }

    static StudioServerTest.Reply post(String endpoint, JsonObject body) throws IOException {
        return request(studio, "POST", "/api/" + endpoint, good(studio), body.toString());
    }

    @Test
    void twoPagesSavingOnOneVersionAtOnceOneWinsTheOtherGets409() throws Exception {
        ExecutorService pages = Executors.newFixedThreadPool(2);
        try {
            for (int round = 0; round < 40; round++) {
                String name = "race" + round + ".nc";
                Files.writeString(dir.resolve(name), "G00 X0\nM30\n");
                String version = request(studio, "GET", "/api/file?name=" + name, good(studio), null).json()
                        .get("version").getAsString();
                CountDownLatch go = new CountDownLatch(1);
                List<Future<StudioServerTest.Reply>> replies = new ArrayList<>();
                for (String text : new String[] {"G00 X1\nM30\n", "G00 X2\nM30\n"}) {
                    replies.add(pages.submit(() -> {
                        go.await();
                        return post("save", body("name", name, "text", text, "version", version));
                    }));
                }
                go.countDown();
                StudioServerTest.Reply a = replies.get(0).get();
                StudioServerTest.Reply b = replies.get(1).get();
                List<Integer> statuses = new ArrayList<>(List.of(a.status(), b.status()));
                statuses.sort(null);
                assertEquals(List.of(200, 409), statuses, "round " + round + ": " + a.body() + " / " + b.body());
                StudioServerTest.Reply won = a.status() == 200 ? a : b;
                assertRefused(409, a.status() == 200 ? b : a);
                // the edit that was acknowledged is the one on disk
                assertEquals(won.json().get("text").getAsString(), Files.readString(dir.resolve(name)), "round " + round);
            }
        } finally {
            pages.shutdownNow();
        }
    }

    @Test
    void aProgramPastTheSizeLimitIsNotSaved() throws IOException {
        String big = "G01 X1 Z1 F0.1\n".repeat((int) (Workspace.MAX_BYTES / 15) + 1000);
        assertTrue(big.length() > Workspace.MAX_BYTES);
        StudioServerTest.Reply r = post("save", body("name", "big.nc", "text", big));
        assertEquals(413, r.status(), r.body().substring(0, Math.min(200, r.body().length())));
        assertTrue(Files.notExists(dir.resolve("big.nc")));
    }

    /** A request written as it is, and the status of the answer (the socket waits at most 20 s). */
    static int raw(String head) throws IOException {
        try (java.net.Socket s = new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), studio.port())) {
            s.setSoTimeout(20000);
            s.getOutputStream().write(head.getBytes(java.nio.charset.StandardCharsets.ISO_8859_1));
            String answer = new String(s.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.ISO_8859_1);
            return Integer.parseInt(answer.substring(9, 12));
        }
    }

    @Test
    void connectionsThatSendHalfAHeadLeaveTheStudioAnsweringStopIncluded() throws IOException {
        List<java.net.Socket> half = new ArrayList<>();
        try {
            for (int i = 0; i < 12; i++) {
                java.net.Socket s = new java.net.Socket(java.net.InetAddress.getLoopbackAddress(), studio.port());
                s.getOutputStream().write("GET /api/info HTTP/1.1\r\nHost: 127.0".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
                s.getOutputStream().flush();
                half.add(s);
            }
            // each within the client's 20 s (they waited minutes: six threads, each held by half a head)
            assertEquals(200, request(studio, "GET", "/api/info", good(studio), null).status());
            assertRefused(409, post("run/stop", new JsonObject())); // Stop answers: there is no run to stop
            assertEquals(200, request(studio, "GET", "/api/files", good(studio), null).status());
        } finally {
            for (java.net.Socket s : half) {
                s.close();
            }
        }
    }

    @Test
    void aSecondHostOrAnAbsoluteTargetIsRefused() throws IOException {
        String host = "Host: 127.0.0.1:" + studio.port() + "\r\n";
        String token = Guard.TOKEN_HEADER + ": " + studio.token() + "\r\n";
        assertEquals(200, raw("GET /api/info HTTP/1.1\r\n" + host + token + "Connection: close\r\n\r\n"));
        assertEquals(400, raw("GET /api/info HTTP/1.1\r\n" + host + "Host: evil.example\r\n" + token
                + "Connection: close\r\n\r\n"));
        assertEquals(400, raw("GET http://evil.example/api/info HTTP/1.1\r\n" + host + token + "Connection: close\r\n\r\n"));
        assertEquals(400, raw("GET http://127.0.0.1:" + studio.port() + "/api/info HTTP/1.1\r\n" + host + token
                + "Connection: close\r\n\r\n"));
    }
}
