package gcnc.lsp;

import gcnc.diag.Code;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;

/**
 * {@code gcnc explain CODE}'s text for the editor: each code a diagnostic links to (its
 * codeDescription) is written once, as the command line prints it, to {@code E107.txt} in a folder
 * of this server's (by default {@code ~/.cache/gcnc/explain/VERSION-LANG/}), and the link is that
 * file's URI; the code action "Explain E107" opens it. A folder that cannot be written leaves the
 * codes unlinked (logged once), and the code action shows the text in a message instead.
 */
final class ExplainFiles {
    private final Function<String, String> text;
    private final Path folder;
    private final Map<Code, Optional<String>> written = new ConcurrentHashMap<>();
    private final Log log;

    /**
     * @param text   the text of {@code gcnc explain CODE} in the server's language (from the command line)
     * @param folder where the files go
     */
    ExplainFiles(Function<String, String> text, Path folder, Log log) {
        this.text = text;
        this.folder = folder;
        this.log = log;
    }

    /** The default folder: $XDG_CACHE_HOME/gcnc/explain/VERSION-LANG, else ~/.cache/... */
    static Path defaultFolder(String version, String lang) {
        String cache = System.getenv("XDG_CACHE_HOME");
        Path base = cache != null && !cache.isEmpty() ? Path.of(cache) : Path.of(System.getProperty("user.home"), ".cache");
        return base.resolve("gcnc").resolve("explain").resolve(version + "-" + lang);
    }

    /** The explanation of {@code code} as text. */
    String text(Code code) {
        return text.apply(code.id());
    }

    /** The URI of the file that explains {@code code}, written on first use; empty if it cannot be. */
    Optional<String> uri(Code code) {
        return written.computeIfAbsent(code, c -> {
            Path file = folder.resolve(c.id() + ".txt");
            try {
                Files.createDirectories(folder);
                Path tmp = Files.createTempFile(folder, c.id(), ".tmp");
                Files.writeString(tmp, text(c), StandardCharsets.UTF_8);
                Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                return Optional.of(file.toUri().toString());
            } catch (IOException | RuntimeException e) {
                log.error("cannot write the explanation of " + c.id() + " to " + file + ": " + e);
                return Optional.empty();
            }
        });
    }
}
