package gcnc.tables;

import gcnc.diag.Phrase;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * The one way gcnc turns the bytes of a table, control or machine profile into text: UTF-8,
 * strictly. A byte-order mark at the start is dropped (editors on Windows write one); a byte that
 * is not UTF-8 is a fault at its line and column, because a silently replaced character would turn
 * a value into something else and surface later as a strange finding.
 */
public final class Utf8 {
    private static final byte[] BOM = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};

    private Utf8() {
    }

    /**
     * The most bytes a table, control or profile file may have: 8 MiB, a hundred times the largest
     * shipped table. A link to {@code /dev/zero} or a file of another kind named by mistake is
     * refused there (E404) rather than read until memory runs out.
     */
    public static final int MAX_BYTES = 8 << 20;

    /** The text of the file {@code file}, at most {@link #MAX_BYTES} bytes ({@code path}: the name faults carry). */
    public static String read(String path, java.nio.file.Path file) throws java.io.IOException, TableException {
        try (java.io.InputStream in = java.nio.file.Files.newInputStream(file)) {
            return decode(path, bounded(path, in));
        }
    }

    /** The bytes of {@code in}, refused (E404) past {@link #MAX_BYTES}: never more than that is held. */
    public static byte[] bounded(String path, java.io.InputStream in) throws java.io.IOException, TableException {
        byte[] bytes = in.readNBytes(MAX_BYTES + 1);
        if (bytes.length > MAX_BYTES) {
            throw new TableException(path, gcnc.diag.Diagnostic.error(gcnc.diag.Code.E404_TABLE_FILE_TOO_LARGE,
                    gcnc.diag.Span.of(1, 1), MAX_BYTES));
        }
        return bytes;
    }

    /** The text of {@code bytes}, read from the file {@code path} (the name faults carry). */
    public static String decode(String path, byte[] bytes) throws TableException {
        int start = startsWithBom(bytes) ? BOM.length : 0;
        CharsetDecoder decoder = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes, start, bytes.length - start);
        CharBuffer out = CharBuffer.allocate(bytes.length);
        CoderResult result = decoder.decode(in, out, true);
        if (!result.isError()) {
            result = decoder.flush(out);
        }
        out.flip();
        if (result.isError()) {
            // The decoder stops at the first byte of the bad sequence; out holds the text before it.
            throw badByte(path, out, bytes[in.position()]);
        }
        return out.toString();
    }

    private static boolean startsWithBom(byte[] bytes) {
        return bytes.length >= BOM.length && bytes[0] == BOM[0] && bytes[1] == BOM[1] && bytes[2] == BOM[2];
    }

    /** The fault at the place of the bad byte, counted in the characters before it as an editor shows them. */
    private static TableException badByte(String path, CharSequence before, byte bad) {
        int line = 1;
        int column = 1;
        for (int i = 0; i < before.length(); i++) {
            if (before.charAt(i) == '\n') {
                line++;
                column = 1;
            } else {
                column++;
            }
        }
        return Csv.fault(path, line, column, Phrase.NOT_UTF8.with(String.format("0x%02X", bad & 0xFF)));
    }
}
