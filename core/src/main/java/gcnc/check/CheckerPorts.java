package gcnc.check;

import gcnc.check.geom.Coordinates;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import java.util.List;
import java.util.Optional;

/**
 * The checker as its cycles ({@link CycleHost}) and its corner flow ({@link CornerHost}, a
 * {@link Lookahead}) see it: each call goes to the {@link Checker}, which alone commits a block's
 * state. The classes given these ports never name the checker.
 */
final class CheckerPorts implements CycleHost, CornerHost {
    private final Checker checker;

    CheckerPorts(Checker checker) {
        this.checker = checker;
    }

    @Override
    public ModalState state() {
        return checker.state();
    }

    @Override
    public Diagnostics out() {
        return checker.out();
    }

    @Override
    public MachineProfile profile() {
        return checker.profile();
    }

    @Override
    public Coordinates coordinates() {
        return checker.coordinates();
    }

    @Override
    public FunctionIndex functions() {
        return checker.functions();
    }

    @Override
    public Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin) {
        return checker.one(b, isFirst, origin);
    }

    @Override
    public Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread,
                                         PullOut pullOut) {
        return checker.thread(b, isFirst, origin, thread, pullOut, 0);
    }

    @Override
    public Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread,
                                         PullOut pullOut, double startAngle) {
        return checker.thread(b, isFirst, origin, thread, pullOut, startAngle);
    }

    @Override
    public Dry dry(RawBlock b, ModalState from, Diagnostics found) {
        return checker.dry(b, from, found, true);
    }

    @Override
    public Dry peek(RawBlock b, ModalState from, Diagnostics found) {
        return checker.dry(b, from, found, false);
    }

    @Override
    public List<CheckedBlock> flow(RawBlock b, boolean isFirst) {
        return checker.flow(b, isFirst);
    }

    @Override
    public List<CheckedBlock> flowOn(RawBlock b, boolean isFirst) {
        return checker.flowOn(b, isFirst);
    }

    @Override
    public List<RawBlock> cornersInContour(List<RawBlock> blocks, ModalState from) {
        return checker.cornersInContour(blocks, from);
    }

    @Override
    public ThreadChain threadChain() {
        return checker.threadChain();
    }

    @Override
    public void reportAside(Diagnostics found) {
        checker.reportAside(found);
    }

    @Override
    public boolean startsCycle(RawBlock b) {
        return checker.startsCycle(b);
    }

    @Override
    public ModalState fixed(RawBlock fixed) {
        return checker.fixed(fixed);
    }

    @Override
    public boolean cAxisOn() {
        return checker.cAxisOn();
    }

    @Override
    public void keepMotion(int motion) {
        checker.keepMotion(motion);
    }

    @Override
    public void takeFixed(ModalState fixed) {
        checker.takeFixed(fixed);
    }

    @Override
    public String readingContour() {
        return checker.readingContour();
    }
}
