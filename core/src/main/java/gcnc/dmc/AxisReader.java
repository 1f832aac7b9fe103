package gcnc.dmc;

import gcnc.machine.Plane;
import static gcnc.dmc.DmcReader.axes;
import static gcnc.dmc.DmcReader.bad;
import static gcnc.dmc.DmcReader.INT32;
import static gcnc.dmc.DmcReader.integer;

import gcnc.diag.Code;
import gcnc.dmc.Command.*;
import gcnc.dmc.DmcReader.Faults;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The per-axis commands of a DMC line, for {@link DmcReader} (the one reader): {@code OF}, {@code GA},
 * the thread's sync point, {@code MF}/{@code MR}, {@code GR}, {@code PA}, {@code AO}, the servo
 * settings {@code KP KI KD ER} and the soft limits {@code BL}/{@code FL}; each value at its channel's
 * place ({@code GA ,,C}), as {@link DmcPrinter} writes them. What is not of its form is E301.
 */
final class AxisReader {
    private static final Pattern SYNC = Pattern.compile(
            "([a-z][a-z0-9]{0,7})=\\(@INT\\[_TP([A-HXYZW])/([0-9]{1,7})\\]([+-]1)\\)\\*([0-9]{1,7})([+-][0-9]{1,7})?");
    private static final Pattern VARIABLE = Pattern.compile("[a-z][a-z0-9]{0,7}");
    /** {@code gpz=(_TPC-gsp)*_GRX-(_RPX-35480)} (or {@code +35480} for a negative start), as DmcPrinter writes it. */
    private static final Pattern PHASE = Pattern.compile(
            "([a-z][a-z0-9]{0,7})=\\(_TP([A-HXYZW])-([a-z][a-z0-9]{0,7})\\)\\*_GR([A-HXYZW])-\\(_RP([A-HXYZW])([+-][0-9]{1,10})\\)");

    private AxisReader() {
    }

    static Command offset(String args, String text, Faults faults) {
        String[] a = args.split(",", -1);
        int channel = -1;
        Fixed volts = null;
        for (int i = 0; i < a.length; i++) {
            if (a[i].isBlank()) {
                continue;
            }
            Fixed v = Fixed.parse(a[i], 0, a[i].length(), false);
            if (v == null || Math.abs(v.value()) > 9.998 || channel >= 0) {
                return bad(faults, "OF", text); // gcnc writes one channel's offset per OF
            }
            channel = i;
            volts = v;
        }
        return channel < 0 || channel > 7 ? bad(faults, "OF", text) : new Offset(channel, volts);
    }

    /** Per-channel arguments: the value at each channel's place, "" where empty; null past eight places. */
    static String[] places(String args) {
        String[] a = args.split(",", -1);
        if (a.length > 8) {
            return null;
        }
        for (int i = 0; i < a.length; i++) {
            a[i] = a[i].strip();
        }
        return a;
    }

    /** The places that hold a value, in channel order; null unless exactly {@code n}. */
    static int[] filled(String[] slots, int n) {
        if (slots == null) {
            return null;
        }
        int[] at = new int[n];
        int k = 0;
        for (int i = 0; i < slots.length; i++) {
            if (!slots[i].isEmpty()) {
                if (k == n) {
                    return null;
                }
                at[k++] = i;
            }
        }
        return k == n ? at : null;
    }

    /** The k-th filled place as a number ({@code whole}: no point allowed), or null when it is not one or no places fit. */
    private static Fixed value(String[] slots, int[] at, int k, boolean whole) {
        return at == null ? null : Fixed.parse(slots[at[k]], 0, slots[at[k]].length(), whole);
    }

    static Command gearMaster(String args, String text, Faults faults) {
        String[] slots = places(args);
        int[] at = filled(slots, 2);
        if (at == null || slots[at[0]].length() != 1 || !slots[at[0]].equals(slots[at[1]])
                || Plane.channel(slots[at[0]].charAt(0)) < 0) {
            return bad(faults, "GA", text);
        }
        return new GearMaster(slots[at[0]].charAt(0), Plane.letter(at[0]), Plane.letter(at[1]));
    }

    static Command syncPoint(String t, Faults faults) {
        Matcher p = PHASE.matcher(t);
        if (p.matches()) {
            if (!p.group(4).equals(p.group(5))) {
                faults.fault(Code.E300_SIM_UNKNOWN_INSTRUCTION, t);
                return null;
            }
            return new Command.PhaseError(p.group(1), p.group(2).charAt(0), p.group(3), p.group(4).charAt(0),
                    -Long.parseLong(p.group(6)));
        }
        Matcher m = SYNC.matcher(t);
        if (!m.matches() || !m.group(3).equals(m.group(5))) {
            faults.fault(Code.E300_SIM_UNKNOWN_INSTRUCTION, t);
            return null;
        }
        long phase = m.group(6) == null ? 0 : Long.parseLong(m.group(6));
        return new SyncPoint(m.group(1), m.group(2).charAt(0), Integer.parseInt(m.group(3)), m.group(4).equals("-1"),
                phase);
    }

    static Command waitPast(String cmd, String args, String text, Faults faults) {
        String[] slots = places(args);
        int[] at = filled(slots, 1);
        if (at == null) {
            return bad(faults, cmd, text);
        }
        String v = slots[at[0]];
        Command.Operand operand;
        if (VARIABLE.matcher(v).matches()) {
            operand = new Operand.Variable(v);
        } else {
            Fixed n = Fixed.parse(v, 0, v.length(), true);
            if (n == null) {
                return bad(faults, cmd, text);
            }
            operand = new Operand.Count(n.unscaled());
        }
        return new WaitPast(cmd.equals("MR"), Plane.letter(at[0]), operand);
    }

    /** Two numbers at two axes' places, in channel order ({@code GR}, {@code PA}, {@code BL}/{@code FL}). */
    private record Two(char first, Fixed p, char second, Fixed q) {
    }

    /** The two numbers {@code args} holds at their axes' places ({@code whole}: no point allowed), or null. */
    private static Two two(String args, boolean whole) {
        String[] slots = places(args);
        int[] at = filled(slots, 2);
        Fixed p = value(slots, at, 0, whole);
        Fixed q = value(slots, at, 1, whole);
        return p == null || q == null ? null : new Two(Plane.letter(at[0]), p, Plane.letter(at[1]), q);
    }

    static Command gearRatio(String args, String text, Faults faults) {
        Two r = two(args, false);
        return r == null ? bad(faults, "GR", text) : new GearRatio(r.first(), r.p(), r.second(), r.q());
    }

    /** {@code IP gpz,gpx} or {@code IP gpz}: one or two variables at their axes' places. */
    static Command incrementPosition(String args, String text, Faults faults) {
        String[] slots = places(args);
        int[] at = filled(slots, 2);
        if (at == null) {
            at = filled(slots, 1);
        }
        if (at == null) {
            return bad(faults, "IP", text);
        }
        for (int i : at) {
            if (!VARIABLE.matcher(slots[i]).matches()) {
                return bad(faults, "IP", text);
            }
        }
        return at.length == 2
                ? new Command.IncrementPosition(Plane.letter(at[0]), slots[at[0]], Plane.letter(at[1]), slots[at[1]])
                : new Command.IncrementPosition(Plane.letter(at[0]), slots[at[0]], (char) 0, "");
    }

    /** {@code DP ,,0}: one axis's position, a whole count. */
    static Command definePosition(String args, String text, Faults faults) {
        String[] slots = places(args);
        int[] at = filled(slots, 1);
        Fixed n = value(slots, at, 0, true);
        if (n == null) {
            return bad(faults, "DP", text);
        }
        return new Command.DefinePosition(Plane.letter(at[0]), n.unscaled());
    }

    static Command positionAbsolute(String args, String text, Faults faults) {
        Two p = two(args, true);
        return p == null ? bad(faults, "PA", text)
                : new PositionAbsolute(p.first(), p.p().unscaled(), p.second(), p.q().unscaled());
    }

    static Command analogOut(String args, String text, Faults faults) {
        int comma = args.indexOf(',');
        // a Modbus device's analog output, 1,000 to 8,999: AO's only range (command reference AO)
        int n = comma < 0 ? -1 : integer(args.substring(0, comma).strip(), 1000, 8999);
        Fixed v = comma < 0 ? null : Fixed.parse(args, comma + 1, args.length(), false);
        if (n < 0 || v == null || Math.abs(v.value()) > 9.9998) {
            return bad(faults, "AO", text);
        }
        return new AnalogOut(n, v);
    }

    static Command axisSetting(Setting setting, String args, String text, Faults faults) {
        String[] slots = places(args);
        int[] at = filled(slots, 1);
        Fixed v = value(slots, at, 0, false);
        if (v == null) {
            return bad(faults, setting.name(), text);
        }
        return new AxisSetting(setting, at[0], v);
    }

    static Command softLimit(String cmd, String args, String text, Faults faults) {
        Two l = two(args, true);
        if (l == null) {
            return bad(faults, cmd, text);
        }
        if (Math.abs(l.p().unscaled()) > INT32 || Math.abs(l.q().unscaled()) > INT32) {
            faults.fault(Code.E310_SIM_COUNT_RANGE, text);
            return null;
        }
        return new SoftLimit(cmd.equals("FL"), l.first(), l.p().unscaled(), l.second(), l.q().unscaled());
    }
}
