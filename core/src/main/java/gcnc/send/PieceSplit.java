package gcnc.send;

import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.dmc.StreamSplit;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * A piece to run split into the stream form's two parts as the compile splits a program ({@link StreamSplit}),
 * each command keeping the compiled program's line it stands for (what {@link StreamForm} downloads and sends).
 */
record PieceSplit(List<PieceSplit.Sent> resident, List<PieceSplit.Sent> stream) {
    /** A command of the run and the compiled program's line it stands for. */
    record Sent(Command command, int origin) {
    }

    /** The resident program as it is downloaded: packed into lines as the compile writes it. */
    List<String> residentLines(int width) {
        return Download.packedLines(resident.stream().map(Sent::command).toList(), width);
    }

    /** {@code piece} split as the compile splits a program ({@link StreamSplit}), each command keeping its compiled line. */
    static PieceSplit of(Download piece, DmcProgram program) {
        Map<Instruction, Integer> origins = new IdentityHashMap<>();
        List<Instruction> stream = new ArrayList<>();
        StreamSplit split = new StreamSplit(stream::add, Long.MAX_VALUE, program.lineWidth());
        for (int j = 0; j < piece.commands().size(); j++) {
            int o = Math.max(0, piece.originOf(j));
            Instruction i = new Instruction(piece.commands().get(j), program.instructions().get(o).source());
            origins.put(i, o);
            split.accept(i);
        }
        List<Instruction> resident = split.finish().resident();
        // a command the split made (gready, a routine's label and EN, the call of a moved block) stands
        // for the compiled line of the command beside it
        List<Sent> r = new ArrayList<>();
        Map<String, Integer> routineStart = new HashMap<>();
        int last = 0;
        String label = null;
        for (int k = 0; k < resident.size(); k++) {
            Instruction i = resident.get(k);
            Integer o = origins.get(i);
            if (i.command() instanceof Command.Label l) {
                label = l.name();
                Integer next = k + 1 < resident.size() ? origins.get(resident.get(k + 1)) : null;
                if (next != null) {
                    routineStart.put(label, next);
                }
            }
            last = o != null ? o : last;
            r.add(new Sent(i.command(), o != null ? o : last));
        }
        List<Sent> s = new ArrayList<>(stream.size());
        last = 0;
        for (Instruction i : stream) {
            Integer o = origins.get(i);
            if (o == null && i.command() instanceof Command.Call call) {
                o = routineStart.get(call.label());
            }
            last = o != null ? o : last;
            s.add(new Sent(i.command(), last));
        }
        return new PieceSplit(r, s);
    }
}
