package gcnc.plan;

import gcnc.ir.CheckedBlock;
import java.util.function.Consumer;

/**
 * Every motion its own sequence, stopped at its end: what gcnc wrote before it planned (and the
 * thesis wrote). Holds nothing back.
 */
public final class ExactStop implements Planner {
    @Override
    public void accept(CheckedBlock b, Consumer<Step> out) {
        out.accept(new Step.Before(b));
        for (int i = 0; i < b.motions().size(); i++) {
            out.accept(new Step.Alone(b, i));
        }
        out.accept(new Step.After(b));
    }

    @Override
    public void finish(Consumer<Step> out) {
    }

    @Override
    public boolean holding() {
        return false;
    }
}
