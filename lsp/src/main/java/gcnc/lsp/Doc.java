package gcnc.lsp;

import java.net.URI;
import java.nio.file.Path;
import java.util.Optional;

/**
 * An open buffer: its URI, its whole text (the server asks for full text on each change), the
 * client's version of it, and the file it is (empty for an unsaved buffer or another scheme).
 */
record Doc(String uri, String text, int version, Optional<Path> path) {
    static Doc of(String uri, String text, int version) {
        Optional<Path> path;
        try {
            URI u = URI.create(uri);
            path = "file".equals(u.getScheme()) ? Optional.of(Path.of(u)) : Optional.empty();
        } catch (IllegalArgumentException | java.nio.file.FileSystemNotFoundException e) {
            path = Optional.empty();
        }
        return new Doc(uri, text, version, path);
    }

    /** The same buffer with a new text. */
    Doc edited(String newText, int newVersion) {
        return new Doc(uri, newText, newVersion, path);
    }

    /** The folder called programs are looked for in (the file's), as the command line's check does. */
    Optional<Path> folder() {
        return path.map(p -> p.toAbsolutePath().getParent());
    }

    /** The name findings are reported under: the file's name, as {@code gcnc check FILE} in its folder shows it. */
    String name() {
        return path.map(p -> p.getFileName().toString()).orElse(uri);
    }
}
