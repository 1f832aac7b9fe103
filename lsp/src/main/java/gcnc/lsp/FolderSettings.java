package gcnc.lsp;

import gcnc.Session;
import gcnc.machine.ControlLoader;
import gcnc.machine.ProfileLoader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * What a folder's programs are checked with: the machine, the control and the tables, as the command
 * line's {@code --machine NAME|PATH}, {@code --control NAME|PATH} and {@code --tables DIR} give them.
 * They come from the client's settings (initializationOptions, workspace/didChangeConfiguration),
 * and a {@code .gcnc} file in the program's folder or the nearest folder above it overrides them
 * key by key (docs/editors.md, "Settings"):
 *
 * <pre>
 * # the shop's lathe
 * machine = haas
 * control = fanuc-a
 * tables  = ../my-tables
 * </pre>
 *
 * One {@code key = value} a line; {@code #} starts a comment; a path is relative to the file's folder.
 *
 * @param machine  a profile name or a .machine path, or empty (gcnc's default machine)
 * @param control  a control name or folder, or empty (the profile's own)
 * @param tables   an edited copy of tables/, or empty (the built-in tables)
 * @param file     the .gcnc file these came from, if one did
 * @param problems the .gcnc file's lines that could not be read, each "line: what"
 */
record FolderSettings(Optional<String> machine, Optional<String> control, Optional<Path> tables, Optional<Path> file,
                      List<Problem> problems) {
    /** The name of the per-folder file. */
    static final String FILE = ".gcnc";

    /** A line of a .gcnc file that is not a setting. */
    record Problem(int line, String text) {
    }

    /** No machine, control or tables given: gcnc's defaults, as {@code gcnc check} without options. */
    static final FolderSettings DEFAULTS = new FolderSettings(Optional.empty(), Optional.empty(), Optional.empty(),
            Optional.empty(), List.of());

    /** The session options these settings give (the same resolution as the command line's CommonOptions). */
    Session.Options options() {
        Session.Options o = Session.Options.defaults();
        if (machine.isPresent()) {
            o = o.withMachine(machine.get());
        }
        if (control.isPresent()) {
            o = o.withControl(control.get());
        }
        if (tables.isPresent()) {
            o = o.withTables(tables.get());
        }
        return o;
    }

    /** The nearest .gcnc file at or above {@code folder}, no higher than {@code top} (when given). */
    static Optional<Path> find(Path folder, Optional<Path> top) {
        for (Path p = folder; p != null; p = p.getParent()) {
            Path f = p.resolve(FILE);
            if (Files.isRegularFile(f)) {
                return Optional.of(f);
            }
            if (top.isPresent() && p.equals(top.get())) {
                break;
            }
        }
        return Optional.empty();
    }

    /** These settings with those of {@code file} over them. */
    FolderSettings with(Path file) throws IOException {
        Path dir = file.toAbsolutePath().getParent();
        Optional<String> m = machine;
        Optional<String> c = control;
        Optional<Path> t = tables;
        List<Problem> bad = new ArrayList<>();
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            int hash = line.indexOf('#');
            String text = (hash < 0 ? line : line.substring(0, hash)).strip();
            if (text.isEmpty()) {
                continue;
            }
            int eq = text.indexOf('=');
            String key = eq < 0 ? text : text.substring(0, eq).strip();
            String value = eq < 0 ? "" : text.substring(eq + 1).strip();
            if (eq < 0 || value.isEmpty()) {
                bad.add(new Problem(i + 1, "'" + text + "' is not key = value (machine, control or tables)"));
                continue;
            }
            switch (key) {
                case "machine" -> m = Optional.of(ProfileLoader.isPath(value) ? inFolder(value, dir) : value);
                case "control" -> c = Optional.of(ControlLoader.isPath(value) ? inFolder(value, dir) : value);
                case "tables" -> t = Optional.of(dir.resolve(value).normalize());
                default -> bad.add(new Problem(i + 1, "unknown key '" + key + "': .gcnc knows machine, control and tables"));
            }
        }
        return new FolderSettings(m, c, t, Optional.of(file), List.copyOf(bad));
    }

    /**
     * A path, relative to the .gcnc file's folder; a name (no '/', as the command line tells them apart:
     * ProfileLoader.isPath, ControlLoader.isPath) stays a name. An absolute result keeps its '/'.
     */
    private static String inFolder(String value, Path dir) {
        return dir.resolve(value).normalize().toString();
    }

    /** Settings from the client: a JSON object with "machine", "control", "tables" (strings), any missing. */
    static FolderSettings fromClient(com.google.gson.JsonObject o) {
        if (o == null) {
            return DEFAULTS;
        }
        return new FolderSettings(string(o, "machine"), string(o, "control"), string(o, "tables").map(Path::of),
                Optional.empty(), List.of());
    }

    private static Optional<String> string(com.google.gson.JsonObject o, String key) {
        var e = o.get(key);
        if (e == null || !e.isJsonPrimitive() || e.getAsString().isBlank()) {
            return Optional.empty();
        }
        return Optional.of(e.getAsString().strip());
    }
}
