package gcnc.studio;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;
import com.google.gson.JsonPrimitive;
import com.sun.net.httpserver.HttpExchange;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;

/**
 * The small pieces every handler needs: the method a request must use, read a JSON body (bounded)
 * and its members, the gate and timing of heavy work, answer with JSON, bytes or an error.
 */
final class Http {
    /** A request refused or failed: its status and the message the page shows. */
    record Failure(int status, String message) {
    }

    /** A failure thrown out of a handler; the router answers it as {"error": message}. */
    static final class Fail extends Exception {
        private final Failure failure;

        Fail(int status, String message) {
            super(message, null, false, false);
            this.failure = new Failure(status, message);
        }

        Failure failure() {
            return failure;
        }
    }

    /** The largest request body: a program of {@link Workspace#MAX_BYTES} as a JSON string, with room for escapes. */
    static final int MAX_BODY = (int) (2 * Workspace.MAX_BYTES + 4096);

    private Http() {
    }

    /** The body as a JSON object; 400 when it is not one, 413 when too large. */
    static JsonObject body(HttpExchange ex) throws IOException, Fail {
        byte[] bytes = read(ex.getRequestBody());
        try {
            JsonElement e = JsonParser.parseString(new String(bytes, StandardCharsets.UTF_8));
            if (!e.isJsonObject()) {
                throw new Fail(400, "the request body must be a JSON object");
            }
            return e.getAsJsonObject();
        } catch (JsonParseException | IllegalStateException e) {
            throw new Fail(400, "the request body is not JSON: " + firstLine(e.getMessage()));
        }
    }

    /** A string member of a request, or null when absent; 400 when it is there but not a string. */
    static String string(JsonObject o, String name) throws Fail {
        JsonPrimitive p = member(o, name, JsonPrimitive::isString, "a string");
        return p == null ? null : p.getAsString();
    }

    static String required(JsonObject o, String name) throws Fail {
        String s = string(o, name);
        if (s == null) {
            throw new Fail(400, "the request needs \"" + name + "\"");
        }
        return s;
    }

    /** A whole-number member from {@code min} to {@code max}; 400 when absent or anything else. */
    static int integer(JsonObject o, String name, int min, int max) throws Fail {
        JsonElement e = o.get(name);
        if (e == null || !e.isJsonPrimitive() || !e.getAsJsonPrimitive().isNumber()) {
            throw new Fail(400, "the request needs \"" + name + "\", a whole number");
        }
        java.math.BigDecimal v = e.getAsBigDecimal();
        if (v.signum() != 0 && v.stripTrailingZeros().scale() > 0 || v.compareTo(java.math.BigDecimal.valueOf(min)) < 0
                || v.compareTo(java.math.BigDecimal.valueOf(max)) > 0) {
            throw new Fail(400, "\"" + name + "\" must be a whole number from " + min + " to " + max);
        }
        return v.intValueExact();
    }

    /** A true-or-false member, false when absent; 400 when it is anything else. */
    static boolean flag(JsonObject o, String name) throws Fail {
        JsonPrimitive p = member(o, name, JsonPrimitive::isBoolean, "true or false");
        return p != null && p.getAsBoolean();
    }

    /** A member that is a primitive of the kind {@code is} tells, or null when absent; 400 ("must be {@code what}") otherwise. */
    private static JsonPrimitive member(JsonObject o, String name, java.util.function.Predicate<JsonPrimitive> is, String what)
            throws Fail {
        JsonElement e = o.get(name);
        if (e == null || e.isJsonNull()) {
            return null;
        }
        if (!e.isJsonPrimitive() || !is.test(e.getAsJsonPrimitive())) {
            throw new Fail(400, "\"" + name + "\" must be " + what);
        }
        return e.getAsJsonPrimitive();
    }

    /** The exchange of a read: 405 unless it is a GET. */
    static HttpExchange get(HttpExchange ex) throws Fail {
        if (!ex.getRequestMethod().equals("GET")) {
            throw new Fail(405, "use GET for " + ex.getRequestURI().getRawPath());
        }
        return ex;
    }

    /** The JSON body of a POST (a page's fetch sends it as application/json); 405 for another method. */
    static JsonObject post(HttpExchange ex) throws IOException, Fail {
        if (!ex.getRequestMethod().equals("POST")) {
            throw new Fail(405, "use POST for " + ex.getRequestURI().getRawPath());
        }
        return body(ex);
    }

    /** The work behind an answer: its JSON. */
    interface Work {
        JsonObject run() throws IOException, Fail;
    }

    /**
     * The checks, simulations and compiles that run at once (each may hold a program of 8 MB and its
     * path): the rest wait their turn, while the light endpoints (the file list, save, Run's hold and
     * stop) never wait for them.
     */
    private static final java.util.concurrent.Semaphore HEAVY = new java.util.concurrent.Semaphore(4);

    /**
     * Heavy work ({@link #HEAVY}) answered with its JSON and, in a Server-Timing header ({@code gcnc;dur=12.3}),
     * how long the studio took for it in milliseconds: the browser's developer tools and
     * bench/studio-recheck.sh show it apart from the time on the wire.
     */
    static void timed(HttpExchange ex, Work work) throws IOException, Fail {
        long start = System.nanoTime();
        JsonObject answer;
        HEAVY.acquireUninterruptibly();
        try {
            answer = work.run();
        } finally {
            HEAVY.release();
        }
        ex.getResponseHeaders().set("Server-Timing", String.format(java.util.Locale.ROOT, "gcnc;dur=%.1f",
                (System.nanoTime() - start) / 1e6));
        json(ex, 200, answer);
    }

    private static byte[] read(InputStream in) throws IOException, Fail {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] buf = new byte[1 << 16];
        for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
            out.write(buf, 0, n);
            if (out.size() > MAX_BODY) {
                throw new Fail(413, "the request is larger than " + (MAX_BODY >> 20) + " MB");
            }
        }
        return out.toByteArray();
    }

    static void json(HttpExchange ex, int status, JsonElement body) throws IOException {
        send(ex, status, "application/json; charset=utf-8", body.toString().getBytes(StandardCharsets.UTF_8));
    }

    static void error(HttpExchange ex, Failure f) throws IOException {
        JsonObject o = new JsonObject();
        o.addProperty("error", f.message());
        o.addProperty("status", f.status());
        json(ex, f.status(), o);
    }

    static void send(HttpExchange ex, int status, String type, byte[] body) throws IOException {
        ex.getResponseHeaders().set("Content-Type", type);
        // the page and its answers are never cached (a new launch has a new token) and never framed by another page
        ex.getResponseHeaders().set("Cache-Control", "no-store");
        ex.getResponseHeaders().set("X-Content-Type-Options", "nosniff");
        ex.getResponseHeaders().set("X-Frame-Options", "DENY");
        ex.getResponseHeaders().set("Referrer-Policy", "no-referrer");
        if (ex.getRequestMethod().equals("HEAD")) {
            ex.sendResponseHeaders(status, -1);
            return;
        }
        ex.sendResponseHeaders(status, body.length == 0 ? -1 : body.length);
        if (body.length > 0) {
            try (OutputStream out = ex.getResponseBody()) {
                out.write(body);
            }
        }
    }

    static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }
}
