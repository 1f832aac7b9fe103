package gcnc.machine;

import gcnc.diag.Phrase;
import gcnc.tables.TableException;
import java.util.List;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * Every key a machine profile may hold: the one list, so that a misspelt key is a fault at its
 * line instead of a setting silently left at its default (a {@code x.counts_per_m} would leave the
 * required key missing; a {@code stock.stick_out} would leave the blank where the default puts it).
 * When a key is added to {@link ProfileLoader} or {@link MachineModel}, it is added here and to
 * docs/profiles.md or docs/simulator.md; ProfileKeysTest holds the three together.
 */
final class ProfileKeys {
    /** Keys read by name: ProfileLoader (docs/profiles.md), then MachineModel (docs/simulator.md). */
    static final List<String> NAMED = List.of(
            "name", "control", "units", "machine_zero", "chuck.driven_by", "galil.model", "galil.firmware", "galil.deviations",
            "x.galil", "z.galil", "x.sign", "z.sign", "x.counts_per_mm", "z.counts_per_mm",
            "x.counts_per_inch", "z.counts_per_inch", "x.travel", "z.travel", "x.programming",
            "input.no_point", "home", "rapid.speed", "feed.max", "vector.acceleration", "vector.deceleration",
            "spindle.max_rpm", "spindle.rpm_per_volt", "spindle.axis", "spindle.encoder", "spindle.encoder_axis", "tool_post", "offsets.unit",
            "offsets.file", "wear.max_step", "wear.max_total",
            "tools.table", "tools.offsets", "tools.count", "tools.file", "feed.per_f", "thread.chamfer_leads",
            "thread.chamfer_angle", "plan.blend", "corner.deviation", "plan.on_the_fly", "reference.2", "reference.3", "reference.4",
            // the machine around the motion (MachineIo)
            "spindle.output", "spindle.at_speed", "spindle.at_speed_timeout", "turret.station_outputs",
            "turret.strobe", "turret.in_position", "turret.timeout", "homing.check", "homing.tolerance",
            "stop.cycle_start",
            // the simulator's machine model
            "sim.centre_x", "chuck.face_z", "chuck.jaw_diameter", "chuck.jaw_length", "chuck.diameter",
            "stock.diameter", "stock.length", "stock.stickout", "stock.header",
            "tailstock.centre_z", "tailstock.quill_diameter");

    /** Keys numbered or named by pattern; {@code shape} says how to write them, for the fault (its {0}: the key). */
    record Family(String prefix, Pattern form, Phrase shape) {
        Family(String prefix, String form, Phrase shape) {
            this(prefix, Pattern.compile(form), shape);
        }

        boolean matches(String key) {
            return form.matcher(key).matches();
        }
    }

    static final List<Family> FAMILIES = List.of(
            new Family("work.", "work\\.G5[4-9]", Phrase.UNKNOWN_KEY_WORK),
            // T's last two digits pick the offset: 1 to 99 (tool.0 is refused by ProfileLoader, with its reason)
            new Family("tool.", "tool\\.[0-9]{1,2}", Phrase.UNKNOWN_KEY_TOOL),
            new Family("nose.", "nose\\.[0-9]{1,2}", Phrase.UNKNOWN_KEY_NOSE),
            // wear of tool offset N, apart from its geometry tool.N (ToolWear; also the only key of an offsets file)
            new Family("wear.", "wear\\.[0-9]{1,2}", Phrase.UNKNOWN_KEY_WEAR),
            new Family("m.", "m\\.[0-9]{1,3}", Phrase.UNKNOWN_KEY_M),
            new Family("sim.tool.", "sim\\.tool\\.(default|[0-9]{1,2})(\\.(insert|holder))?",
                    Phrase.UNKNOWN_KEY_SIM_TOOL),
            // the shop's tool table: one line per turret station (ToolTable)
            new Family("station.", "station\\.[0-9]{1,2}", Phrase.UNKNOWN_KEY_STATION));

    private ProfileKeys() {
    }

    /** Faults at the first key (in file order) that gcnc does not read. */
    static void check(ProfileFile f) throws TableException {
        for (String key : f.keys()) {
            if (!known(key)) {
                throw f.faultAtKey(f.required(key), unknown(key));
            }
        }
    }

    static boolean known(String key) {
        return NAMED.contains(key) || FAMILIES.stream().anyMatch(fam -> fam.matches(key));
    }

    /**
     * The message for an unknown key (a {@link Phrase} argument): a known key within a couple of letters first (a typo), then
     * how its family is written when it starts like one ({@code work.G60}), then a known key with
     * the same last part ({@code lathe.home}), else where the keys are listed.
     */
    static String unknown(String key) {
        Optional<String> typo = Spelling.typo(key, NAMED);
        if (typo.isPresent()) {
            return Phrase.UNKNOWN_KEY_TYPO.with(key, typo.get());
        }
        for (Family fam : FAMILIES) {
            if (key.startsWith(fam.prefix())) {
                return fam.shape().with(key);
            }
        }
        return Spelling.sameLastPart(key, NAMED).map(k -> Phrase.UNKNOWN_KEY_TYPO.with(key, k))
                .orElse(Phrase.UNKNOWN_KEY_DOCS.with(key));
    }
}
