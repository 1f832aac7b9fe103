package gcnc.machine;

import gcnc.diag.Phrase;
import gcnc.ir.Letter;
import gcnc.tables.Csv;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables.Param;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Reads and validates a control (tables/controls/README.md). {@code NAME} is the folder
 * {@code controls/NAME/} among the tables; anything with a '/' is a folder path. Every fault
 * names the file, line and column.
 */
public final class ControlLoader {
    /** The keys of control.cfg (tables/controls/README.md); any other is a fault, with a suggestion. */
    private static final List<String> KEYS = List.of("name", "description", "letters", "power_up", "power_up.tool",
            "spindle_clamp", "chuck", "sequence_numbers", "no_point", "dwell.p", "g28.bare", "block_delete",
            "m.unlisted", "cycle.retract_mm", "call.p", "call.depth", "macros",
            "cycle.peck_retract_mm", "cycle.pocket_allowance", "cycle.type1_first_move", "comments", "g01.corner",
            "cycle.drill_words", "cycle.drill_r", "stop.off", "stop.optional", "spindle_above_clamp");

    private ControlLoader() {
    }

    /** The controls gcnc ships (folders of tables/controls/), for the message of an unknown name. */
    public static final java.util.List<String> SHIPPED = java.util.List.of("thesis-2004", "fanuc-a", "fanuc-b", "haas");

    /** Whether {@code --control} names a folder (a '/' in it) rather than a control among the tables. */
    public static boolean isPath(String nameOrPath) {
        return nameOrPath.contains("/");
    }

    public static Control load(String nameOrPath, TableSource tables) throws TableException {
        if (isPath(nameOrPath)) {
            return read(TableSource.directory(Path.of(nameOrPath)), "");
        }
        String dir = "controls/" + nameOrPath + "/";
        try {
            tables.read(dir + "control.cfg");
        } catch (TableException e) {
            String shipped = String.join(", ", SHIPPED);
            throw ProfileFile.fault(tables.describe(dir + "control.cfg"), 1, 1, Spelling.typo(nameOrPath, SHIPPED)
                    .map(near -> Phrase.NO_CONTROL_TYPO.with(nameOrPath, near, shipped))
                    .orElse(Phrase.NO_CONTROL.with(nameOrPath, shipped)));
        }
        return read(tables, dir);
    }

    private static Control read(TableSource src, String dir) throws TableException {
        ProfileFile f = ProfileFile.parse(src.describe(dir + "control.cfg"), src.read(dir + "control.cfg"));
        for (String key : f.keys()) {
            if (!KEYS.contains(key)) {
                throw f.faultAtKey(f.required(key), Spelling.suggest(key, KEYS)
                        .map(k -> Phrase.UNKNOWN_KEY_TYPO.with(key, k)).orElse(Phrase.UNKNOWN_CONTROL_KEY.with(key)));
            }
        }
        Map<Integer, GFunction> g = gTable(src.csv(dir + "g_codes.csv"));
        Map<Integer, MFunction> m = mTable(src.csv(dir + "m_codes.csv"));

        Set<Letter> letters = EnumSet.noneOf(Letter.class);
        ProfileFile.Entry le = f.required("letters");
        for (String s : le.value().split("\\s+")) {
            Letter l = s.length() == 1 ? Letter.of(s.charAt(0)) : null;
            if (l == null) {
                throw f.fault(le, Phrase.LETTERS.with(s));
            }
            letters.add(l);
        }
        List<GFunction> powerUp = new ArrayList<>();
        Optional<Units> units = Optional.empty();
        ProfileFile.Entry pe = f.required("power_up");
        for (String s : pe.value().split("\\s+")) {
            GFunction fn = s.matches("[Gg][0-9]{1,3}") ? g.get(Integer.parseInt(s.substring(1))) : null;
            if (fn == null) {
                throw f.fault(pe, Phrase.POWER_UP.with(s));
            }
            if (fn.role() == GRole.INCH || fn.role() == GRole.METRIC) {
                units = Optional.of(fn.role() == GRole.INCH ? Units.INCH : Units.MM);
            }
            powerUp.add(fn);
        }
        double[] tool = f.pair("power_up.tool");
        return new Control(f.text("name"), f.text("description", ""), letters, g, m, powerUp, units,
                (int) tool[0], (int) tool[1],
                f.choice("spindle_clamp", "machine", "g50", "machine").equals("g50"),
                f.choice("chuck", "operator", "program", "operator").equals("program"),
                f.choice("sequence_numbers", "any", "increasing", "any").equals("increasing"),
                f.choice("no_point", "increment", "literal", "increment").equals("literal"),
                f.choice("dwell.p", "milliseconds", "milliseconds", "seconds").equals("seconds"),
                Control.BareG28.valueOf(f.choice("g28.bare", "error", "error", "home", "nothing").toUpperCase()),
                Control.BlockDelete.valueOf(f.choice("block_delete", "off", "none", "off", "on").toUpperCase()),
                f.choice("m.unlisted", "error", "error", "builder").equals("builder"),
                retract(f), calls(f),
                f.choice("macros", "none", "none", "fanuc-b").equals("fanuc-b"),
                length(f, "cycle.peck_retract_mm"),
                f.choice("cycle.pocket_allowance", "uniform", "uniform", "walls").equals("walls"),
                f.choice("comments", "spanning", "spanning", "line").equals("line"),
                Control.Corners.valueOf(f.choice("g01.corner", "none", "none", "comma", "letters").toUpperCase()),
                f.choice("cycle.drill_words", "haas", "haas", "fanuc").equals("fanuc"),
                f.choice("cycle.drill_r", "incremental", "incremental", "absolute").equals("absolute"),
                new Control.ProgramStop(stopOff(f, m), f.choice("stop.optional", "off", "off", "on").equals("on")),
                f.choice("cycle.type1_first_move", "depth_axis", "depth_axis", "positions").equals("positions"),
                f.choice("spindle_above_clamp", "alarm", "alarm", "clamp").equals("clamp"));
    }

    /**
     * {@code stop.off}: the M codes (M05 M09 ...) a program stop applies, each a spindle stop or an
     * output of the control's M table; none when the key is absent.
     */
    private static List<Integer> stopOff(ProfileFile f, Map<Integer, MFunction> m) throws TableException {
        List<Integer> codes = new ArrayList<>();
        Optional<ProfileFile.Entry> e = f.entry("stop.off");
        if (e.isEmpty()) {
            return codes;
        }
        for (String s : e.get().value().strip().split("\\s+")) {
            MFunction fn = s.matches("[Mm][0-9]{1,3}") ? m.get(Integer.parseInt(s.substring(1))) : null;
            if (s.isEmpty()) {
                continue;
            }
            if (fn == null || fn.role() != MRole.SPINDLE_STOP && fn.role() != MRole.OUTPUT) {
                throw f.fault(e.get(), Phrase.STOP_OFF.with(s));
            }
            codes.add(fn.code());
        }
        return codes;
    }

    /** cycle.retract_mm: zero or more, NaN when the control does not say. */
    private static double retract(ProfileFile f) throws TableException {
        double r = f.number("cycle.retract_mm", Double.NaN);
        if (r < 0) {
            throw f.fault(f.required("cycle.retract_mm"), Phrase.LENGTH_MM.with("cycle.retract_mm"));
        }
        return r;
    }

    /** A length key in mm, zero or more; NaN when the control does not say. */
    private static double length(ProfileFile f, String key) throws TableException {
        double r = f.number(key, Double.NaN);
        if (r < 0) {
            throw f.fault(f.required(key), Phrase.LENGTH_MM.with(key));
        }
        return r;
    }

    /** {@code call.p} (number or count_and_number) and {@code call.depth} (1 to 99, default 4). */
    private static Control.Calls calls(ProfileFile f) throws TableException {
        boolean countInP = f.choice("call.p", "number", "number", "count_and_number").equals("count_and_number");
        String depth = f.text("call.depth", "4");
        if (!depth.matches("[0-9]{1,2}") || Integer.parseInt(depth) < 1) {
            throw f.fault(f.required("call.depth"), Phrase.CALL_DEPTH.with(depth));
        }
        return new Control.Calls(countInP, Integer.parseInt(depth));
    }

    private static Map<Integer, GFunction> gTable(Csv csv) throws TableException {
        Map<Integer, GFunction> g = new HashMap<>();
        for (Csv.Row r : csv.rows()) {
            int code = code(r, "G", g);
            GRole role = role(r, GRole::named);
            g.put(code, new GFunction(code, group(r), role, words(r), r.get("en"), r.get("es")));
        }
        return g;
    }

    private static Map<Integer, MFunction> mTable(Csv csv) throws TableException {
        Map<Integer, MFunction> m = new HashMap<>();
        for (Csv.Row r : csv.rows()) {
            int code = code(r, "M", m);
            int moment = r.integer("moment");
            if (moment != 0 && moment != 1 && moment != 99) {
                throw r.faultAt("moment", Phrase.MOMENT.with("0, 1", moment));
            }
            MRole role = role(r, MRole::named);
            String out = r.get("output");
            if (!out.equals("yes") && !out.equals("no")) {
                throw r.faultAt("output", Phrase.OUTPUT_YES_NO.with(out));
            }
            m.put(code, new MFunction(code, group(r), moment, role, out.equals("yes"), r.get("en"), r.get("es")));
        }
        return m;
    }

    /** The row's code, 0 to 999, on no earlier row of its table ({@code letter} G or M: how the fault names it). */
    private static int code(Csv.Row r, String letter, Map<Integer, ?> earlier) throws TableException {
        int code = r.integer("code");
        if (code < 0 || code > 999) {
            throw r.faultAt("code", Phrase.CODE_RANGE.with(999, code));
        }
        if (earlier.containsKey(code)) {
            throw r.faultAt("code", Phrase.LISTED_TWICE.with(letter + code));
        }
        return code;
    }

    /** The row's function column: one of gcnc's roles, as {@code named} (GRole's or MRole's) finds it. */
    private static <R> R role(Csv.Row r, java.util.function.Function<String, R> named) throws TableException {
        R role = named.apply(r.get("function"));
        if (role == null) {
            throw r.faultAt("function", Phrase.UNKNOWN_FUNCTION.with(r.get("function")));
        }
        return role;
    }

    private static int group(Csv.Row r) throws TableException {
        int group = r.integer("group");
        if (group < 0 || group > 99) {
            throw r.faultAt("group", Phrase.GROUP_RANGE.with(group));
        }
        return group;
    }

    /** The words column: letters of Table 7 separated by spaces, '-' none, '*' not restricted (null). */
    private static Set<Param> words(Csv.Row r) throws TableException {
        String w = r.get("words").trim();
        if (w.equals("*")) {
            return null;
        }
        Set<Param> set = EnumSet.noneOf(Param.class);
        if (w.equals("-")) {
            return set;
        }
        for (String s : w.split("\\s+")) {
            try {
                set.add(Param.valueOf(s));
            } catch (IllegalArgumentException e) {
                throw r.faultAt("words", Phrase.WORDS.with(s));
            }
        }
        return set;
    }
}
