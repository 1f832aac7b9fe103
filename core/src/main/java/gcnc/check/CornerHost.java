package gcnc.check;

import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import java.util.List;

/**
 * What the corner flow ({@link CornerInsertion}) may have the checker do: besides looking
 * ({@link Lookahead}), run a block with its chamfer or corner words taken out, put the G01 back
 * after an inserted arc, and take the state a refused block leaves. Each is one commit by the
 * checker; the corner flow holds no state of the program's.
 */
interface CornerHost extends Lookahead {
    /** The modal state after the last accepted block. */
    ModalState state();

    /** Where the program's findings go. */
    Diagnostics out();

    FunctionIndex functions();

    /** A block with its chamfer or corner words taken out, through the rest of the flow (cycles, G10, G30, a block). */
    List<CheckedBlock> flowOn(RawBlock b, boolean isFirst);

    /**
     * Puts the motion G back after an inserted corner arc: the program's G01 stays in force (the
     * arc is the control's, not a G02/G03 of the program).
     */
    void keepMotion(int motion);

    /** Takes the state {@link #fixed} gave for a refused block (the caller reported the error; the block is not run). */
    void takeFixed(ModalState fixed);

    /** The cycle whose contour is being read ("G71"), or null. */
    String readingContour();
}
