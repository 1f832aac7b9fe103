package gcnc.output;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The temporary files a run has open, removed by a shutdown hook when the run is killed (SIGINT,
 * SIGTERM, SIGHUP) before it could remove them itself. A compile of a long program writes tens of
 * megabytes to its {@code .part} file; Ctrl-C must not leave that behind. The hook is the one piece
 * of process-wide state in gcnc: a signal ends the whole process, not one command.
 * (SIGKILL runs no hook; nothing can clean up after that.)
 */
public final class TempFiles {
    private static final Set<Path> OPEN = ConcurrentHashMap.newKeySet();
    private static final Object HOOK_LOCK = new Object();
    private static boolean hooked;

    private TempFiles() {
    }

    /** Files.createTempFile in {@code dir} (null: the system's temporary folder), remembered until {@link #forget}. */
    static Path create(Path dir, String prefix, String suffix) throws IOException {
        hook();
        Path p = dir == null ? Files.createTempFile(prefix, suffix) : Files.createTempFile(dir, prefix, suffix);
        OPEN.add(p);
        return p;
    }

    /** A path (a backup) that is this run's own until {@link #forget}. */
    static void remember(Path p) {
        hook();
        OPEN.add(p);
    }

    /** The file was renamed into place or deleted: no longer the hook's business. */
    static void forget(Path p) {
        OPEN.remove(p);
    }

    /** Deletes a temporary file now, quietly if it is already gone. */
    static void delete(Path p) throws IOException {
        try {
            Files.deleteIfExists(p);
        } finally {
            OPEN.remove(p);
        }
    }

    /** The temporary files still open; for tests. */
    public static Set<Path> open() {
        return Set.copyOf(OPEN);
    }

    private static void hook() {
        synchronized (HOOK_LOCK) {
            if (!hooked) {
                Runtime.getRuntime().addShutdownHook(new Thread(TempFiles::removeAll, "gcnc-temp-cleanup"));
                hooked = true;
            }
        }
    }

    private static void removeAll() {
        for (Path p : OPEN) {
            try {
                Files.deleteIfExists(p);
            } catch (IOException | RuntimeException e) {
                // The process is ending; a file that cannot be removed now cannot be reported either.
            }
        }
    }
}
