package gcnc.lsp;

import gcnc.ModalStates;
import gcnc.machine.FunctionText;
import gcnc.machine.MachineProfile;
import gcnc.tables.ErrorMessages;
import java.util.Optional;

/**
 * The hover's text, in Markdown: what a G or M word does on this control ({@link FunctionText}, the
 * studio's hover and {@code gcnc explain G71} read the same rows) and the modal state after the
 * line's block ({@link ModalStates}, as the studio's hover shows it).
 */
final class Hovers {
    private Hovers() {
    }

    /** The function {@code word} names on {@code profile}'s control, if it is a G or M word. */
    static Optional<String> function(MachineProfile profile, String word, ErrorMessages.Lang lang) {
        return FunctionText.of(profile.control(), word).map(f -> {
            if (!f.known()) {
                return "**" + f.name() + "**: not a code of control " + f.control();
            }
            String kind = f.letter() == 'G' ? (f.modal() ? "modal, group " + f.group() : "one-shot")
                    : moment(f.moment());
            return "**" + f.name() + "** " + f.text(lang) + "  \n*" + kind + "; control " + f.control() + "*";
        });
    }

    private static String moment(int m) {
        return switch (m) {
            case 1 -> "at the start of the block";
            case 99 -> "at the end of the block";
            default -> "during the block";
        };
    }

    /** The state after a block, one line of Markdown per topic. */
    static String state(ModalStates.Snapshot s, MachineProfile profile) {
        ModalStates.Summary m = ModalStates.summary(s, profile);
        StringBuilder o = new StringBuilder();
        o.append(m.accepted() ? "After this block" : "This block has an error; the state before it");
        if (m.runs() > 1) {
            o.append(" (first of ").append(m.runs()).append(" runs)");
        }
        o.append(":\n\n");
        o.append("- ").append(or(m.unitsG())).append(' ').append(m.units()).append(", ")
                .append(m.incremental() ? "incremental" : "absolute")
                .append(m.motion() != null ? ", " + m.motion() : "").append('\n');
        String feedUnit = m.feedPerRev() ? (m.units().equals("inch") ? "in/rev" : "mm/rev")
                : (m.units().equals("inch") ? "in/min" : "mm/min");
        o.append("- feed ").append(or(m.feedG())).append(m.feed() != null ? " F" + num(m.feed()) + " " + feedUnit : ", no F yet")
                .append('\n');
        o.append("- spindle ").append(or(m.spindleG()));
        if (m.css()) {
            o.append(m.surfaceSpeed() != null ? " S" + num(m.surfaceSpeed()) : "");
        }
        if (m.rpm() != null) {
            o.append(", ").append(num(m.rpm())).append(" rpm");
        }
        m.blockRpm().ifPresent(r -> o.append(" (").append(num(r)).append(" rpm at this block's X)"));
        if (m.rpmClamp() != null) {
            o.append(", clamp ").append(num(m.rpmClamp())).append(" rpm");
        }
        o.append('\n');
        o.append("- work offset ").append(m.workOffset());
        m.workOffsetMm().ifPresent(w -> o.append(" (X").append(num(w.x())).append(" Z").append(num(w.z())).append(" mm)"));
        o.append('\n');
        o.append("- tool ").append(m.tool()).append(", offset ").append(m.toolOffset());
        m.toolOffsetMm().ifPresent(t -> o.append(" (X").append(num(t.x())).append(" Z").append(num(t.z())).append(" mm)"));
        o.append(", nose ").append(or(m.nose())).append('\n');
        m.at().ifPresent(a -> o.append("- tool at X").append(num(a.x())).append(" Z").append(num(a.z()))
                .append(a.diameter() ? " (X a diameter)" : "").append('\n'));
        return o.toString();
    }

    private static String or(String g) {
        return g == null ? "-" : g;
    }

    private static String num(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) + "." : Double.toString(v);
    }
}
