package gcnc.studio;

import gcnc.ProgramFiles;
import gcnc.output.AtomicOutput;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * The folder the studio serves (DIR): the only place it reads or writes. A page names a file by its
 * path relative to DIR with '/' between folders ({@code parts/bishop.nc}); every name is refused
 * unless it stays inside DIR once links are followed (no {@code ..}, no absolute path, no link out),
 * names a regular file (no device, pipe or folder) and, for the studio's own writes, a program
 * ({@link ProgramFiles#EXTENSIONS}) or the DMC and map it compiles to.
 */
final class Workspace {
    /** A name the studio will not use, with the reason shown to the user (and status 400 or 404). */
    static final class Refused extends Exception {
        private final int status;

        Refused(int status, String message) {
            super(message);
            this.status = status;
        }

        int status() {
            return status;
        }
    }

    /** A program as the page gets it: its text and a version that changes when the file does. */
    record Program(String name, String text, String version) {
    }

    /** One program in the list. */
    record Entry(String name, long size, long modified) {
    }

    /** A path segment the studio accepts: no control characters, no backslash or colon (a Windows path). */
    private static final Pattern SEGMENT = Pattern.compile("[^\\x00-\\x1f\\x7f/\\\\:]+");
    /** The longest program the studio opens or saves (a page sends the whole text on each check). */
    static final long MAX_BYTES = 8L << 20;

    private final Path root;

    /** @param root DIR; must exist and be a folder */
    Workspace(Path root) throws IOException {
        this.root = root.toRealPath();
        if (!Files.isDirectory(this.root)) {
            throw new IOException(root + " is not a folder");
        }
    }

    Path root() {
        return root;
    }

    /** The programs under DIR (sub-folders too), as names relative to DIR, in name order. */
    List<Entry> list() throws IOException {
        List<Entry> out = new ArrayList<>();
        for (Path p : ProgramFiles.in(root, ProgramFiles.EXTENSIONS)) {
            if (!inside(p)) {
                continue; // a link to a file outside DIR is not listed (nor opened)
            }
            out.add(new Entry(name(p), Files.size(p), Files.getLastModifiedTime(p).toMillis()));
        }
        return out;
    }

    /** A program's text (UTF-8, a byte that is not becomes U+FFFD as the CLI reads it) and its version. */
    Program read(String name) throws Refused, IOException {
        Path p = existing(name);
        if (Files.size(p) > MAX_BYTES) {
            throw new Refused(413, name + " is larger than " + (MAX_BYTES >> 20) + " MB");
        }
        byte[] bytes = Files.readAllBytes(p);
        return new Program(name(p), new String(bytes, StandardCharsets.UTF_8), version(bytes));
    }

    /**
     * Writes a program as one step (a temporary file renamed over it): a failure leaves the old file
     * as it was. {@code expected} is the version the page opened (null for a new file): when the file
     * changed on disk since, or a new file's name is taken, nothing is written (409), unless {@code force}.
     * The version is compared and the file written under one lock ({@link #saving}): of two pages
     * that save on the same version at the same moment one is written and the other gets 409, its
     * text still in its editor (both once got 200 and one edit was lost). A text longer than
     * {@link #MAX_BYTES} is refused (413), as opening it would be.
     */
    Program save(String name, String text, String expected, boolean force) throws Refused, IOException {
        Path p = writable(name, true);
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        if (bytes.length > MAX_BYTES) {
            throw new Refused(413, name + " is larger than " + (MAX_BYTES >> 20) + " MB (" + bytes.length
                    + " bytes): the studio neither opens nor saves such a program");
        }
        synchronized (saving) {
            boolean exists = Files.exists(p, LinkOption.NOFOLLOW_LINKS);
            if (!force) {
                if (expected == null && exists) {
                    throw new Refused(409, name + " already exists");
                }
                if (expected != null && exists && !expected.equals(version(Files.readAllBytes(p)))) {
                    throw new Refused(409, name + " changed on disk since it was opened");
                }
                if (expected != null && !exists) {
                    throw new Refused(409, name + " was removed since it was opened");
                }
            }
            try (AtomicOutput out = new AtomicOutput(p)) {
                Writer w = out.writer();
                w.write(text);
                w.flush();
                out.commit();
            }
        }
        return new Program(name(p), text, version(bytes));
    }

    /**
     * Held from a save's version check to its rename: the check and the write are one step for every
     * page of this studio. (An editor outside the studio takes no lock; its change between the two is
     * the one a save can still overwrite, a few milliseconds wide.)
     */
    private final Object saving = new Object();

    /** A program that exists, for reading. */
    Path existing(String name) throws Refused, IOException {
        Path p = resolve(name);
        if (!Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
            throw new Refused(404, "no file " + name + " in the studio's folder");
        }
        if (!inside(p)) {
            throw new Refused(403, name + " leads outside the studio's folder");
        }
        if (!Files.isRegularFile(p)) {
            throw new Refused(403, name + " is not a regular file");
        }
        if (!isProgram(p)) {
            throw new Refused(403, name + " is not a part program (" + String.join(", ", ProgramFiles.EXTENSIONS) + ")");
        }
        return p;
    }

    /**
     * A file the studio may write: inside DIR, in a folder that exists, a regular file or nothing yet
     * (never a link, device or pipe, which a rename or a write would go through); a program when
     * {@code program}, else an output the compile names.
     */
    Path writable(String name, boolean program) throws Refused, IOException {
        return writable(resolve(name), name, program);
    }

    Path writable(Path p, String name, boolean program) throws Refused, IOException {
        Path parent = p.getParent();
        if (parent == null || !Files.isDirectory(parent) || !parent.toRealPath().startsWith(root)) {
            throw new Refused(403, name + " is not in a folder of the studio's folder");
        }
        if (Files.isSymbolicLink(p)) {
            throw new Refused(403, name + " is a link; the studio does not write through links");
        }
        if (Files.exists(p, LinkOption.NOFOLLOW_LINKS) && !Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
            throw new Refused(403, name + " is not a regular file");
        }
        if (program && !isProgram(p)) {
            throw new Refused(400, name + ": a program's name ends in ." + String.join(", .", ProgramFiles.EXTENSIONS));
        }
        return p;
    }

    /**
     * Where a compile of {@code program} writes, as {@code gcnc compile} names it: the DMC and the
     * stream form's stream, each with its map, every one checked {@link #writable} (the stream's
     * files are written when the program does not fit the controller, removed when it does).
     */
    record CompileOutputs(Path dmc, String dmcName, Path stream, String streamName) {
    }

    CompileOutputs compileOutputs(Path program) throws Refused, IOException {
        Path dmc = gcnc.output.DmcOutputs.defaultOutput(program);
        Path stream = gcnc.output.FormOutputs.streamFile(dmc);
        for (Path p : new Path[] {dmc, gcnc.output.DmcOutputs.mapFile(dmc), stream, gcnc.output.DmcOutputs.mapFile(stream)}) {
            writable(p, name(p), false);
        }
        return new CompileOutputs(dmc, name(dmc), stream, name(stream));
    }

    /** A workspace step an endpoint takes; {@link #refusing} answers its refusal. */
    interface Call<T> {
        T call() throws Refused, IOException;
    }

    /** Runs {@code call}, a refusal becoming the HTTP answer it names (its status and message). */
    static <T> T refusing(Call<T> call) throws IOException, Http.Fail {
        try {
            return call.call();
        } catch (Refused r) {
            throw new Http.Fail(r.status(), r.getMessage());
        }
    }

    /**
     * A machine profile Configure may write: a name ending in .machine, inside DIR, in a folder
     * that exists, never through a link, a device or a pipe.
     */
    Path writableProfile(String name) throws Refused, IOException {
        Path p = resolve(name);
        if (!p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".machine")
                || p.getFileName().toString().length() <= ".machine".length()) {
            throw new Refused(400, shown(name) + ": a machine profile's name ends in .machine");
        }
        return writable(p, name, false);
    }

    /** A file's name relative to DIR when it is a program under DIR (links followed), else empty. */
    Optional<String> nameOf(String file) {
        try {
            Path real = Path.of(file).toRealPath();
            return real.startsWith(root) && isProgram(real) ? Optional.of(name(real)) : Optional.empty();
        } catch (IOException | InvalidPathException e) {
            return Optional.empty();
        }
    }

    /** The name of {@code p} relative to DIR, '/' between folders. */
    String name(Path p) {
        return root.relativize(p).toString().replace(java.io.File.separatorChar, '/');
    }

    /**
     * A relative name to a path under DIR, by its text alone: no empty, "." or ".." segment, no
     * absolute path, no control character. Links are checked by the caller ({@link #inside}).
     */
    Path resolve(String name) throws Refused {
        if (name == null || name.isEmpty()) {
            throw new Refused(400, "no file name given");
        }
        if (name.length() > 1024 || name.startsWith("/")) {
            throw new Refused(400, "a file name is relative to the studio's folder: " + shown(name));
        }
        Path p = root;
        for (String segment : name.split("/", -1)) {
            if (segment.equals(".") || segment.equals("..") || !SEGMENT.matcher(segment).matches()) {
                throw new Refused(400, "not a file name in the studio's folder: " + shown(name));
            }
            try {
                p = p.resolve(segment);
            } catch (InvalidPathException e) {
                throw new Refused(400, "not a file name: " + shown(name));
            }
        }
        return p;
    }

    /** Whether {@code p} (which exists) is still under DIR once every link is followed. */
    boolean inside(Path p) throws IOException {
        try {
            return p.toRealPath().startsWith(root);
        } catch (NoSuchFileException e) {
            return false; // a dangling link
        }
    }

    static boolean isProgram(Path p) {
        String n = p.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return dot > 0 && ProgramFiles.EXTENSIONS.contains(n.substring(dot + 1).toLowerCase(Locale.ROOT));
    }

    /** A name as a message shows it: control characters escaped, at most 80 characters. */
    static String shown(String name) {
        StringBuilder b = new StringBuilder();
        name.codePoints().limit(80).forEach(c -> {
            if (c < 0x20 || c == 0x7f) {
                b.append(String.format("\\x%02x", c));
            } else {
                b.appendCodePoint(c);
            }
        });
        return b.toString();
    }

    static String version(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes), 0, 12);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java has SHA-256", e);
        }
    }
}
