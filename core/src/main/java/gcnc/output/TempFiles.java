package gcnc.output;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
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

    /**
     * A new, empty, private file in {@code dir} (null: the system's temporary folder), remembered
     * until {@link #forget}. As Files.createTempFile does, it is created exclusively (O_EXCL: an
     * existing file or link of that name is never opened, another name is tried) and readable by its
     * owner only; its name is made from the process, a counter and the clock rather than from
     * SecureRandom, whose seeding showed as 25 ms of every run's start-up.
     */
    static Path create(Path dir, String prefix, String suffix) throws IOException {
        hook();
        Path folder = dir != null ? dir : Path.of(System.getProperty("java.io.tmpdir"));
        for (int attempt = 0; ; attempt++) {
            Path p = folder.resolve(prefix + ProcessHandle.current().pid() + "-" + COUNTER.incrementAndGet() + "-"
                    + Long.toHexString(System.nanoTime() & 0xffffffL) + suffix);
            try {
                if (POSIX) {
                    Files.createFile(p, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
                } else {
                    Files.createFile(p);
                }
            } catch (java.nio.file.FileAlreadyExistsException e) {
                if (attempt < 100) {
                    continue;
                }
                throw e;
            }
            OPEN.add(p);
            return p;
        }
    }

    private static final java.util.concurrent.atomic.AtomicLong COUNTER = new java.util.concurrent.atomic.AtomicLong();
    private static final boolean POSIX = java.nio.file.FileSystems.getDefault().supportedFileAttributeViews()
            .contains("posix");

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
