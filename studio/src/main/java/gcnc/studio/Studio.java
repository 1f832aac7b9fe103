package gcnc.studio;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import gcnc.Session;
import gcnc.tables.ErrorMessages;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.URLEncoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * {@code gcnc studio}: a local web editor for the part programs in one folder, served by the JDK's
 * own HTTP server on the loopback address only. The page (index.html, studio.js, CodeMirror from the
 * WebJars) comes from inside the jar; the page asks for everything else through the JSON API
 * ({@link Api}, docs/studio.md), guarded by {@link Guard}. One studio serves one folder with one
 * {@link Session}, the same the command line would make from the same options.
 */
public final class Studio implements AutoCloseable {
    /**
     * How a studio starts.
     *
     * @param root    DIR: the folder whose programs it edits; it reads and writes nowhere else
     * @param port    the port, 0 for any free one
     * @param session the tables and machine every check and compile uses
     * @param lang    the language of the page and of the messages
     * @param version gcnc's version, written in the JSON reports
     * @param running how the Run screen reaches controllers
     */
    public record Config(Path root, int port, Session session, ErrorMessages.Lang lang, String version, Running running) {
        /** A studio whose virtual controller runs in real time and which opens no serial port. */
        public Config(Path root, int port, Session session, ErrorMessages.Lang lang, String version) {
            this(root, port, session, lang, version, Running.DEFAULT);
        }
    }

    /**
     * How the Run screen reaches controllers.
     *
     * @param virtualSpeed how many times faster than real time the studio's virtual controller runs (1: real time)
     * @param serial       opens a serial port for a run; null when this studio has none (the command line
     *                     gives jSerialComm's: the studio carries no serial library of its own)
     */
    public record Running(double virtualSpeed, SerialPorts serial) {
        public static final Running DEFAULT = new Running(1, null);

        public Running {
            if (!(virtualSpeed > 0)) {
                throw new IllegalArgumentException("the virtual controller's speed must be above 0");
            }
        }
    }

    /** Opens a Galil's serial port as {@code gcnc run --port DEV --baud N --handshake ...} does. */
    @FunctionalInterface
    public interface SerialPorts {
        /** The link; E815 (no such port) or E816 (held, no permission) as a {@link gcnc.send.RunFault}. */
        gcnc.send.Link open(String device, int baud, boolean hardwareHandshake) throws gcnc.send.RunFault;
    }

    /** The page's own files: name to content type (nothing else is served from the jar but the WebJars). */
    private static final Map<String, String> STATIC = Map.of(
            "studio.js", "text/javascript; charset=utf-8",
            "gcode-mode.js", "text/javascript; charset=utf-8",
            "profile.js", "text/javascript; charset=utf-8",
            "hover.js", "text/javascript; charset=utf-8",
            "configure.js", "text/javascript; charset=utf-8",
            "run.js", "text/javascript; charset=utf-8",
            "testcut.js", "text/javascript; charset=utf-8",
            "i18n.js", "text/javascript; charset=utf-8",
            "studio.css", "text/css; charset=utf-8");

    private final HttpServer server;
    private final ExecutorService threads;
    private final String token;
    private final Guard guard;
    private final Api api;
    private final WebJars webJars;
    private final Config config;
    /**
     * The page may run only the studio's own scripts and the import map (by its hash), and talk only
     * to the studio: text that reached the page some other way could run nothing. CodeMirror puts
     * its styles in style elements, hence inline styles.
     */
    private final String contentPolicy;

    private Studio(Config config, HttpServer server, ExecutorService threads, String token, Workspace workspace)
            throws IOException {
        this.config = config;
        this.server = server;
        this.threads = threads;
        this.token = token;
        this.guard = new Guard(port(), token);
        this.webJars = new WebJars();
        this.contentPolicy = "default-src 'none'; script-src 'self' '" + sha256(webJars.importMap())
                + "'; style-src 'self' 'unsafe-inline'; connect-src 'self'; img-src 'self' data:; base-uri 'none';"
                + " form-action 'none'; frame-ancestors 'none'";
        this.api = new Api(workspace, config);
    }

    /**
     * The most connections the studio holds at once (the JDK server's {@code jdk.httpserver.maxConnections}:
     * one more is closed as soon as it is accepted). Every client is on the loopback address, so the
     * bound is for all of them together: a browser opens six per host, the event streams three more.
     */
    static final int MAX_CONNECTIONS = 32;
    /**
     * Seconds a request's head and body may take to arrive ({@code sun.net.httpserver.maxReqTime}):
     * a connection that sends half a head is closed then, and its thread freed.
     */
    static final int HEAD_SECONDS = 10;

    /**
     * The JDK server's limits, as system properties, which it reads once, when the first server of
     * the JVM is made: set here before it unless the user set them (java -D...). Without them a
     * local process that opened 8 connections and sent half a request head on each held all six
     * threads for minutes, and the page (Stop included) got no answer.
     */
    private static void serverLimits() {
        System.getProperties().putIfAbsent("jdk.httpserver.maxConnections", Integer.toString(MAX_CONNECTIONS));
        System.getProperties().putIfAbsent("sun.net.httpserver.maxReqTime", Integer.toString(HEAD_SECONDS));
    }

    /** Binds the loopback address (never another interface) and starts serving. */
    public static Studio start(Config config) throws IOException {
        Workspace workspace = new Workspace(config.root());
        serverLimits();
        HttpServer server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), config.port()), 16);
        AtomicInteger n = new AtomicInteger();
        // a thread for every connection the server admits: the JDK reads a request's head on the
        // executor's thread, so a fixed few were all taken by connections that never finished theirs.
        // The heavy work (check, simulate, compile) is bounded apart (Http.timed), so Stop always has a thread.
        ExecutorService threads = new java.util.concurrent.ThreadPoolExecutor(0, MAX_CONNECTIONS + 8, 30,
                java.util.concurrent.TimeUnit.SECONDS, new java.util.concurrent.SynchronousQueue<>(), r -> {
                    Thread t = new Thread(r, "gcnc-studio-" + n.incrementAndGet());
                    t.setDaemon(true);
                    return t;
                });
        server.setExecutor(threads);
        Studio studio;
        try {
            studio = new Studio(config, server, threads, newToken(), workspace);
        } catch (IOException | RuntimeException e) {
            server.stop(0);
            threads.shutdownNow();
            throw e;
        }
        server.createContext("/", studio::handle);
        server.start();
        return studio;
    }

    public int port() {
        return server.getAddress().getPort();
    }

    public String token() {
        return token;
    }

    /** The URL that opens the studio: {@code http://127.0.0.1:N/?token=…}. */
    public URI url() {
        return URI.create("http://127.0.0.1:" + port() + "/?token=" + token);
    }

    /** The URL that opens the studio on one program ({@code name} relative to DIR). */
    public URI url(String name) {
        return URI.create(url() + "&file=" + URLEncoder.encode(name, StandardCharsets.UTF_8).replace("+", "%20"));
    }

    public Path root() {
        return api.root();
    }

    /** Stops serving; open event streams are closed. */
    @Override
    public void close() {
        api.close();
        server.stop(0);
        threads.shutdownNow();
    }

    /** The CSP source for an inline script: "sha256-" and its digest in base 64. */
    private static String sha256(String script) {
        try {
            byte[] d = java.security.MessageDigest.getInstance("SHA-256").digest(script.getBytes(StandardCharsets.UTF_8));
            return "sha256-" + java.util.Base64.getEncoder().encodeToString(d);
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }

    /** 24 random bytes from the system's strong source, as hex: what a page must show to be let in. */
    private static String newToken() {
        byte[] b = new byte[24];
        new SecureRandom().nextBytes(b);
        return HexFormat.of().formatHex(b);
    }

    /**
     * Every request: guarded first, then routed. Whatever a handler throws becomes a JSON error (400
     * for a malformed request, 500 for a fault), never a dropped connection or a dead server.
     */
    private void handle(HttpExchange ex) {
        try (ex) {
            String path = ex.getRequestURI().getRawPath();
            boolean isApi = path.startsWith("/api/");
            boolean isPage = path.equals("/") || path.equals("/index.html");
            Optional<Http.Failure> refused = guard.refuse(ex, isApi || isPage);
            if (refused.isPresent()) {
                Http.error(ex, refused.get());
                return;
            }
            try {
                if (isApi) {
                    api.handle(path.substring("/api/".length()), ex);
                } else {
                    serve(path, ex);
                }
            } catch (Http.Fail f) {
                Http.error(ex, f.failure());
            } catch (RuntimeException | IOException | StackOverflowError e) {
                Http.error(ex, new Http.Failure(500, "the studio failed on this request: " + e));
            }
        } catch (IOException | RuntimeException e) {
            // the connection broke while answering: nothing more to tell that client
        }
    }

    private void serve(String path, HttpExchange ex) throws IOException, Http.Fail {
        if (!ex.getRequestMethod().equals("GET") && !ex.getRequestMethod().equals("HEAD")) {
            throw new Http.Fail(405, ex.getRequestMethod() + " is not allowed on " + Workspace.shown(path));
        }
        if (path.equals("/") || path.equals("/index.html")) {
            ex.getResponseHeaders().set("Content-Security-Policy", contentPolicy);
            Http.send(ex, 200, "text/html; charset=utf-8", page());
            return;
        }
        if (path.startsWith("/static/") && STATIC.containsKey(path.substring("/static/".length()))) {
            String name = path.substring("/static/".length());
            Http.send(ex, 200, STATIC.get(name), resource(name));
            return;
        }
        if (path.startsWith("/webjars/")) {
            byte[] js = webJars.file(path.substring("/webjars/".length()));
            if (js != null) {
                Http.send(ex, 200, "text/javascript; charset=utf-8", js);
                return;
            }
        }
        throw new Http.Fail(404, "nothing at " + Workspace.shown(path));
    }

    /** index.html with the import map and the language filled in. */
    private byte[] page() throws IOException {
        String html = new String(resource("index.html"), StandardCharsets.UTF_8);
        return html.replace("@IMPORTMAP@", webJars.importMap())
                .replace("@LANG@", config.lang().name().toLowerCase(java.util.Locale.ROOT))
                .getBytes(StandardCharsets.UTF_8);
    }

    private static byte[] resource(String name) throws IOException {
        try (InputStream in = Studio.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IOException("the studio's " + name + " is missing from the jar");
            }
            return in.readAllBytes();
        }
    }
}
