package gcnc.send;

import gcnc.dmc.Command;
import gcnc.machine.MachineProfile;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * Before a resume runs: what the controller holds against what the program needs at the resume
 * point ({@link Resume#restored}: the tool, each output bit the program switched — the spindle's
 * direction, the coolant, the chuck —, the spindle's speed), read from the controller ({@code MG TOOL},
 * {@code MG @OUT[n]}, {@code MG _OFc}) and said line by line: what the resume changes, and what it
 * finds as the program left it. A value the controller cannot say (a variable it does not hold, an
 * analog output it gives no operand for) is said as set, not compared. Under G96 the speed restored is
 * the surface speed's r/min where the axes are ({@link Resume#spindle}), not the r/min last set. The work offset and the feed
 * mode need nothing on the controller: the compile resolved them into every later line's counts
 * and speeds (docs/run.md, "Resume").
 */
final class ResumeState {
    private ResumeState() {
    }

    /** The lines that say what the resume at {@code line} changes on {@code c} (none when it holds all of it). */
    static List<String> changes(MachineLink c, MachineProfile profile, List<Command> restored, int line, BlockTable.Block at)
            throws IOException {
        List<String> out = new ArrayList<>();
        List<String> kept = new ArrayList<>();
        for (Command r : restored) {
            Said s = switch (Restore.of(r)) {
                case TOOL -> tool(c, (Command.ToolNumber) r);
                case OUTPUT -> output(c, profile, (Command.Output) r);
                case SPINDLE -> r instanceof Command.Offset of ? offset(c, profile, of, at, line)
                        : analog(profile, (Command.AnalogOut) r, at, line);
                // the variables are gcnc's own (gline, gstop): restored, not said
                case VARIABLE, NOTHING -> throw new IllegalArgumentException("a resume says nothing of " + r);
            };
            (s.kept() ? kept : out).add(s.text());
        }
        List<String> said = new ArrayList<>();
        for (String o : out) {
            said.add("before the resume at line " + line + " the controller is set as the program needs it: " + o);
        }
        if (!kept.isEmpty()) {
            said.add("the controller already holds what line " + line + " needs: " + String.join(", ", kept));
        }
        return said;
    }

    /** One line of what the resume finds: the controller {@code kept} it as the program needs it, or it changes. */
    private record Said(String text, boolean kept) {
    }

    private static Said tool(MachineLink c, Command.ToolNumber t) throws IOException {
        Double held = read(c, "TOOL");
        String need = "tool " + t.station();
        if (held != null && Math.round(held) == t.station()) {
            return new Said(need, true);
        }
        return new Said(need + " (the controller held " + (held == null ? "no TOOL" : "TOOL=" + Math.round(held))
                + "): TOOL=" + t.station() + "; the turret must hold station " + t.station(), false);
    }

    private static Said output(MachineLink c, MachineProfile profile, Command.Output o) throws IOException {
        Double held = read(c, "@OUT[" + o.bit() + "]");
        String need = "output " + o.bit() + names(profile, o.bit()) + (o.on() ? " on" : " off");
        if (held != null && (held != 0) == o.on()) {
            return new Said(need, true);
        }
        return new Said(need + " (the controller held it " + (held == null ? "unknown" : held != 0 ? "on" : "off")
                + "): " + (o.on() ? "SB" : "CB") + o.bit(), false);
    }

    private static Said offset(MachineLink c, MachineProfile profile, Command.Offset of, BlockTable.Block at, int line)
            throws IOException {
        Double held = read(c, "_OF" + MachineLink.letter(of.channel()));
        double v = of.volts().value();
        String need = spindle(profile, v, at, line);
        if (held != null && Math.abs(held - v) < 0.001) {
            return new Said(need, true);
        }
        return new Said(need + " (the controller held " + (held == null ? "an unknown speed"
                : String.format(Locale.ROOT, "%.4f V", held)) + ")", false);
    }

    private static Said analog(MachineProfile profile, Command.AnalogOut ao, BlockTable.Block at, int line) {
        return new Said(spindle(profile, ao.volts().value(), at, line) + " (AO" + ao.output() + " set; the controller"
                + " gives no operand to read it back)", false);
    }

    /** The spindle's speed as the program writes it: r/min (and G96's surface speed when it is in force). */
    private static String spindle(MachineProfile profile, double volts, BlockTable.Block at, int line) {
        String rpm = String.format(Locale.ROOT, "spindle %.0f r/min (%.4f V)", Math.abs(volts) * profile.rpmPerVolt(), volts);
        if (at != null && at.css() && !Double.isNaN(at.surfaceSpeed())) {
            rpm += String.format(Locale.ROOT, "; G96 S%s %s at line %d: the surface speed's r/min where the axes are",
                    trim(at.surfaceSpeed()), at.inch() ? "ft/min" : "m/min", line);
        }
        return rpm;
    }

    /** {@code v} to three decimals, without trailing zeros ("3000", "0.25"). */
    static String trim(double v) {
        if (!Double.isFinite(v)) {
            return String.valueOf(v); // a feed typed as NaN or Infinity is refused by name, not by a stack trace
        }
        return java.math.BigDecimal.valueOf(Math.rint(v * 1000) / 1000).stripTrailingZeros().toPlainString();
    }

    /** " (M08/M09)": the M codes of the profile that switch bit {@code bit}, "" when none names it. */
    private static String names(MachineProfile profile, int bit) {
        Map<Integer, Boolean> ms = new TreeMap<>();
        for (int m = 0; m < 100; m++) {
            for (String o : profile.outputsFor(m)) {
                if (o.strip().equals("SB" + bit) || o.strip().equals("CB" + bit)) {
                    ms.put(m, o.strip().startsWith("SB"));
                }
            }
        }
        if (ms.isEmpty()) {
            return "";
        }
        List<String> n = new ArrayList<>();
        ms.forEach((m, on) -> n.add(String.format(Locale.ROOT, "M%02d", m)));
        return " (" + String.join("/", n) + ")";
    }

    /** {@code MG operand}, or null when the controller cannot say (an undefined variable: it refuses the command). */
    private static Double read(MachineLink c, String operand) throws IOException {
        try {
            return c.client().number(operand);
        } catch (GalilClient.Rejected r) {
            // a variable the controller does not hold (one that never ran the program: TOOL undefined);
            // TC1 clears the error the question left (COMALL TC: "After TC has been read, the error code is
            // set to zero"), else the resumed program's end reads it in _TC and is taken for an error stop
            c.client().query("TC1");
            return null;
        }
    }
}
