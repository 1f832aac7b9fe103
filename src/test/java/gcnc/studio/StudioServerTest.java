package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.ConnectException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The studio's server with a plain HTTP client (a socket: the tests set Host and Origin as an attacker's
 * page or a rebinding name would): each refusal, the files under DIR only, and the API's answers
 * against the command line's own for the same program.
 */
class StudioServerTest {
    static Studio studio;
    static Path dir;
    static Path outside;

    @BeforeAll
    static void start() throws Exception {
        dir = Files.createTempDirectory("gcnc-studio");
        outside = Files.createTempDirectory("gcnc-outside");
        Session s = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        studio = Studio.start(new Studio.Config(dir, 0, s, ErrorMessages.Lang.EN, "test"));
    }

    @AfterAll
    static void stop() {
        studio.close();
    }

    @BeforeEach
    void freshFolder() throws IOException {
        try (var files = Files.walk(dir)) {
            for (Path p : files.sorted(Collections.reverseOrder()).toList()) {
                if (!p.equals(dir)) {
                    Files.delete(p);
                }
            }
        }
        Files.copy(Path.of("samples/bishop.nc"), dir.resolve("bishop.nc"));
    }

    // ---- a raw HTTP client ----

    record Reply(int status, String head, String body) {
        JsonObject json() {
            return JsonParser.parseString(body).getAsJsonObject();
        }
    }

    /** One request; {@code headers} null values are left out (so Host can be missing). */
    static Reply request(String method, String target, Map<String, String> headers, String body) throws IOException {
        return request(studio, method, target, headers, body);
    }

    /** One request to the studio {@code on}. */
    static Reply request(Studio on, String method, String target, Map<String, String> headers, String body) throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), on.port())) {
            s.setSoTimeout(20000);
            StringBuilder req = new StringBuilder(method + " " + target + " HTTP/1.1\r\n");
            for (Map.Entry<String, String> h : headers.entrySet()) {
                if (h.getValue() != null) {
                    req.append(h.getKey()).append(": ").append(h.getValue()).append("\r\n");
                }
            }
            byte[] b = body == null ? new byte[0] : body.getBytes(StandardCharsets.UTF_8);
            req.append("Connection: close\r\nContent-Length: ").append(b.length).append("\r\n\r\n");
            OutputStream out = s.getOutputStream();
            out.write(req.toString().getBytes(StandardCharsets.UTF_8));
            out.write(b);
            out.flush();
            return parse(s.getInputStream().readAllBytes());
        }
    }

    private static Reply parse(byte[] raw) {
        String all = new String(raw, StandardCharsets.UTF_8);
        int status = Integer.parseInt(all.substring(9, 12));
        int head = all.indexOf("\r\n\r\n");
        return new Reply(status, head < 0 ? all : all.substring(0, head), head < 0 ? "" : all.substring(head + 4));
    }

    static Map<String, String> good() {
        return good(studio);
    }

    /** The headers the studio's own page sends to {@code on}. */
    static Map<String, String> good(Studio on) {
        Map<String, String> h = new java.util.LinkedHashMap<>();
        h.put("Host", "127.0.0.1:" + on.port());
        h.put(Guard.TOKEN_HEADER, on.token());
        return h;
    }

    static Reply get(String target) throws IOException {
        return request("GET", target, good(), null);
    }

    static Reply post(String endpoint, JsonObject body) throws IOException {
        return request("POST", "/api/" + endpoint, good(), body.toString());
    }

    static JsonObject body(String... pairs) {
        JsonObject o = new JsonObject();
        for (int i = 0; i < pairs.length; i += 2) {
            o.addProperty(pairs[i], pairs[i + 1]);
        }
        return o;
    }

    static void assertRefused(int status, Reply r) {
        assertEquals(status, r.status(), r.body());
        assertTrue(r.json().get("error").getAsString().length() > 5, r.body());
    }

    // ---- 1. server and safety ----

    @Test
    void listensOnTheLoopbackAddressOnly() throws Exception {
        assertEquals("127.0.0.1", studio.url().getHost());
        Optional<InetAddress> lan = Collections.list(NetworkInterface.getNetworkInterfaces()).stream()
                .flatMap(n -> Collections.list(n.getInetAddresses()).stream())
                .filter(a -> a instanceof Inet4Address && !a.isLoopbackAddress()).findFirst();
        if (lan.isPresent()) { // a machine with a network address: the studio is not reachable on it
            try (Socket s = new Socket()) {
                assertThrows(ConnectException.class, () -> s.connect(new InetSocketAddress(lan.get(), studio.port()), 2000));
            }
        }
        assertEquals(200, get("/api/info").status());
    }

    @Test
    void aRequestForAnotherHostIsRefused() throws IOException {
        // DNS rebinding: the attacker's name resolves to 127.0.0.1, the browser still sends its own name
        for (String host : new String[] {"evil.example:" + studio.port(), "evil.example", "127.0.0.1:" + (studio.port() + 1),
                "127.0.0.1", "0.0.0.0:" + studio.port(), "localhost.evil.example:" + studio.port()}) {
            Map<String, String> h = good();
            h.put("Host", host);
            assertRefused(403, request("GET", "/api/info", h, null));
        }
        Map<String, String> none = good();
        none.put("Host", null);
        assertEquals(403, request("GET", "/api/files", none, null).status());
        Map<String, String> local = good();
        local.put("Host", "localhost:" + studio.port());
        assertEquals(200, request("GET", "/api/files", local, null).status());
    }

    @Test
    void theApiAndThePageNeedTheToken() throws IOException {
        Map<String, String> h = good();
        h.remove(Guard.TOKEN_HEADER);
        assertRefused(403, request("GET", "/api/files", h, null));
        assertRefused(403, request("POST", "/api/check", h, body("name", "a.nc", "text", "G00 X1").toString()));
        assertRefused(403, request("GET", "/", h, null));
        String wrong = studio.token().substring(1) + "0";
        h.put(Guard.TOKEN_HEADER, wrong);
        assertRefused(403, request("GET", "/api/files", h, null));
        h.remove(Guard.TOKEN_HEADER);
        assertRefused(403, request("GET", "/api/files?token=" + wrong, h, null));
        assertEquals(200, request("GET", "/api/files?token=" + studio.token(), h, null).status());
        assertEquals(200, request("GET", "/?token=" + studio.token(), h, null).status());
        // the editor's code is no secret: CodeMirror and the page's scripts need no token
        assertEquals(200, request("GET", "/static/studio.js", h, null).status());
    }

    @Test
    void aRequestFromAnotherPageIsRefused() throws IOException {
        for (String origin : new String[] {"http://evil.example", "null", "https://127.0.0.1:" + studio.port(),
                "http://127.0.0.1:" + (studio.port() + 1), "http://127.0.0.1:" + studio.port() + ".evil.example"}) {
            Map<String, String> h = good();
            h.put("Origin", origin);
            assertRefused(403, request("POST", "/api/save", h,
                    body("name", "bishop.nc", "text", "M30", "version", "x").toString()));
        }
        assertEquals(Files.readString(Path.of("samples/bishop.nc")), Files.readString(dir.resolve("bishop.nc")));
        Map<String, String> self = good();
        self.put("Origin", "http://127.0.0.1:" + studio.port());
        assertEquals(200, request("GET", "/api/files", self, null).status());
    }

    @Test
    void aMalformedRequestIsA400WithAJsonErrorAndTheServerGoesOn() throws IOException {
        assertRefused(400, request("POST", "/api/check", good(), "{not json"));
        assertRefused(400, request("POST", "/api/check", good(), "[1, 2]"));
        assertRefused(400, request("POST", "/api/check", good(), ""));
        assertRefused(400, post("check", body("text", "G00 X1")));
        JsonObject wrongType = body("name", "a.nc");
        wrongType.addProperty("text", 42);
        assertRefused(400, post("check", wrongType));
        JsonObject wrongFlag = body("name", "a.nc", "text", "M30");
        wrongFlag.addProperty("force", "yes");
        assertRefused(400, post("save", wrongFlag));
        assertRefused(404, get("/api/nothing"));
        assertRefused(405, get("/api/check"));
        assertRefused(405, request("POST", "/api/files", good(), "{}"));
        assertRefused(404, get("/webjars/crelt/0.0.1/index.js"));
        assertRefused(404, get("/webjars/crelt/1.0.7/../../../gcnc/studio/Studio.class"));
        // what the JDK's own server cannot parse it answers itself; the studio goes on serving
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), studio.port())) {
            s.getOutputStream().write("\u0000\u0001 GARBAGE\r\n\r\n".getBytes(StandardCharsets.ISO_8859_1));
            s.setSoTimeout(5000);
            try (InputStream in = s.getInputStream()) {
                in.readAllBytes();
            } catch (IOException closed) {
                // a connection it drops is an answer too
            }
        }
        assertEquals(400, request("GET", "/api/file?name=%zz", good(), null).status());
        assertEquals(200, get("/api/info").status());
    }

    @Test
    void thePageMapsCodeMirrorToThePinnedWebJarsInsideTheJar() throws IOException {
        Reply page = get("/?token=" + studio.token());
        assertEquals(200, page.status());
        String html = page.body();
        int from = html.indexOf("<script type=\"importmap\">") + "<script type=\"importmap\">".length();
        JsonObject imports = JsonParser.parseString(html.substring(from, html.indexOf("</script>", from)))
                .getAsJsonObject().getAsJsonObject("imports");
        assertEquals(15, imports.size());
        assertEquals("/webjars/codemirror/6.0.2/dist/index.js", imports.get("codemirror").getAsString());
        assertEquals("/webjars/codemirror__view/6.43.7/dist/index.js", imports.get("@codemirror/view").getAsString());
        assertEquals("/webjars/style-mod/4.1.3/src/style-mod.js", imports.get("style-mod").getAsString());
        for (String name : imports.keySet()) { // every module the map names is served, from the jar
            Reply js = get(imports.get(name).getAsString());
            assertEquals(200, js.status(), name);
            assertTrue(js.body().contains("export"), name);
        }
        // only the studio's scripts and this import map may run on the page
        String csp = page.head().lines().filter(l -> l.toLowerCase(java.util.Locale.ROOT).startsWith("content-security-policy:"))
                .findFirst().orElseThrow();
        assertTrue(csp.contains("script-src 'self' 'sha256-"), csp);
        assertTrue(csp.contains("connect-src 'self'"), csp);
        assertTrue(page.head().contains("X-frame-options: DENY") || page.head().contains("X-Frame-Options: DENY"), page.head());
    }

    // ---- 1. files under DIR only ----

    @Test
    void namesThatLeaveTheFolderAreRefused() throws IOException {
        Files.writeString(outside.resolve("secret.nc"), "(secret)\nM30\n");
        for (String name : new String[] {"../" + outside.getFileName() + "/secret.nc", outside.resolve("secret.nc").toString(),
                "./bishop.nc", "a//b.nc", "a\\..\\b.nc", "c:bishop.nc", "bi\u0000shop.nc", ""}) {
            Reply r = get("/api/file?name=" + java.net.URLEncoder.encode(name, StandardCharsets.UTF_8));
            assertRefused(400, r);
            assertRefused(400, post("save", body("name", name, "text", "M30")));
        }
        assertTrue(Files.readString(outside.resolve("secret.nc")).contains("secret"));
    }

    @Test
    void linksOutOfTheFolderAndDevicesAreNeitherListedNorReadNorWritten() throws IOException {
        Files.writeString(outside.resolve("secret.nc"), "(secret)\nM30\n");
        Files.createSymbolicLink(dir.resolve("link.nc"), outside.resolve("secret.nc"));
        Files.createSymbolicLink(dir.resolve("out"), outside);
        Files.createSymbolicLink(dir.resolve("zero.nc"), Path.of("/dev/zero"));
        Files.createDirectory(dir.resolve("folder.nc"));
        List<String> listed = new ArrayList<>();
        get("/api/files").json().getAsJsonArray("files").forEach(f -> listed.add(f.getAsJsonObject().get("name").getAsString()));
        assertEquals(List.of("bishop.nc"), listed);
        assertRefused(403, get("/api/file?name=link.nc"));
        assertRefused(403, get("/api/file?name=out/secret.nc"));
        assertRefused(403, get("/api/file?name=zero.nc"));
        assertRefused(403, get("/api/file?name=folder.nc"));
        assertRefused(404, get("/api/file?name=none.nc"));
        assertRefused(403, post("save", body("name", "link.nc", "text", "M30")));
        assertRefused(403, post("save", body("name", "out/new.nc", "text", "M30")));
        assertRefused(403, post("save", body("name", "zero.nc", "text", "M30")));
        assertRefused(403, post("save", body("name", "folder.nc", "text", "M30")));
        assertRefused(403, post("save", body("name", "no/such/folder.nc", "text", "M30")));
        assertRefused(400, post("save", body("name", "notes.txt", "text", "M30")));
        assertEquals("(secret)\nM30\n", Files.readString(outside.resolve("secret.nc")));
        assertFalse(Files.exists(outside.resolve("new.nc")));
        // a compile whose DMC would be written through a link out of the folder writes nothing
        Files.writeString(outside.resolve("target.dmc"), "kept\n");
        Files.createSymbolicLink(dir.resolve("bishop.dmc"), outside.resolve("target.dmc"));
        assertRefused(403, post("compile", body("name", "bishop.nc")));
        assertEquals("kept\n", Files.readString(outside.resolve("target.dmc")));
    }

    // ---- 2. files ----

    @Test
    void listOpenSaveNewAndSaveAs() throws IOException {
        Files.createDirectories(dir.resolve("parts/op2"));
        Files.writeString(dir.resolve("parts/op2/FACE.NC"), "M30\n");
        Files.writeString(dir.resolve("notes.txt"), "not a program");
        List<String> listed = new ArrayList<>();
        get("/api/files").json().getAsJsonArray("files").forEach(f -> listed.add(f.getAsJsonObject().get("name").getAsString()));
        assertEquals(List.of("bishop.nc", "parts/op2/FACE.NC"), listed);

        JsonObject opened = get("/api/file?name=parts/op2/FACE.NC").json();
        assertEquals("M30\n", opened.get("text").getAsString());
        String version = opened.get("version").getAsString();

        // save: the version opened must still be the one on disk
        JsonObject saved = post("save", body("name", "parts/op2/FACE.NC", "text", "G00 X1\nM30\n", "version", version)).json();
        assertEquals("G00 X1\nM30\n", Files.readString(dir.resolve("parts/op2/FACE.NC")));
        assertFalse(version.equals(saved.get("version").getAsString()));
        // a save from a page that opened an older version is refused, and the file is left as it is
        assertRefused(409, post("save", body("name", "parts/op2/FACE.NC", "text", "lost?", "version", version)));
        assertEquals("G00 X1\nM30\n", Files.readString(dir.resolve("parts/op2/FACE.NC")));
        JsonObject forced = body("name", "parts/op2/FACE.NC", "text", "M02\n", "version", version);
        forced.addProperty("force", true);
        assertEquals(200, post("save", forced).status());
        assertEquals("M02\n", Files.readString(dir.resolve("parts/op2/FACE.NC")));

        // new (no version): made; a second new of the same name is refused (save as onto an existing file)
        assertEquals(200, post("save", body("name", "new.nc", "text", "M30\n")).status());
        assertEquals("M30\n", Files.readString(dir.resolve("new.nc")));
        assertRefused(409, post("save", body("name", "bishop.nc", "text", "M30\n")));
        assertEquals(Files.readString(Path.of("samples/bishop.nc")), Files.readString(dir.resolve("bishop.nc")));
        // no temporary file is left behind by any of it
        try (var files = Files.walk(dir)) {
            assertEquals(List.of(), files.filter(p -> p.getFileName().toString().endsWith(".part")).toList());
        }
    }

    @Test
    void theEventStreamTellsWhenTheListOfProgramsChanges() throws IOException {
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), studio.port())) {
            s.setSoTimeout(10000);
            s.getOutputStream().write(("GET /api/events?token=" + studio.token() + " HTTP/1.1\r\nHost: 127.0.0.1:"
                    + studio.port() + "\r\n\r\n").getBytes(StandardCharsets.UTF_8));
            InputStream in = s.getInputStream();
            StringBuilder seen = new StringBuilder();
            readUntil(in, seen, "\"name\":\"bishop.nc\"");
            assertTrue(seen.toString().contains("text/event-stream"), seen.toString());
            assertTrue(seen.toString().contains("event: files\ndata: {\"files\":[{\"name\":\"bishop.nc\""), seen.toString());
            Files.writeString(dir.resolve("made-elsewhere.nc"), "M30\n");
            seen.setLength(0);
            readUntil(in, seen, "made-elsewhere.nc");
            assertTrue(seen.toString().contains("event: files"), seen.toString());
        }
    }

    private static void readUntil(InputStream in, StringBuilder seen, String wanted) throws IOException {
        byte[] buf = new byte[4096];
        while (!seen.toString().contains(wanted)) {
            int n = in.read(buf);
            if (n < 0) {
                throw new IOException("the stream ended before " + wanted + ": " + seen);
            }
            seen.append(new String(buf, 0, n, StandardCharsets.UTF_8));
        }
    }

    // ---- 3-6. check, simulate, compile: the command line's answers ----

    /** The command line's JSON for a file, without the file name (the studio names files relative to DIR). */
    static JsonArray cliDiagnostics(Path file) {
        java.io.StringWriter out = new java.io.StringWriter();
        picocli.CommandLine cl = gcnc.cli.Main.commandLine("check", "--lang", "en", "--machine", "thesis-2004", "--format", "json", file.toString());
        cl.setOut(new java.io.PrintWriter(out, true));
        cl.setErr(new java.io.PrintWriter(new java.io.StringWriter(), true));
        cl.execute("check", "--lang", "en", "--machine", "thesis-2004", "--format", "json", file.toString());
        JsonArray a = JsonParser.parseString(out.toString()).getAsJsonObject().getAsJsonArray("diagnostics");
        a.forEach(d -> d.getAsJsonObject().remove("file"));
        return a;
    }

    @Test
    void checkAnswersWhatGcncCheckFormatJsonPrints() throws IOException {
        String broken = Files.readString(dir.resolve("bishop.nc")).replace("N135 G01 Z-04500", "N135 G01 Z-04500 Q")
                .replace("N240 G03 X+1000 R1400 F050", "N240 G03 X+1000 F050");
        Files.writeString(dir.resolve("broken.nc"), broken);
        JsonObject doc = post("check", body("name", "broken.nc", "text", broken)).json();
        assertEquals("gcnc-diagnostics", doc.get("format").getAsString());
        JsonArray mine = doc.getAsJsonArray("diagnostics");
        assertTrue(mine.size() >= 2, doc.toString());
        mine.forEach(d -> assertEquals("broken.nc", d.getAsJsonObject().remove("file").getAsString()));
        assertEquals(cliDiagnostics(dir.resolve("broken.nc")), mine);
        assertEquals(6, mine.get(0).getAsJsonObject().get("line").getAsInt());
        assertEquals(0, post("check", body("name", "bishop.nc", "text", Files.readString(dir.resolve("bishop.nc"))))
                .json().get("errors").getAsInt());
    }

    @Test
    void simulateGivesEachMoveAndEachDmcLineItsGcodeLine() throws IOException {
        String text = Files.readString(dir.resolve("bishop.nc"));
        JsonObject r = post("simulate", body("name", "bishop.nc", "text", text)).json();
        List<String> lines = text.lines().toList();
        JsonArray moves = r.getAsJsonObject("drawing").getAsJsonArray("moves");
        assertEquals(57, moves.size());
        for (JsonElement m : moves) {
            int line = m.getAsJsonObject().get("line").getAsInt();
            String block = lines.get(line - 1);
            // every move comes from a block that moves; a rapid from a G00 block
            assertTrue(block.matches(".*G0[0-3].*"), block);
            assertEquals(block.contains("G00"), m.getAsJsonObject().get("rapid").getAsBoolean(), block);
        }
        // N135 G01 Z-04500 (line 6): one feed move to Z -4500 in the program's units, at X 2034 (a diameter)
        JsonObject n135 = moves.get(2 + 1).getAsJsonObject();
        assertEquals(6, n135.get("line").getAsInt());
        JsonArray z = n135.getAsJsonArray("z");
        assertEquals(-4500, z.get(z.size() - 1).getAsDouble(), 0.01);
        assertEquals(2034, n135.getAsJsonArray("x").get(0).getAsDouble(), 0.01);
        // the DMC: the same lines gcnc compile writes, each with its G-code line as the .map says
        JsonArray dmc = r.getAsJsonArray("dmc");
        Path out = dir.resolve("cli.dmc");
        cli("compile", "--machine", "thesis-2004", dir.resolve("bishop.nc").toString(), "-o", out.toString());
        List<String> written = Files.readAllLines(out);
        assertEquals(written.size(), dmc.size());
        gcnc.dmc.SourceMap.Locator map;
        try (var in = Files.newBufferedReader(dir.resolve("cli.dmc.map"))) {
            map = gcnc.dmc.SourceMap.read(in).at();
        }
        for (int i = 0; i < dmc.size(); i++) {
            JsonObject l = dmc.get(i).getAsJsonObject();
            assertEquals(written.get(i), l.get("text").getAsString());
            JsonArray parts = l.getAsJsonArray("parts");
            List<String> texts = new java.util.ArrayList<>();
            for (int k = 0; k < parts.size(); k++) { // each command of the packed line with its G-code line, as the map
                JsonObject c = parts.get(k).getAsJsonObject();
                texts.add(c.get("text").getAsString());
                gcnc.dmc.Source at = map.source(i + 1, k);
                assertEquals(at == null ? 0 : at.line(), c.get("line").getAsInt(), "DMC line " + (i + 1) + "." + k);
            }
            assertEquals(written.get(i), String.join(";", texts));
        }
        assertTrue(r.getAsJsonObject("summary").get("cycleSeconds").getAsDouble() > 0);
        JsonObject stock = r.getAsJsonObject("drawing").getAsJsonObject("stock");
        assertEquals(2200, stock.get("x").getAsDouble(), 0.01); // the header's 22.00 mm bar, in the program's 0.01 mm
    }

    @Test
    void compileWritesTheDmcAndItsMapAsTheCommandLineDoes() throws IOException {
        JsonObject r = post("compile", body("name", "bishop.nc")).json();
        assertTrue(r.get("ok").getAsBoolean(), r.toString());
        assertEquals("bishop.dmc", r.get("dmc").getAsString());
        assertEquals("bishop.dmc.map", r.get("map").getAsString());
        assertTrue(r.getAsJsonObject("summary").get("cycleSeconds").getAsDouble() > 30);
        cli("compile", "--machine", "thesis-2004", dir.resolve("bishop.nc").toString(), "-o", dir.resolve("cli.dmc").toString());
        assertEquals(Files.readString(dir.resolve("cli.dmc")), Files.readString(dir.resolve("bishop.dmc")));
        assertEquals(Files.readString(dir.resolve("cli.dmc.map")), Files.readString(dir.resolve("bishop.dmc.map")));

        // with an error: nothing written, the old DMC and map kept
        Files.writeString(dir.resolve("bishop.nc"), Files.readString(dir.resolve("bishop.nc")).replace("N135 G01 Z-04500", "N135 G01 Z-04500 Q"));
        String before = Files.readString(dir.resolve("bishop.dmc"));
        JsonObject bad = post("compile", body("name", "bishop.nc")).json();
        assertFalse(bad.get("ok").getAsBoolean());
        assertEquals("E006", bad.getAsJsonObject("diagnostics").getAsJsonArray("diagnostics").get(0).getAsJsonObject().get("code").getAsString());
        assertEquals(before, Files.readString(dir.resolve("bishop.dmc")));
    }

    static void cli(String... args) {
        picocli.CommandLine cl = gcnc.cli.Main.commandLine(args);
        cl.setOut(new java.io.PrintWriter(new java.io.StringWriter(), true));
        cl.setErr(new java.io.PrintWriter(new java.io.StringWriter(), true));
        assertEquals(0, cl.execute(args), String.join(" ", args));
    }
}
