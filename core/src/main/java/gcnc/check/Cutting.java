package gcnc.check;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;

/**
 * Whether a checked block cuts: a feed, an arc or a thread pass (not a rapid or a dwell). A clean
 * cut closes the root causes ({@link FindingReport}) and settles the advisories' pending warnings.
 */
final class Cutting {
    private Cutting() {
    }

    /** Whether the block cuts: a feed, an arc or a thread pass (not a rapid or a dwell). */
    static boolean cuts(CheckedBlock b) {
        for (Motion m : b.motions()) {
            if (m.accept(CUTS)) {
                return true;
            }
        }
        return false;
    }

    /** Whether a motion cuts: a feed, an arc or a thread pass. */
    private static final Motion.Visitor<Boolean> CUTS = new Motion.Visitor<>() {
        @Override
        public Boolean linear(Motion.Linear l) {
            return !l.rapid();
        }

        @Override
        public Boolean arc(Motion.Arc a) {
            return true;
        }

        @Override
        public Boolean dwell(Motion.Dwell d) {
            return false;
        }

        @Override
        public Boolean thread(Motion.Thread t) {
            return true;
        }
    };
}
