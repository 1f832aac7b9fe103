package gcnc.studio;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;

/**
 * CodeMirror 6 as the WebJars put it on the class path (inside gcnc.jar): ES modules that import each
 * other by package name ({@code import ... from "@codemirror/state"}). A browser resolves such bare
 * names through an import map, made here from each WebJar's own package.json, so the page loads the
 * exact files the jar holds, from the studio itself, with no CDN and no bundler in the build.
 */
final class WebJars {
    /** The WebJars the page uses (build.gradle pins their versions); codemirror is the meta-package. */
    static final List<String> ARTIFACTS = List.of("codemirror", "codemirror__view", "codemirror__state",
            "codemirror__language", "codemirror__lint", "codemirror__autocomplete", "codemirror__commands",
            "codemirror__search", "lezer__common", "lezer__highlight", "lezer__lr", "crelt", "style-mod",
            "w3c-keyname", "marijn__find-cluster-break");

    private static final String RESOURCES = "META-INF/resources/webjars/";

    /** Artifact to version, as the jars on the class path have them. */
    private final Map<String, String> versions = new LinkedHashMap<>();
    /** Package name ({@code @codemirror/view}) to the URL of its ES module entry. */
    private final Map<String, String> imports = new LinkedHashMap<>();

    WebJars() throws IOException {
        ClassLoader cl = WebJars.class.getClassLoader();
        for (String artifact : ARTIFACTS) {
            Properties pom = new Properties();
            try (InputStream in = cl.getResourceAsStream("META-INF/maven/org.webjars.npm/" + artifact + "/pom.properties")) {
                if (in == null) {
                    throw new IOException("the WebJar " + artifact + " is not on the class path (build.gradle of studio/)");
                }
                pom.load(in);
            }
            String version = pom.getProperty("version");
            versions.put(artifact, version);
            JsonObject pkg;
            try (InputStream in = cl.getResourceAsStream(RESOURCES + artifact + "/" + version + "/package.json")) {
                if (in == null) {
                    throw new IOException("the WebJar " + artifact + " " + version + " has no package.json");
                }
                pkg = JsonParser.parseString(new String(in.readAllBytes(), StandardCharsets.UTF_8)).getAsJsonObject();
            }
            imports.put(pkg.get("name").getAsString(), "/webjars/" + artifact + "/" + version + "/" + entry(pkg));
        }
    }

    /** The ES module a package exports to {@code import}: exports.import, else module, else main. */
    private static String entry(JsonObject pkg) {
        JsonElement exports = pkg.get("exports");
        String e = null;
        if (exports != null && exports.isJsonObject()) {
            JsonObject x = exports.getAsJsonObject();
            JsonElement dot = x.has(".") ? x.get(".") : x;
            if (dot.isJsonObject() && dot.getAsJsonObject().has("import") && dot.getAsJsonObject().get("import").isJsonPrimitive()) {
                e = dot.getAsJsonObject().get("import").getAsString();
            }
        }
        if (e == null && pkg.has("module")) {
            e = pkg.get("module").getAsString();
        }
        if (e == null) {
            e = pkg.get("main").getAsString();
        }
        return e.startsWith("./") ? e.substring(2) : e;
    }

    /** The import map, as the page's {@code <script type="importmap">} holds it. */
    String importMap() {
        JsonObject map = new JsonObject();
        JsonObject im = new JsonObject();
        imports.forEach(im::addProperty);
        map.add("imports", im);
        return map.toString();
    }

    Map<String, String> versions() {
        return versions;
    }

    /**
     * A file of one of the WebJars by its URL path after {@code /webjars/} ({@code crelt/1.0.7/index.js}),
     * or null: only the listed WebJars at their own version, only .js files, no {@code ..}.
     */
    byte[] file(String path) throws IOException {
        String[] parts = path.split("/", 3);
        if (parts.length < 3 || !versions.containsKey(parts[0]) || !versions.get(parts[0]).equals(parts[1])
                || !parts[2].endsWith(".js") || path.contains("..") || path.contains("//") || path.contains("\\")) {
            return null;
        }
        try (InputStream in = WebJars.class.getClassLoader().getResourceAsStream(RESOURCES + path)) {
            return in == null ? null : in.readAllBytes();
        }
    }
}
