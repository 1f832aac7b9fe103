package gcnc.controller;

import static gcnc.controller.Statements.onlyInProgram;
import static gcnc.controller.Statements.range;
import static gcnc.controller.Statements.split;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The controller's own two-letter commands, those gcnc.dmc does not read ({@link Statements} hands them
 * here): the protocol's ({@code TC}, {@code CW}, {@code CF}, {@code EO}, {@code WH}, {@code UL}, {@code RS},
 * {@code LM ?}, {@code DM}), the threads' ({@code XQ}, {@code HX}, {@code JP}, {@code JS}, {@code RE},
 * {@code ZS}, and the waits {@code MC}, {@code AI}), the stops ({@code ST}, {@code AB}, {@code MO}) and the
 * axes' ({@code IT}, {@code VR}, {@code CS}, {@code DP}, {@code TP}, {@code OB}); what the virtual controller
 * does not model is {@code ?} with TC 1.
 */
record OwnCommands(VirtualGalil c, ThreadFlow flow) {

    /** Accepted and stored nowhere: servo tuning, soft limits (not modelled; docs say so). IT: {@link #smooth}. */
    private static final java.util.Set<String> NO_EFFECT = java.util.Set.of("KP", "KI", "KD", "ER", "BL", "FL", "TL",
            "OE", "NO");

    private double eval(String e) throws GalilException {
        return Expressions.eval(e, c);
    }

    String command(String cmd, String args, ProgramThread th) throws GalilException {
        return switch (cmd) {
            // the protocol's
            case "TC" -> tellError(args);
            case "MG" -> MgFormat.message(c, args, th);
            case "CW" -> dataAdjustment(args);
            case "CF" -> configureUnsolicited(args, th);
            case "EO" -> echo(args, th);
            case "WH" -> whichHandle(th);
            case "UL" -> upload(th);
            case "DL" -> throw new GalilException(th != null ? Tc.NOT_IN_PROGRAM : Tc.UNRECOGNIZED);
            case "LM" -> linearMode(args);
            case "DM" -> dimension(args);
            case "RS" -> reset(th);
            // the threads' and their waits
            case "XQ" -> flow.execute(args);
            case "HX" -> flow.halt(args);
            case "ZS" -> zeroStack(th);
            case "RE" -> returnFromError(th);
            case "JP", "JS" -> flow.jump(cmd, args, th);
            case "MC" -> waitForSequence(th);
            case "AI" -> waitForInput(args, th);
            // the stops
            case "ST" -> stop(args, th);
            case "AB" -> abort(args, th);
            case "MO" -> motorsOff(args);
            // the axes'
            case "IT" -> smoothing(args);
            case "CA" -> coordinateAxes(args);
            case "VR" -> vectorRatio(args);
            case "CS" -> clearSequence(args);
            case "DP" -> define(args);
            case "TP", "RP" -> tell(args);
            case "OB" -> outputBit(args);
            default -> {
                if (NO_EFFECT.contains(cmd)) {
                    yield "";
                }
                throw new GalilException(Tc.UNRECOGNIZED);
            }
        };
    }

    /** TC n: the last error's code (n = 1: with its text), then no error. */
    private String tellError(String args) throws GalilException {
        double n = args.isEmpty() ? 0 : eval(args);
        Tc e = c.lastError;
        c.lastError = Tc.NONE;
        return (n == 1 && e != Tc.NONE ? e.code + " " + e.text : String.valueOf(e.code)) + "\r\n";
    }

    /** CW 1 or 2: whether unsolicited characters have their high bit set (1) or not (2). */
    private String dataAdjustment(String args) throws GalilException {
        double n = eval(split(args).get(0));
        if (n != 1 && n != 2) {
            throw new GalilException(Tc.RANGE);
        }
        c.cw = (int) n;
        return "";
    }

    /** WH: the handle the command came in on (COMALL WH: not valid in a program). */
    private String whichHandle(ProgramThread th) throws GalilException {
        if (th != null) {
            throw new GalilException(Tc.NOT_IN_PROGRAM);
        }
        return (c.port == 'S' ? "SERIAL" : "IH" + c.port) + "\r\n";
    }

    /** UL: the program in memory, ended by a backslash (not valid in a program). */
    private String upload(ProgramThread th) throws GalilException {
        if (th != null) {
            throw new GalilException(Tc.NOT_IN_PROGRAM);
        }
        return c.program.upload() + "\\";
    }

    /** LM ?: the vector buffer's free slots (what gcnc asks); LM/LI linear mode is not modelled. */
    private String linearMode(String args) throws GalilException {
        if (args.equals("?")) {
            return c.motion.free() + "\r\n";
        }
        throw new GalilException(Tc.UNRECOGNIZED);
    }

    /**
     * ZS: zero the subroutine stack (COMALL ZS): an error routine's EN then ends the thread instead of
     * returning into the motion it interrupted (gcnc's #FAULT does this).
     */
    private String zeroStack(ProgramThread th) throws GalilException {
        onlyInProgram(th);
        th.stack.clear();
        return "";
    }

    /** RE: back from an error routine (COMALL RE: "Not Valid in terminal"). */
    private String returnFromError(ProgramThread th) throws GalilException {
        onlyInProgram(th);
        th.back();
        return "";
    }

    /** MC: the thread waits until the sequence is still. */
    private String waitForSequence(ProgramThread th) throws GalilException {
        onlyInProgram(th);
        th.waitingFor = ThreadWaits.sequenceStill(c.motion);
        return "";
    }

    /** AI n: the thread waits until input n is on (n above 0) or off (n below 0). */
    private String waitForInput(String args, ProgramThread th) throws GalilException {
        onlyInProgram(th);
        int n = (int) eval(args);
        int bit = Math.abs(n);
        c.io("IN", bit);
        th.waitingFor = ThreadWaits.input(c, bit, n > 0);
        return "";
    }

    /** ST: the sequence decelerates to a stop; without an operand the other threads halt too. */
    private String stop(String args, ProgramThread th) {
        if (args.isEmpty()) {
            haltOthers(th);
        }
        c.motion.stop(4);
        c.gearing.stop(); // gearing off, a settling move ends where it is (assumed: docs/virtual-controller.md)
        return "";
    }

    /** AB: the motion ends at once; AB 1 leaves the threads running. */
    private String abort(String args, ProgramThread th) throws GalilException {
        double n = args.isEmpty() ? 0 : eval(args);
        if (n != 1) {
            haltOthers(th);
        }
        c.motion.abort(7, c.time());
        c.gearing.stop();
        return "";
    }

    /** Every program thread but {@code th} (the one that gave the command; null: the host) halts. */
    private void haltOthers(ProgramThread th) {
        for (ProgramThread t : c.threads) {
            if (t != th) {
                t.halt();
            }
        }
    }

    /** MO: the axes' motors off (all without an operand); a sequence on one of them ends. */
    private String motorsOff(String args) throws GalilException {
        VectorMotion mo = c.motion;
        for (int a : axesOrAll(args)) {
            c.servo[a] = false;
            if (a == mo.axis1 || a == mo.axis2) {
                mo.abort(0, c.time());
            }
        }
        c.gearing.stop();
        return "";
    }

    /** IT n,n,...: one value per axis in order, an empty place leaves that axis as it is. */
    private String smoothing(String args) throws GalilException {
        String[] places = args.split(",", -1);
        for (int i = 0; i < places.length; i++) {
            if (!places[i].isBlank()) {
                smooth(i, eval(places[i].strip()));
            }
        }
        return "";
    }

    /** CA S: the coordinate system gcnc uses, the only one modelled. */
    private String coordinateAxes(String args) throws GalilException {
        if (!args.equals("S")) {
            throw new GalilException(Tc.S_OPERAND);
        }
        return "";
    }

    /** VR r: the vector speed ratio, 0 to 10. */
    private String vectorRatio(String args) throws GalilException {
        c.motion.vr = range(eval(args), 0, 10);
        c.motion.changed();
        return "";
    }

    /** CS (or CS S): the sequence buffer cleared. */
    private String clearSequence(String args) throws GalilException {
        if (!args.isEmpty() && !args.equals("S")) {
            throw new GalilException(Tc.S_OPERAND);
        }
        c.motion.clear();
        return "";
    }

    /** OB n,v: output n on (v not 0) or off. */
    private String outputBit(String args) throws GalilException {
        List<String> a = split(args);
        if (a.size() != 2) {
            throw new GalilException(Tc.OPERAND);
        }
        int n = (int) range(eval(a.get(0)), 1, c.model.outputs);
        c.setOutput(n, eval(a.get(1)) != 0);
        return "";
    }

    /**
     * CF: where unsolicited messages go (COMALL CF): {@code CF S} the main serial port (the power-up
     * value), {@code CF A}..{@code CF H} an Ethernet handle, {@code CF I} the port the command came in on
     * ("Not valid in program"). The reference offers {@code T} for an aux serial port the virtual
     * controller does not have.
     */
    private String configureUnsolicited(String args, ProgramThread th) throws GalilException {
        String a = args.strip();
        if (a.equals("I")) {
            if (th != null) {
                throw new GalilException(Tc.NOT_IN_PROGRAM);
            }
            c.cf = c.port;
        } else if (a.equals("S") || a.length() == 1 && a.charAt(0) >= 'A' && a.charAt(0) <= 'H') {
            c.cf = a.charAt(0);
        } else {
            throw new GalilException(Tc.OPERAND);
        }
        return "";
    }

    /**
     * EO: the serial port's echo (COMALL EO: "defaulted to EO1", "accepted over the serial port only";
     * "The ethernet port will not echo commands"). From an Ethernet handle it is refused: the reference
     * does not say with which code, TC 1 is assumed (docs/virtual-controller.md).
     */
    private String echo(String args, ProgramThread th) throws GalilException {
        if (th == null && c.port != 'S') {
            throw new GalilException(Tc.UNRECOGNIZED);
        }
        double n = eval(args.isEmpty() ? "1" : args);
        if (n != 0 && n != 1) {
            throw new GalilException(Tc.RANGE);
        }
        c.echo = n == 1;
        return "";
    }

    /**
     * {@code IT} of axis {@code a}: 0.004 to 1, resolution 1/256 (command reference IT). Below 1 the real
     * controller filters the axis in VM and the motion takes longer; the virtual one does not smooth, so it
     * says so in the trace (docs/virtual-controller.md).
     */
    void smooth(int a, double v) throws GalilException {
        if (a < 0 || a >= c.model.axes) {
            throw new GalilException(Tc.OPERAND);
        }
        if (v < 0.004 || v > 1) {
            throw new GalilException(Tc.RANGE);
        }
        c.smoothing[a] = v;
        if (v != 1) {
            c.traceEvent(String.format(Locale.ROOT, "IT %c %.4f: smoothing not modelled, the motion runs unfiltered (IT 1)",
                    (char) ('A' + a), v));
        }
    }

    private List<Integer> axesOrAll(String args) throws GalilException {
        if (args.isEmpty()) {
            List<Integer> all = new ArrayList<>();
            for (int i = 0; i < c.model.axes; i++) {
                all.add(i);
            }
            return all;
        }
        return c.axes(args);
    }

    private String define(String args) throws GalilException {
        if (c.motion.running()) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        List<String> a = split(args);
        if (a.size() > c.model.axes) {
            throw new GalilException(Tc.OPERAND);
        }
        for (int i = 0; i < a.size(); i++) {
            if (!a.get(i).isEmpty()) {
                c.motion.position[i] = (long) eval(a.get(i));
            }
        }
        c.motion.clear();
        return "";
    }

    private String tell(String args) throws GalilException {
        List<Integer> axes = axesOrAll(args);
        StringBuilder b = new StringBuilder();
        for (int a : axes) {
            b.append(b.length() == 0 ? "" : ", ").append((long) Math.rint(c.motion.position[a]));
        }
        return b + "\r\n";
    }

    /** DM name[n], ...; {@code DM ?} answers the array elements still free (a sender's pre-flight). */
    private String dimension(String args) throws GalilException {
        if (args.equals("?")) {
            return (int) c.operand("DM") + "\r\n";
        }
        for (String d : split(args)) {
            Matcher m = Pattern.compile("([A-Za-z][A-Za-z0-9]{0,7})\\[(.+)\\]").matcher(d);
            if (!m.matches()) {
                throw new GalilException(Tc.OPERAND);
            }
            int n = (int) range(eval(m.group(2)), 1, c.model.arrayElements);
            int used = Operands.elementsUsed(c);
            double[] old = c.arrays.get(m.group(1));
            if (used - (old == null ? 0 : old.length) + n > c.model.arrayElements) {
                throw new GalilException(Tc.ARRAY_SPACE);
            }
            if (old == null && c.arrays.size() >= Model.ARRAYS) {
                throw new GalilException(Tc.TOO_MANY_VARIABLES);
            }
            c.arrays.put(m.group(1), new double[n]);
        }
        return "";
    }

    /** RS: motion, threads, variables, arrays, outputs and errors back to power-up; the program stays; #AUTO runs. */
    private String reset(ProgramThread th) throws GalilException {
        if (th != null) {
            throw new GalilException(Tc.NOT_IN_PROGRAM); // COMALL RS: "Not Valid in program"
        }
        for (ProgramThread t : c.threads) {
            t.halt();
        }
        c.motion.abort(7, c.time());
        c.gearing.stop();
        c.variables.clear();
        c.arrays.clear();
        c.outputs = 0;
        java.util.Arrays.fill(c.offsets, 0);
        java.util.Arrays.fill(c.servo, false);
        c.lastError = Tc.NONE;
        c.cw = 2;
        c.cf = 'S';
        c.echo = c.model.galil.serialEcho();
        java.util.Arrays.fill(c.smoothing, 1);
        int auto = c.program.label("AUTO");
        if (auto >= 0) {
            c.threads[0].start(auto);
        }
        return "";
    }
}
