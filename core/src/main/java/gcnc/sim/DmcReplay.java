package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
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
     * @param sourceOf the G-code file and line of each DMC line, from the source-map side file
     *                 ({@link gcnc.dmc.SourceMap#read}; null where it has none); null when there is no map
     */
    public static SimReport replay(BufferedReader in, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics, java.util.function.IntFunction<Source> sourceOf) {
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
                // read again below with its faults reported; here only the blank is looked for
                if (DmcReader.read(l, (code, args) -> { }) instanceof Command.Stock stock) {
                    if (stock.blank().isEmpty()) {
                        options = options.withoutBlank();
                    } else {
                        gcnc.machine.MachineModel.Blank b = stock.blank().get();
                        options = options.withStock(new StockSize(b.diameter(), b.length(), b.stickout(), b.bore()));
                    }
                    break;
                }
            }
        }
        Simulator sim = new Simulator(profile, options, diagnostics);
        List<Instruction> chunk = new ArrayList<>();
        int dmcLine = 0;
        int source = -1;
        List<Fault> faults = new ArrayList<>(1);
        try {
            java.util.Iterator<String> first = head.iterator();
            for (String l = next(first, in, failure); l != null; l = next(first, in, failure)) {
                dmcLine++;
                Source mapped = sourceOf == null ? null : sourceOf.apply(dmcLine);
                Command c = DmcReader.read(l, (code, args) -> faults.add(new Fault(code, args)));
                if (c instanceof Command.SourceMark mark) {
                    source = mark.line();
                }
                Source at = mapped != null ? mapped : Source.line(source > 0 ? source : dmcLine);
                if (!faults.isEmpty()) {
                    sim.replay(chunk); // findings in the order of the lines
                    chunk.clear();
                    faults.forEach(f -> sim.fault(at, f.code(), f.args()));
                }
                // a blank or unreadable line is still a line of the file: the lines after it keep their numbers
                chunk.add(new Instruction(c != null ? c : new Command.Remark(faults.isEmpty() ? l.strip() : ""), at));
                faults.clear();
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

    private record Fault(Code code, Object[] args) {
    }
}
