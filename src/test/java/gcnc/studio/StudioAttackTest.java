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
}
