package gcnc.output;

import gcnc.diag.Code;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;

/**
 * Where an {@link AtomicOutput}'s temporary file is made and how, once finished, it reaches the
 * target: renamed over a regular file (or a new one) beside which it was made, keeping the old
 * file's mode and a second name for it until the whole commit is done, so that a joint commit
 * can be taken back; copied into a device, a pipe or a descriptor's name (made in the system's
 * temporary folder, never replacing what is there); copied into a stream. The writing itself
 * (lines, text, bytes, the hash) is {@link AtomicOutput}'s.
 */
final class Placement {
    /** How the finished temporary file reaches the target; also the order of a joint commit. */
    enum Kind {
        /** Renamed over a regular file: can be undone while a later output of the same commit fails. */
        REPLACE,
        /** Copied into an existing file that is not a regular one (a device, a pipe). */
        WRITE_THROUGH,
        /** Copied into a stream. */
        STREAM
    }

    private final Kind kind;
    /** Where the lines end up (a link's own file for a symbolic link); null for a stream. */
    private final Path target;
    private final OutputStream stream;
    private final Path temp;
    /** The target as it was before {@link #install} replaced it, kept until the whole commit is done. */
    private Path backup;

    private Placement(Kind kind, Path target, OutputStream stream, Path temp) {
        this.kind = kind;
        this.target = target;
        this.stream = stream;
        this.temp = temp;
    }

    /**
     * The placement for a file at {@code target}: a directory, or a path with no file name, is
     * refused (E502); a regular file its owner made read-only is not replaced.
     */
    static Placement of(Path target) throws IOException {
        Path absolute = target.toAbsolutePath();
        if (absolute.getFileName() == null || Files.isDirectory(absolute)) {
            throw new AtomicOutput.Refused(Code.E502_OUTPUT_IS_DIRECTORY);
        }
        if (Files.exists(absolute) && (!Files.isRegularFile(absolute) || isDescriptor(absolute))) {
            return new Placement(Kind.WRITE_THROUGH, absolute, null, TempFiles.create(null, "gcnc-", ".part"));
        }
        Path real = Files.isSymbolicLink(absolute) && Files.exists(absolute) ? absolute.toRealPath() : absolute;
        if (Files.exists(real) && !Files.isWritable(real)) {
            // A rename would replace a file its owner made read-only to keep it: write nothing.
            throw new java.nio.file.AccessDeniedException(target.toString());
        }
        Placement p = new Placement(Kind.REPLACE, real, null, TempFiles.create(real.getParent(), "." + real.getFileName(), ".part"));
        p.keepPermissions();
        return p;
    }

    /** The placement for a stream (standard output): copied into it on commit. */
    static Placement of(OutputStream stream) throws IOException {
        return new Placement(Kind.STREAM, null, stream, TempFiles.create(null, "gcnc-", ".part"));
    }

    /**
     * A name under /dev or /proc, such as /dev/stdout or /proc/self/fd/3: it stands for a descriptor
     * the caller opened, which may be a regular file ({@code >> log}). Replacing that file would throw
     * away what it held; it is written through (appended to) instead.
     */
    private static boolean isDescriptor(Path absolute) {
        return absolute.startsWith("/dev") || absolute.startsWith("/proc");
    }

    Kind kind() {
        return kind;
    }

    /** The temporary file the output is written to. */
    Path temp() {
        return temp;
    }

    /** A new file is ordinary (rw-r--r--), not private like a temporary one; a replaced file keeps its mode. */
    private void keepPermissions() throws IOException {
        if (!temp.getFileSystem().supportedFileAttributeViews().contains("posix")) {
            return;
        }
        try {
            Set<PosixFilePermission> mode = PosixFilePermissions.fromString("rw-r--r--");
            if (Files.isRegularFile(target)) {
                mode = Files.getPosixFilePermissions(target);
            }
            Files.setPosixFilePermissions(temp, mode);
        } catch (IOException | RuntimeException e) {
            // a store without modes (a FAT stick) refuses them: its files have none to keep. Asked
            // only then: reading the mount table costs a millisecond per output, every compile.
            if (e instanceof IOException && !storeHasModes()) {
                return;
            }
            TempFiles.delete(temp);
            throw e;
        }
    }

    private boolean storeHasModes() {
        try {
            return Files.getFileStore(temp).supportsFileAttributeView("posix");
        } catch (IOException e) {
            return true; // not known: the refusal stands
        }
    }

    /** Puts the finished temporary file where it belongs. */
    void install() throws IOException {
        switch (kind) {
            case REPLACE -> {
                if (Files.exists(target, LinkOption.NOFOLLOW_LINKS)) {
                    keepBackup();
                }
                try {
                    Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                } catch (IOException | RuntimeException e) {
                    dropBackup();
                    throw e;
                }
            }
            case WRITE_THROUGH -> {
                try (OutputStream o = Files.newOutputStream(target, StandardOpenOption.WRITE, StandardOpenOption.APPEND)) {
                    Files.copy(temp, o);
                }
                TempFiles.delete(temp);
            }
            case STREAM -> {
                Files.copy(temp, stream);
                stream.flush();
                TempFiles.delete(temp);
            }
        }
        TempFiles.forget(temp);
    }

    /** A second name for the old target (a hard link; a copy where links are not possible). */
    private void keepBackup() throws IOException {
        Path b = temp.resolveSibling(temp.getFileName() + ".old");
        TempFiles.remember(b);
        try {
            try {
                Files.createLink(b, target);
            } catch (IOException | UnsupportedOperationException e) {
                Files.copy(target, b, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.COPY_ATTRIBUTES);
            }
        } catch (IOException | RuntimeException e) {
            TempFiles.delete(b);
            throw e;
        }
        backup = b;
    }

    /** Takes back {@link #install}: the old file returns, or the new one goes if there was none. */
    void undo() throws IOException {
        if (kind != Kind.REPLACE) {
            return;
        }
        if (backup != null) {
            // Should the move back fail, the old contents stay in the backup file: never deleted.
            TempFiles.forget(backup);
            Files.move(backup, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            backup = null;
        } else {
            Files.deleteIfExists(target);
        }
    }

    /** The old target's second name, once the whole commit is done (or its rename failed). */
    void dropBackup() throws IOException {
        if (backup != null) {
            TempFiles.delete(backup);
            backup = null;
        }
    }
}
