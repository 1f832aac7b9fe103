package gcnc.studio;

import com.sun.net.httpserver.HttpExchange;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Locale;
import java.util.Optional;

/**
 * Who may talk to the studio. Its server listens on the loopback address only, but any web page the
 * user has open can still send requests to 127.0.0.1, and a name the attacker controls can be made
 * to resolve to 127.0.0.1 (DNS rebinding). So every request must name the studio itself as its Host,
 * a request a browser marks as coming from another page (Origin) is refused, and every API call and
 * the page itself need the random token printed in the studio's URL, which no other page can know.
 */
final class Guard {
    /** The header a page's fetch carries the token in (a query parameter would end up in logs and history). */
    static final String TOKEN_HEADER = "X-Gcnc-Token";

    private final int port;
    private final byte[] token;

    Guard(int port, String token) {
        this.port = port;
        this.token = token.getBytes(StandardCharsets.UTF_8);
    }

    /** Why the request is refused (status and message), or empty when it may go on. */
    Optional<Http.Failure> refuse(HttpExchange ex, boolean needsToken) {
        java.util.List<String> hosts = ex.getRequestHeaders().get("Host");
        if (hosts != null && hosts.size() > 1) {
            // which one a proxy or a cache would believe is anyone's guess (RFC 9112 section 3.2: 400)
            return Optional.of(new Http.Failure(400, "a request names one Host, not " + hosts.size()));
        }
        URI target = ex.getRequestURI();
        if (target.isAbsolute() || target.getRawAuthority() != null) {
            // a browser sends the path alone; an absolute target names a host besides Host
            return Optional.of(new Http.Failure(400, "the request's target is a path (/api/...), not "
                    + Workspace.shown(target.toString())));
        }
        String host = ex.getRequestHeaders().getFirst("Host");
        if (host == null || !isSelf(host)) {
            return Optional.of(new Http.Failure(403, "the Host header must be 127.0.0.1:" + port + " or localhost:" + port));
        }
        String origin = ex.getRequestHeaders().getFirst("Origin");
        if (origin != null && !isSelfOrigin(origin)) {
            return Optional.of(new Http.Failure(403, "requests from other pages are refused (Origin " + Workspace.shown(origin) + ")"));
        }
        if (needsToken && !hasToken(ex)) {
            return Optional.of(new Http.Failure(403, "this needs the token printed in the studio's URL"));
        }
        return Optional.empty();
    }

    /** "127.0.0.1:N" or "localhost:N", this studio's port. */
    private boolean isSelf(String hostPort) {
        String h = hostPort.toLowerCase(Locale.ROOT);
        return h.equals("127.0.0.1:" + port) || h.equals("localhost:" + port);
    }

    /** The studio's own page: "http://" and itself ("null", a sandboxed or file: page, is not). */
    private boolean isSelfOrigin(String origin) {
        String o = origin.toLowerCase(Locale.ROOT);
        return o.startsWith("http://") && isSelf(o.substring("http://".length()));
    }

    private boolean hasToken(HttpExchange ex) {
        String given = ex.getRequestHeaders().getFirst(TOKEN_HEADER);
        if (given == null) {
            given = query(ex.getRequestURI(), "token");
        }
        // compared in constant time: how long a wrong token took must not tell how much of it was right
        return given != null && MessageDigest.isEqual(token, given.getBytes(StandardCharsets.UTF_8));
    }

    /** A query parameter's decoded value, or null. */
    static String query(URI uri, String name) {
        String q = uri.getRawQuery();
        if (q == null) {
            return null;
        }
        for (String pair : q.split("&")) {
            int eq = pair.indexOf('=');
            String key = eq < 0 ? pair : pair.substring(0, eq);
            if (key.equals(name)) {
                try {
                    return java.net.URLDecoder.decode(eq < 0 ? "" : pair.substring(eq + 1), StandardCharsets.UTF_8);
                } catch (IllegalArgumentException e) {
                    return null; // a malformed %-escape: as if not given
                }
            }
        }
        return null;
    }
}
