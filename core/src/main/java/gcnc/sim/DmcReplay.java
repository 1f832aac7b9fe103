package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.galil.GalilLine;
import gcnc.machine.MachineProfile;
import java.io.BufferedReader;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * Replays a .dmc file by itself (a user's hand-edited program, or --trace): no G-code to compare
 * against, so conformance is off and a sequence counts as a rapid when its VS equals the
 * profile's rapid.speed, unless gcnc marked it a feed ({@code NO G01}). The blank is the one of a
 * {@code NO STOCK} comment in the program's first lines (what the compile was checked against)
 * when the options give none. Findings are located at the G-code line when the file carries
 * {@code NO L<line>} source-map comments or a source map is given, else at the DMC line. Streams
 * in chunks.
 */
public final class DmcReplay {
    /** How many lines from the start may hold the {@code NO STOCK} comment (it follows the header). */
    private static final int HEAD = 64;

    private DmcReplay() {
    }

    public static SimReport replay(BufferedReader in, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics) {
        return replay(in, profile, options, diagnostics, null);
    }

    /**
     * @param sourceOf the G-code line of each DMC line, from the source-map side file
     *                 ({@link gcnc.galil.SourceMap#read}); null when there is none
     */
    public static SimReport replay(BufferedReader in, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics, java.util.function.IntUnaryOperator sourceOf) {
        List<String> head = new ArrayList<>();
        IOException failure = null;
        try {
            for (String l = head.size() < HEAD ? in.readLine() : null; l != null; l = head.size() < HEAD ? in.readLine() : null) {
                head.add(l);
            }
        } catch (IOException e) {
            failure = e;
        }
        if (options.stock().isEmpty() && !options.noBlank()) {
            for (String l : head) {
                if (gcnc.galil.StockComment.isNone(l)) {
                    options = options.withoutBlank();
                    break;
                }
                gcnc.machine.MachineModel.Blank b = gcnc.galil.StockComment.read(l);
                if (b != null) {
                    options = options.withStock(new StockSize(b.diameter(), b.length(), b.stickout(), b.bore()));
                    break;
                }
            }
        }
        Simulator sim = new Simulator(profile, options, diagnostics);
        List<GalilLine> chunk = new ArrayList<>();
        int dmcLine = 0;
        int source = -1;
        try {
            java.util.Iterator<String> first = head.iterator();
            for (String l = next(first, in, failure); l != null; l = next(first, in, failure)) {
                dmcLine++;
                String t = l.strip();
                if (t.startsWith("NO L")) {
                    source = sourceLine(t.substring(4), source);
                }
                int mapped = sourceOf == null ? 0 : sourceOf.applyAsInt(dmcLine);
                chunk.add(new GalilLine(l, mapped > 0 ? mapped : source > 0 ? source : dmcLine));
                if (chunk.size() == 1024) {
                    sim.replay(chunk);
                    chunk.clear();
                }
            }
        } catch (IOException e) {
            diagnostics.error(Code.E500_IO, Span.of(Math.max(1, dmcLine), 1), gcnc.diag.Phrase.IO_CANNOT_READ.arg(),
                    gcnc.diag.Phrase.reason(e));
        }
        sim.replay(chunk);
        sim.end(List.of());
        return sim.report();
    }

    /** The next line: from the lines read ahead, then from the reader; a read-ahead failure is thrown when they run out. */
    private static String next(java.util.Iterator<String> first, BufferedReader in, IOException failure) throws IOException {
        if (first.hasNext()) {
            return first.next();
        }
        if (failure != null) {
            throw failure;
        }
        return in.readLine();
    }

    private static int sourceLine(String digits, int otherwise) {
        try {
            return Integer.parseInt(digits.strip());
        } catch (NumberFormatException e) {
            return otherwise;
        }
    }
}
