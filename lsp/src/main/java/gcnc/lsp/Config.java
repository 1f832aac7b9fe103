package gcnc.lsp;

import gcnc.Session;
import gcnc.tables.TableException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;

/**
 * The session each buffer is checked with: the client's settings, the nearest {@code .gcnc} over
 * them ({@link FolderSettings}), opened through {@link Session#open} as the command line opens its
 * options. Sessions are kept by what they were opened from and the time stamps of the files they
 * read (the .gcnc file, a profile or control given as a path, a tables folder), so an edited profile
 * is read again at the next check, and {@link #forget} (a watched file changed) drops them all.
 */
final class Config {
    /** A buffer's settings and the session they open, or the fault that kept it from opening. */
    record Resolved(FolderSettings settings, Optional<Session> session, Optional<TableException> fault) {
    }

    private volatile FolderSettings client = FolderSettings.DEFAULTS;
    private volatile List<Path> roots = List.of();
    private final Map<String, Resolved> sessions = new ConcurrentHashMap<>();

    void client(FolderSettings settings) {
        client = settings;
        forget();
    }

    void roots(List<Path> folders) {
        roots = List.copyOf(folders);
    }

    void forget() {
        sessions.clear();
    }

    /** What a buffer in {@code folder} (empty: an unsaved buffer) is checked with. */
    Resolved resolve(Optional<Path> folder) throws IOException {
        FolderSettings s = client;
        Optional<Path> file = folder.flatMap(f -> FolderSettings.find(f, roots.stream().filter(f::startsWith).findFirst()));
        if (file.isPresent()) {
            s = s.with(file.get());
        }
        String key = s.machine().orElse("") + '\0' + s.control().orElse("") + '\0' + s.tables().map(Path::toString).orElse("")
                + '\0' + stamp(s);
        FolderSettings settings = s;
        Resolved r = sessions.get(key);
        if (r == null) {
            try {
                r = new Resolved(settings, Optional.of(Session.open(settings.options())), Optional.empty());
            } catch (TableException e) {
                r = new Resolved(settings, Optional.empty(), Optional.of(e));
            }
            sessions.put(key, r);
        }
        return r;
    }

    /** The files a session of {@code s} reads that a user may edit, as their time stamps and sizes. */
    private static String stamp(FolderSettings s) throws IOException {
        StringBuilder b = new StringBuilder();
        s.file().ifPresent(f -> b.append(stamp(f)));
        // a profile given as a path may name a tool table beside it: the files of its folder
        Stream<Path> profileFolder = s.machine().filter(gcnc.machine.ProfileLoader::isPath)
                .map(m -> Path.of(m).toAbsolutePath().getParent()).stream();
        for (Path dir : Stream.concat(Stream.concat(s.tables().stream(), profileFolder),
                s.control().filter(gcnc.machine.ControlLoader::isPath).map(Path::of).stream()).toList()) {
            if (dir != null && Files.isDirectory(dir)) {
                try (Stream<Path> files = Files.walk(dir, dir.equals(s.tables().orElse(null)) ? 4 : 1)) {
                    files.filter(Files::isRegularFile).filter(f -> !f.getFileName().toString().endsWith(".nc"))
                            .sorted().forEach(f -> b.append(stamp(f)));
                }
            }
        }
        return b.toString();
    }

    private static String stamp(Path f) {
        try {
            return f + "@" + Files.getLastModifiedTime(f).toMillis() + "/" + Files.size(f) + ";";
        } catch (IOException e) {
            return f + "@none;";
        }
    }
}
