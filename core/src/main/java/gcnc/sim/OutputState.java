package gcnc.sim;

import gcnc.machine.MachineProfile;
import gcnc.machine.MRole;
import java.util.List;

/**
 * The controller's digital outputs as SB/CB left them, read back as machine states through the
 * profile's M output map, by what each M does in the machine's control: the spindle runs once an M03 or M04 pattern is completed and stops
 * once an M05 pattern is; the chuck closes with M11's pattern and opens with M10's. A pattern
 * counts when the directive just written belongs to it and all its bits now match. At start
 * the spindle is stopped; the chuck is closed where the operator clamps it before cycle start
 * (the profile's chuck.driven_by), else treated as open (unknown) until M11's pattern is seen.
 * With no outputs for M03/M04 (or M10/M11) in the profile the matching check is off.
 */
final class OutputState {
    private static final int BITS = 1000;
    private final byte[] bits = new byte[BITS]; // 0 unknown, 1 off, 2 on
    private final int[][] patterns = new int[12][];
    private int highest = -1;
    boolean running;
    boolean closed;
    final boolean spindleKnown;
    final boolean chuckKnown;

    OutputState(MachineProfile p) {
        for (MRole role : new MRole[] {MRole.SPINDLE_CW, MRole.SPINDLE_CCW, MRole.SPINDLE_STOP, MRole.CHUCK_OPEN,
            MRole.CHUCK_CLOSE}) {
            int m = role.number();
            // the control's own code for it (Haas clamps the chuck with M10, the thesis with M11)
            List<String> dirs = p.control().mFor(role).map(f -> p.outputsFor(f.code())).orElse(List.of());
            int[] pat = new int[dirs.size()];
            for (int i = 0; i < pat.length; i++) {
                String d = dirs.get(i);
                int bit = Integer.parseInt(d.substring(2).strip());
                pat[i] = d.startsWith("SB") ? bit + 1 : -(bit + 1);
            }
            patterns[m] = pat;
        }
        // the operator clamps the part before cycle start unless the program drives the chuck
        closed = !p.chuckByProgram();
        spindleKnown = patterns[3].length > 0 || patterns[4].length > 0;
        chuckKnown = patterns[10].length > 0 || patterns[11].length > 0;
    }

    void set(int bit, boolean on) {
        if (bit < 0 || bit >= BITS) {
            return;
        }
        bits[bit] = (byte) (on ? 2 : 1);
        highest = Math.max(highest, bit);
        int signed = on ? bit + 1 : -(bit + 1);
        if (completes(3, signed) || completes(4, signed)) {
            running = true;
        } else if (completes(5, signed)) {
            running = false;
        }
        if (completes(11, signed)) {
            closed = true;
        } else if (completes(10, signed)) {
            closed = false;
        }
    }

    private boolean completes(int m, int signed) {
        int[] pat = patterns[m];
        boolean mine = false;
        for (int d : pat) {
            mine |= d == signed;
            int bit = Math.abs(d) - 1;
            if (bits[bit] != (d > 0 ? 2 : 1)) {
                return false;
            }
        }
        return mine;
    }

    /** The outputs known to be on, for findings and the trace: "on 1 3" or "all off". */
    String describe() {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i <= highest; i++) {
            if (bits[i] == 2) {
                b.append(b.length() == 0 ? "on " : " ").append(i);
            }
        }
        return b.length() == 0 ? "all off" : b.toString();
    }
}
