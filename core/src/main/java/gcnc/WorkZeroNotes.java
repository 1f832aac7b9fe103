package gcnc;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import gcnc.machine.MachineModel;
import gcnc.machine.MachineProfile;
import gcnc.sim.StockSize;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;

/**
 * What a run says about its work zero when it was not simply the profile's: E662 when the blank
 * given for the run moved the offsets a shop sets on the blank's face ({@code work.G54 = 0, face}),
 * E663 when the run's blank has its face elsewhere than a G54 the profile pins (the program's Z0 is
 * then not the face). Both at line 1, as E316 is: they are about the whole run.
 */
final class WorkZeroNotes {
    private WorkZeroNotes() {
    }

    static void report(MachineProfile p, Optional<StockSize> blank, Diagnostics diags) {
        MachineModel m = p.model();
        MachineModel.WorkZero w = m.workZero();
        if (w.given() && !w.atFace().isEmpty()) {
            double face = m.chuck().orElseThrow().faceZ();
            String offsets = w.atFace().stream().sorted().map(g -> "G" + g).collect(Collectors.joining(", "));
            double profileStickout = m.stock().map(MachineModel.Blank::stickout).orElse(w.stickout());
            diags.report(new Diagnostic(Code.E662_WORK_ZERO_FROM_BLANK, Severity.NOTE, Span.of(1, 1),
                    List.of(offsets, mm(face + w.stickout()), mm(face), mm(w.stickout()),
                            mm(face + profileStickout))));
        }
        if (blank.isPresent() && m.chuck().isPresent() && !w.atFace().contains(54) && m.stock().isPresent()
                && blank.get().stickout() != m.stock().get().stickout()) {
            double face = m.chuck().get().faceZ() + blank.get().stickout();
            double g54 = p.workOffset(54).map(pt -> pt.z() / p.z().countsPerMm()).orElse(0.0);
            if (Math.abs(face - g54) > 0.01) {
                diags.report(Diagnostic.warning(Code.E663_WORK_ZERO_PINNED, Span.of(1, 1), mm(face), mm(g54)));
            }
        }
    }

    private static String mm(double v) {
        return gcnc.machine.ProfileFile.written(v);
    }
}
