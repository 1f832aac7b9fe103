package gcnc.machine;

import gcnc.tables.Tables.Param;
import java.util.Set;

/**
 * A row of a control's G table (the thesis's Table 3 with Table 7 as {@code words}): the code as
 * the control writes it, its modal group (0 = one-shot), what it does, and the parameter words
 * it takes ({@code null}: not restricted).
 */
public record GFunction(int code, int group, GRole role, Set<Param> words, String english, String spanish) {
    public GFunction {
        // an EnumSet (a bit mask) behind a read-only view: the checker asks it for every word of every block
        words = words == null ? null : java.util.Collections.unmodifiableSet(
                words.isEmpty() ? java.util.EnumSet.noneOf(Param.class) : java.util.EnumSet.copyOf(words));
    }

    public boolean modal() {
        return group != 0;
    }

    public String name() {
        return code < 10 ? "G0" + code : "G" + code;
    }
}
