package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.Source;
import gcnc.machine.MachineProfile;
import java.io.BufferedReader;
import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Replays the stream form (docs/galil.md, "The stream form") as the controller and its host run
 * it: the resident program's set-up up to its {@code EN}, then the stream, then the resident's
 * routines. A {@code JS #L} of the stream runs the resident routine {@code #L} in place when it is
 * a straight run of commands (the blocks moved into the resident program: threads); a routine that
 * loops (the waits for the spindle and the turret) is answered at once, as in a program-form replay.
 * Each line is located through its own file's map.
 *
 * <p>The resident program is read whole first (it is the size of a program memory: at most
 * {@link #RESIDENT_LINES} lines are read); the stream is read line by line.
 */
public final class StreamReplay {
    /** The most lines of a resident program read (twice the largest Galil program memory). */
    public static final int RESIDENT_LINES = 8000;

    private StreamReplay() {
    }

    public static SimReport replay(BufferedReader resident, gcnc.dmc.SourceMap.Locator residentMap, BufferedReader stream,
                                   gcnc.dmc.SourceMap.Locator streamMap, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics) {
        List<DmcReplay.Read> program = new ArrayList<>();
        DmcReplay.Reads reads = DmcReplay.lines(resident, residentMap);
        try {
            for (DmcReplay.Read r = reads.next(); r != null; r = reads.next()) {
                if (r.dmcLine() > RESIDENT_LINES) {
                    diagnostics.error(Code.E244_RESIDENT_TOO_LONG_TO_REPLAY, Span.of(RESIDENT_LINES + 1, 1), RESIDENT_LINES);
                    return new Simulator(profile, options, new Diagnostics()).report();
                }
                program.add(r);
            }
        } catch (IOException e) {
            diagnostics.error(Code.E500_IO, Span.of(Math.max(1, program.size()), 1), gcnc.diag.Phrase.IO_CANNOT_READ.arg(),
                    gcnc.diag.Phrase.reason(e));
            return new Simulator(profile, options, new Diagnostics()).report();
        }
        int end = program.size();
        for (int i = 0; i < program.size(); i++) {
            if (program.get(i).command() instanceof Command.End) {
                end = i;
                break;
            }
        }
        Map<String, List<DmcReplay.Read>> straight = straightRoutines(program, end);
        DmcReplay.Reads streamReads = DmcReplay.lines(stream, streamMap);
        int setUpEnd = end;
        return DmcReplay.replay(new DmcReplay.Reads() {
            private int next;
            private List<DmcReplay.Read> routine = List.of();
            private int inRoutine;
            private boolean streamDone;

            @Override
            public DmcReplay.Read next() throws IOException {
                if (next < setUpEnd) {
                    return program.get(next++);
                }
                if (inRoutine < routine.size()) {
                    return routine.get(inRoutine++);
                }
                if (!streamDone) {
                    DmcReplay.Read r = streamReads.next();
                    if (r != null) {
                        if (r.command() instanceof Command.Call call && straight.containsKey(call.label())) {
                            routine = straight.get(call.label());
                            inRoutine = 0;
                            return next();
                        }
                        return r;
                    }
                    streamDone = true;
                }
                return next < program.size() ? program.get(next++) : null;
            }
        }, profile, options, diagnostics);
    }

    /** The routines after the set-up's EN that run straight to their EN (no jump): their lines without the label and the EN. */
    private static Map<String, List<DmcReplay.Read>> straightRoutines(List<DmcReplay.Read> program, int end) {
        Map<String, List<DmcReplay.Read>> out = new HashMap<>();
        String label = null;
        List<DmcReplay.Read> body = new ArrayList<>();
        boolean jumps = false;
        for (int i = end + 1; i < program.size(); i++) {
            Command c = program.get(i).command();
            if (c instanceof Command.Label l) {
                label = l.name();
                body = new ArrayList<>();
                jumps = false;
            } else if (label != null) {
                // inside a routine: its EN closes it, any other line is its body
                if (c instanceof Command.End) {
                    if (!jumps) {
                        out.put(label, body);
                    }
                    label = null;
                } else {
                    jumps |= c instanceof Command.Jump || c instanceof Command.Call || c instanceof Command.ClearStack;
                    body.add(program.get(i));
                }
            }
        }
        return out;
    }
}
