package gcnc.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;

/**
 * An output file that appears whole or not at all: lines go to a temporary file beside the target,
 * which replaces the target only on {@link #commit()}. {@link #close()} without commit deletes it,
 * so a program with errors never leaves a half-written .dmc behind. A write that fails (a full
 * disk) is kept and the lines after it dropped: the compile goes on reporting the program's own
 * findings, and {@link #commit()} then throws that failure instead of replacing the target.
 */
final class AtomicOutput implements AutoCloseable {
    private final Path target;
    private final Path temp;
    private final OutputStream out;
    /** Our own buffer for {@link #line}: no lock and no copy per line (a compile writes millions). */
    private final byte[] buffer = new byte[1 << 16];
    private int buffered;
    private Writer writer;
    private boolean committed;
    /** The first write error, or null. */
    private IOException failure;

    /** Opens the temporary file's stream (a seam for tests that need a failing disk). */
    interface Opener {
        OutputStream open(Path temp) throws IOException;
    }

    AtomicOutput(Path target) throws IOException {
        this(target, p -> Files.newOutputStream(p));
    }

    AtomicOutput(Path target, Opener opener) throws IOException {
        this.target = target.toAbsolutePath();
        this.temp = Files.createTempFile(this.target.getParent(), "." + target.getFileName(), ".part");
        // A temporary file is private (rw-------); the output is an ordinary file others may read.
        if (Files.getFileStore(temp).supportsFileAttributeView("posix")) {
            Files.setPosixFilePermissions(temp, PosixFilePermissions.fromString("rw-r--r--"));
        }
        this.out = opener.open(temp);
    }

    /** For text written in pieces (the SVG); a file takes either this or {@link #line}, not both. */
    Writer writer() {
        if (writer == null) {
            writer = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        }
        return writer;
    }

    /** Writes one line with an LF end (decision D5: files use LF; the sender sends CR). */
    void line(String text) {
        if (failure != null) {
            return;
        }
        try {
            int n = text.length();
            if (buffered + n + 1 > buffer.length) {
                drain();
            }
            for (int i = 0; i < n; i++) {
                char c = text.charAt(i);
                if (c >= 0x80 || buffered == buffer.length) {
                    // Not ASCII (a comment in a tool name, say) or longer than the buffer: the slow way.
                    drain();
                    out.write(text.substring(i).getBytes(StandardCharsets.UTF_8));
                    break;
                }
                buffer[buffered++] = (byte) c;
            }
            if (buffered == buffer.length) {
                drain();
            }
            buffer[buffered++] = '\n';
        } catch (IOException e) {
            failure = e;
        }
    }

    private void drain() throws IOException {
        out.write(buffer, 0, buffered);
        buffered = 0;
    }

    void commit() throws IOException {
        if (failure != null) {
            throw failure;
        }
        closeStreams();
        Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        committed = true;
    }

    @Override
    public void close() throws IOException {
        if (!committed) {
            try {
                closeStreams();
            } finally {
                Files.deleteIfExists(temp);
            }
        }
    }

    private void closeStreams() throws IOException {
        if (writer != null) {
            writer.close();
        } else {
            if (failure == null) {
                drain();
            }
            out.close();
        }
    }
}
