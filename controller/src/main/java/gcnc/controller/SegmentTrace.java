package gcnc.controller;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.util.Locale;

/**
 * {@code --trace FILE}: one line per executed segment, so that a test can compare the path the
 * controller ran with the simulator's, count for count (docs/virtual-controller.md, "Trace"):
 * <pre>
 * SEQUENCE SEGMENT VP|CR END1 END2 FREE TIME
 * </pre>
 * the sequence number (from 1, one per BGS), the segment's number in it (from 1; {@code _CSS} reads one
 * less while it executes: the segment counter starts at zero), its kind, the
 * absolute end position of the two plane axes in whole counts (first VM axis first), the free buffer slots
 * when it ended ({@code _LMS}) and the controller time in seconds. Lines that start with {@code #} are
 * events, not segments: the header, a sequence's end and why ({@code end}, {@code underrun}, {@code stop},
 * {@code abort}), a limit trip, a stall, an {@code AV}'s trip ({@code # av n tripped at P of path (trip point
 * T)}: P the path run when the thread went on, T the sum of the sequence's AV distances) or an AV the
 * sequence ended short of. Each line is flushed as it is written.
 */
final class SegmentTrace {
    private final Writer out;

    SegmentTrace(Writer out) {
        this.out = new BufferedWriter(out);
    }

    void header(String revision) {
        line("# gcnc virtual controller " + revision + ": sequence segment kind end1 end2 free time");
    }

    void segment(int sequence, int number, VectorSegment s, int free, double time) {
        line(String.format(Locale.ROOT, "%d %d %s %d %d %d %.4f", sequence, number, s.arc() ? "CR" : "VP",
                (long) Math.rint(s.end1()), (long) Math.rint(s.end2()), free, time));
    }

    /** A thread pass settled on its end: {@code PASS 1 PA END1 END2 FREE TIME}, its number counted from 1. */
    void pass(int pass, double end1, double end2, int free, double time) {
        line(String.format(Locale.ROOT, "%d 1 PA %d %d %d %.4f", pass, (long) Math.rint(end1), (long) Math.rint(end2),
                free, time));
    }

    void event(String text, double time) {
        line(String.format(Locale.ROOT, "# %s t=%.4f", text, time));
    }

    private void line(String text) {
        try {
            out.write(text);
            out.write('\n');
            out.flush();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    void close() {
        try {
            out.close();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
