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
 * in chunks. {@link StreamReplay} replays the stream form's two files through the same loop.
 */
public final class DmcReplay {
    /** How many lines from the start may hold the {@code NO STOCK} comment (it follows the header). */
    private static final int HEAD = 64;

    private DmcReplay() {
    }

    /**
     * One command read: its command (null for a blank or unreadable statement), where it is located,
     * what the reader could not read, and the file's line it is on.
     */
    record Read(Command command, String text, Source at, List<Fault> faults, int dmcLine) {
    }

    /** The lines of a replay, one at a time; null at the end. */
    interface Reads {
        Read next() throws IOException;
    }

    /**
     * A DMC file's commands, each line read once and split into its statements ({@code ;}, a packed
     * line): each located at the map's G-code line, else at the last {@code NO L} mark's, else at
     * the DMC line.
     */
    static Reads lines(BufferedReader in, gcnc.dmc.SourceMap.Locator sourceOf) {
        return new Reads() {
            private int dmcLine;
            private int source = -1;
            private List<String> statements = List.of();
            private int next;

            @Override
            public Read next() throws IOException {
                String l = null;
                if (next >= statements.size()) {
                    l = in.readLine();
                    if (l == null) {
                        return null;
                    }
                    dmcLine++;
                    statements = DmcReader.statements(l);
                    next = 0;
                }
                // a blank line is one read of nothing: it still counts as a line of the file
                int k = next++;
                String text = statements.isEmpty() ? l : statements.get(k);
                Source mapped = sourceOf == null ? null : sourceOf.source(dmcLine, k);
                List<Fault> faults = new ArrayList<>(0);
                Command c = DmcReader.read(text, (code, args) -> faults.add(new Fault(code, args)));
                if (c instanceof Command.SourceMark mark) {
                    source = mark.line();
                }
                Source at = mapped != null ? mapped : Source.line(source > 0 ? source : dmcLine);
                return new Read(c, text, at, faults, dmcLine);
            }
        };
    }

    public static SimReport replay(BufferedReader in, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics) {
        return replay(in, profile, options, diagnostics, null);
    }

    /**
     * @param sourceOf the G-code file and line of each DMC command, from the source-map side file
     *                 ({@link gcnc.dmc.SourceMap#read}; null where it has none); null when there is no map
     */
    public static SimReport replay(BufferedReader in, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics, gcnc.dmc.SourceMap.Locator sourceOf) {
        return replay(lines(in, sourceOf), profile, options, diagnostics);
    }

    /** Replays {@code reads}: the blank of a {@code NO STOCK} line among the first ones, then every line in chunks. */
    static SimReport replay(Reads reads, MachineProfile profile, SimOptions options, Diagnostics diagnostics) {
        List<Read> head = new ArrayList<>();
        IOException failure = null;
        try {
            for (Read r = reads.next(); r != null; r = head.size() < HEAD ? reads.next() : null) {
                head.add(r);
            }
        } catch (IOException e) {
            failure = e;
        }
        if (options.stock().isEmpty() && !options.noBlank()) {
            for (Read r : head) {
                if (r.command() instanceof Command.Stock stock) {
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
        // a DMC file by itself is held to the controller's limits as a compile's output is (a hand-edited
        // CR 9,0,90 is refused by the controller: it must not replay clean)
        Diagnostics refused = new Diagnostics();
        gcnc.galil.LimitCheck limits = new gcnc.galil.LimitCheck(profile.controllerLimits(), refused, chunk::add);
        int lines = 0;
        try {
            java.util.Iterator<Read> first = head.iterator();
            for (Read read = next(first, reads, failure); read != null; read = next(first, reads, failure)) {
                Read r = read;
                lines++;
                if (!r.faults().isEmpty()) {
                    sim.replay(chunk); // findings in the order of the lines
                    chunk.clear();
                    r.faults().forEach(f -> sim.fault(r.at(), f.code(), f.args()));
                }
                // a blank or unreadable line is still a line of the file: the lines after it keep their numbers
                Command c = r.command() != null ? r.command()
                        : new Command.Remark(r.faults().isEmpty() ? r.text().strip() : "");
                limits.accept(new Instruction(c, r.at()));
                if (chunk.size() == 1024) {
                    sim.replay(chunk);
                    chunk.clear();
                }
            }
        } catch (IOException e) {
            diagnostics.error(Code.E500_IO, Span.of(Math.max(1, lines), 1), gcnc.diag.Phrase.IO_CANNOT_READ.arg(),
                    gcnc.diag.Phrase.reason(e));
        }
        sim.replay(chunk);
        limits.finish();
        sim.end(List.of());
        // the limit errors are findings of the replay too: in the run's diagnostics and in its count
        diagnostics.addAll(refused);
        return sim.report().withMoreFindings(refused.size());
    }

    /** The next line: from the lines read ahead, then from the reader; a read-ahead failure is thrown when they run out. */
    private static Read next(java.util.Iterator<Read> first, Reads reads, IOException failure) throws IOException {
        if (first.hasNext()) {
            return first.next();
        }
        if (failure != null) {
            throw failure;
        }
        return reads.next();
    }

    record Fault(Code code, Object[] args) {
    }
}
