package gcnc.output;

import gcnc.diag.Code;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;

/**
 * An output that appears whole or not at all. Lines go to a temporary file; only {@link #commit()}
 * puts them where they belong, and {@link #close()} without commit deletes the temporary file, so a
 * program with errors, a full disk or a killed run ({@link TempFiles}) never leaves a half-written
 * .dmc, nor a {@code .part} file, behind. A write that fails (a full disk) is kept and the lines
 * after it dropped: the compile goes on reporting the program's own findings, and {@link #commit()}
 * then throws that failure instead of touching the target.
 *
 * <p>Where the lines end up depends on what the target is:
 * <ul>
 * <li>a regular file, or none yet: the temporary file is made beside it and renamed over it (a
 * symbolic link is followed, so the link stays and its file is replaced);</li>
 * <li>something else that exists, such as {@code /dev/null}, a terminal or a named pipe, or a name
 * for a descriptor ({@code /dev/stdout}, {@code /proc/self/fd/N}) whatever it leads to: it is
 * written through (appended to), never replaced (the temporary file is in the system's temporary
 * folder);</li>
 * <li>a stream ({@link #toStream}, standard output for {@code -o -}): copied into it on commit.</li>
 * </ul>
 * A directory, or a path with no file name ({@code /}), is refused when the output is made. Where the
 * temporary file is made and how it is put in place (and taken back within a joint commit) is
 * {@link Placement}'s job; this class writes it.
 */
public final class AtomicOutput implements AutoCloseable {
    /** An output gcnc will not write, with the diagnostic that says why. */
    public static final class Refused extends IOException {
        private final Code code;
        private final List<String> args;

        Refused(Code code, String... args) {
            super(code.id() + " " + Arrays.toString(args));
            this.code = code;
            this.args = List.of(args);
        }

        public Code code() {
            return code;
        }

        public List<String> args() {
            return args;
        }
    }

    /**
     * Who chose an output's name, which decides whether it may be written through a symbolic link.
     * Every output of gcnc is opened with one ({@link #open}): the DMC, its map, the stream and its
     * map, the drawing, the Gradle plugin's sheets and reports.
     */
    public enum Name {
        /** The user named it ({@code -o OUT}, {@code --svg OUT}): a link there is followed, its file replaced. */
        GIVEN,
        /**
         * gcnc chose it (a map or a stream beside the DMC, {@code FILE.dmc} for a compile without
         * {@code -o}, a report in a build folder): a symbolic link there is refused (E510), since
         * whoever planted it would choose the file a compile, perhaps as root, replaces.
         */
        DERIVED
    }

    /** An output at {@code target}, named as {@code name} says: a link at a {@link Name#DERIVED} name is refused (E510). */
    public static AtomicOutput open(Path target, Name name) throws IOException {
        if (name == Name.DERIVED) {
            refuseLink(target);
        }
        return new AtomicOutput(target);
    }

    /** Writes text into a writer (a report, a sheet); what {@link #write} runs. */
    @FunctionalInterface
    public interface Text {
        void to(Writer w) throws IOException;
    }

    /** A whole text file at {@code target} ({@link #open} with {@code name}): in place once written, or not at all. */
    public static void write(Path target, Name name, Text text) throws IOException {
        try (AtomicOutput out = open(target, name)) {
            Writer w = out.writer();
            text.to(w);
            w.flush();
            out.commit();
        }
    }

    /** E510 when {@code target} is a symbolic link (dangling or not). */
    public static void refuseLink(Path target) throws Refused {
        if (Files.isSymbolicLink(target)) {
            throw new Refused(Code.E510_SIDE_FILE_IS_LINK, target.toString());
        }
    }

    /** Opens the temporary file's stream (a seam for tests that need a failing disk). */
    public interface Opener {
        OutputStream open(Path temp) throws IOException;
    }

    /** Where the temporary file is and how it reaches the target. */
    private final Placement placement;
    private final Path temp;
    private final OutputStream out;
    /** Our own buffer for {@link #line}: no lock and no copy per line (a compile writes millions). */
    private final LineBuffer lines;
    private Writer writer;
    private boolean closed;
    private boolean committed;
    /** The SHA-256 of every byte written once {@link #hashed} is called, for the source map to record which DMC it belongs to. */
    private final java.security.MessageDigest sha = sha256Digest();
    private java.security.DigestOutputStream digesting;

    public AtomicOutput(Path target) throws IOException {
        this(target, p -> Files.newOutputStream(p));
    }

    public AtomicOutput(Path target, Opener opener) throws IOException {
        this(Placement.of(target), opener);
    }

    private AtomicOutput(Placement placement, Opener opener) throws IOException {
        this.placement = placement;
        this.temp = placement.temp();
        this.out = open(opener);
        this.lines = new LineBuffer(out);
    }

    /** An output that goes to {@code stream} (standard output) once committed, and nowhere otherwise. */
    public static AtomicOutput toStream(OutputStream stream) throws IOException {
        return new AtomicOutput(Placement.of(stream), p -> Files.newOutputStream(p));
    }

    /** True when the target is a regular file (or will be one): only then does a side file belong beside it. */
    public boolean replacesFile() {
        return placement.kind() == Placement.Kind.REPLACE;
    }

    /**
     * Refuses an output that is the program being read, under any name: the same path, {@code ./}, a
     * symbolic or a hard link ({@link Files#isSameFile}). Standard input ({@code input} null) has no file.
     */
    public static void refuseInput(Path input, Path output) throws Refused {
        if (input == null || !Files.exists(output) || !Files.exists(input)) {
            return;
        }
        try {
            if (Files.isSameFile(input, output)) {
                throw new Refused(Code.E501_OUTPUT_IS_INPUT, input.toString());
            }
        } catch (Refused r) {
            throw r;
        } catch (IOException e) {
            // Cannot tell (no permission to look): writing will report the real problem, if any.
        }
    }

    private OutputStream open(Opener opener) throws IOException {
        try {
            digesting = new java.security.DigestOutputStream(opener.open(temp), sha);
            digesting.on(false); // only a DMC with a map is hashed (see hashed())
            return digesting;
        } catch (IOException | RuntimeException e) {
            TempFiles.delete(temp);
            throw e;
        }
    }

    /** For a binary file (a setup sheet's PNG), written whole: a file takes this, {@link #writer} or {@link #line}. */
    public void bytes(byte[] content) throws IOException {
        out.write(content);
    }

    /** For text written in pieces (the SVG); a file takes either this or {@link #line}, not both. */
    public Writer writer() {
        if (writer == null) {
            writer = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        }
        return writer;
    }


    /**
     * Writes one line with an LF end (decision D5: files use LF; the sender sends CR); after a write
     * failure nothing more is written, and the failure is thrown at commit ({@link LineBuffer}).
     */
    public void line(String text) {
        lines.line(text);
    }

    /** Writes a line of two whole numbers, "{@code a b}" (a source map entry), digits straight into the buffer. */
    public void line(long a, long b) {
        lines.line(a, 0, b);
    }

    /** "{@code a.k b}", or "{@code a b}" when {@code k} is 0: a map entry that starts inside a packed line. */
    public void line(long a, int k, long b) {
        lines.line(a, k, b);
    }

    public void commit() throws IOException {
        commitAll(this);
    }

    /** From now on every byte written is hashed ({@link #sha256()}); call it before the first line. */
    public void hashed() {
        digesting.on(true);
    }

    /**
     * The SHA-256 of what was written since {@link #hashed}, in lowercase hex; ends the temporary file (no line may follow),
     * so a write failure is thrown here as at commit.
     */
    public String sha256() throws IOException {
        finish();
        return hex(sha.digest());
    }

    /** The SHA-256 of a file's bytes, in lowercase hex. */
    public static String sha256(Path file) throws IOException {
        java.security.MessageDigest d = sha256Digest();
        try (java.io.InputStream in = Files.newInputStream(file)) {
            byte[] b = new byte[1 << 16];
            for (int n = in.read(b); n >= 0; n = in.read(b)) {
                d.update(b, 0, n);
            }
        }
        return hex(d.digest());
    }

    private static java.security.MessageDigest sha256Digest() {
        try {
            return java.security.MessageDigest.getInstance("SHA-256");
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

    private static String hex(byte[] bytes) {
        StringBuilder b = new StringBuilder(bytes.length * 2);
        for (byte x : bytes) {
            b.append(Character.forDigit((x >> 4) & 15, 16)).append(Character.forDigit(x & 15, 16));
        }
        return b.toString();
    }

    /**
     * Puts several outputs in place as one: all or none. Every temporary file is finished first (a
     * full disk stops the commit before any target is touched); then the regular files are renamed
     * into place one by one, and when a rename fails the ones already done get their old contents
     * back (or are removed if they did not exist) before the failure is thrown.
     */
    public static void commitAll(AtomicOutput... outputs) throws IOException {
        for (AtomicOutput o : outputs) {
            o.finish();
        }
        List<AtomicOutput> order = new ArrayList<>(List.of(outputs));
        order.sort(Comparator.comparing(o -> o.placement.kind()));
        List<AtomicOutput> done = new ArrayList<>();
        try {
            for (AtomicOutput o : order) {
                o.install();
                done.add(o);
            }
        } catch (IOException | RuntimeException e) {
            for (int i = done.size() - 1; i >= 0; i--) {
                try {
                    done.get(i).placement.undo();
                } catch (IOException | RuntimeException u) {
                    e.addSuppressed(u);
                }
            }
            throw e;
        }
        for (AtomicOutput o : done) {
            o.placement.dropBackup();
        }
    }

    /** Ends the temporary file: the first write failure, or one on closing, is thrown. */
    private void finish() throws IOException {
        if (lines.failure() != null) {
            throw lines.failure();
        }
        closeStreams();
    }

    private void install() throws IOException {
        placement.install();
        committed = true;
    }

    @Override
    public void close() throws IOException {
        if (!committed) {
            try {
                closeStreams();
            } finally {
                TempFiles.delete(temp);
            }
        }
    }

    private void closeStreams() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        if (writer != null) {
            writer.close();
        } else {
            lines.flush();
            out.close();
        }
    }
}
