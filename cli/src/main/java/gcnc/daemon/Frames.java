package gcnc.daemon;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

/**
 * The resident checker's wire format, both ways: a frame is one type byte, a 4-byte big-endian
 * length and that many bytes. Binary frames, not lines, because a program read from standard input
 * and a DMC written to standard output may hold any byte (docs/command-line.md, "Resident checker",
 * lists the types).
 */
final class Frames {
    /** The longest frame read: a chunk of standard input or output is at most 64 KiB; a header field is short. */
    static final int MAX = 1 << 20;

    private Frames() {
    }

    /** One frame as read. */
    record Frame(char type, byte[] data) {
        String text() {
            return new String(data, StandardCharsets.UTF_8);
        }
    }

    static Frame read(DataInputStream in) throws IOException {
        int type = in.read();
        if (type < 0) {
            throw new EOFException("the connection closed");
        }
        int length = in.readInt();
        if (length < 0 || length > MAX) {
            throw new IOException("a frame of " + length + " bytes");
        }
        byte[] data = new byte[length];
        in.readFully(data);
        return new Frame((char) type, data);
    }

    static void write(DataOutputStream out, char type, byte[] data, int off, int len) throws IOException {
        out.write(type);
        out.writeInt(len);
        out.write(data, off, len);
    }

    static void write(DataOutputStream out, char type, String text) throws IOException {
        byte[] b = text.getBytes(StandardCharsets.UTF_8);
        write(out, type, b, 0, b.length);
    }
}
