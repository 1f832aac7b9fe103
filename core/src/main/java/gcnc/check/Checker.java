package gcnc.check;

import gcnc.check.geom.Coordinates;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.util.List;
import java.util.Optional;

/**
 * The checking stage: each block's words go through the thesis's syntax actions, then the
 * end-of-block operations in their fixed order, then motion building. The first error of a block
 * is reported and the block is dropped; the modal state changes only for a block without errors,
 * or one whose only errors are broken prerequisites ({@link #recover}); a block rejected for
 * anything else still keeps its unambiguous modal words ({@link Salvage}).
 *
 * <p>One root cause, one error: a prerequisite broken again by later blocks (a program that never
 * starts the spindle) is reported at its first block, with a note that counts the later ones
 * ({@link FindingReport}).
 * <p>What the control runs but may not be meant (a cut with offset 00, a feed mode without F, G96
 * without S, C-axis codes) is judged after each accepted block by {@link Advisories} (issue 17).
 * <p>Block delete: once a '/' block appears, a second checker follows the program with the
 * switch in the other position, so both variants are checked; what only the other finds is
 * reported with a note saying so ({@link DeleteSwitch}).
 * <p>The cycles and the corner flow reach the checker only through {@link CheckerPorts}
 * ({@link CycleHost}, {@link CornerHost}); the blocks leave it through {@link BlockRelease}.
 */
public final class Checker {
    /** After this many errors the checker reports E116 once and stops (the run keeps no more: {@link Diagnostics}). */
    public static final int ERROR_CAP = Diagnostics.ERROR_CAP;

    private final Tables tables;
    private final MachineProfile profile;
    private final Diagnostics out;
    private final FunctionIndex functions;
    private final Coordinates coordinates;
    /** A block's words, checks and motion, into the one {@link BlockDraft} ({@link BlockRun}). */
    private final BlockRun run;
    private final int errorCap;
    /** One block's findings before they are reported (reused: nothing allocated per block). */
    private final Diagnostics scratch = new Diagnostics();
    private final FindingReport findings;
    private final RepeatWarnings repeats;
    /** The block delete switch as this checker follows it, and the checker in its other position. */
    private final DeleteSwitch deletes;
    /** Where the block being checked comes from ({@link RawBlock#origin}): its checked blocks go there. */
    private gcnc.diag.Origin from = gcnc.diag.Origin.PROGRAM;
    private ModalState state;
    /** The cycles (G70-G73, G90/G94): the contour read ahead, the stored contours, the expansion. */
    private final CycleExpansion cycles;
    private long blocks;
    private boolean stopped;
    /** Warning E053 given for the blocks after the end in force (once, not per block). */
    private boolean warnedAfterEnd;
    /** What the control runs but may not be meant: offset 00 cuts, a feed mode without F, C-axis codes. */
    private Advisories advisories;
    /** G41/G42 and continuous G32 threads: how the checked blocks leave the checker. */
    private BlockRelease release;
    /** What a block would do and a cycle's blocks: the cycles and the corner flow call back through these. */
    private final CheckerPorts ports = new CheckerPorts(this);
    private final OffsetAndReturn offsets;
    /** G01 chamfering and corner rounding: a corner block held until its next move (docs/chamfer.md). */
    private CornerInsertion corners = new CornerInsertion(ports);

    public Checker(Tables tables, MachineProfile profile, Diagnostics out) {
        this(tables, profile, out, ERROR_CAP);
    }

    Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap) {
        this(tables, profile, out, errorCap, new DeleteSwitch(profile.control()));
    }

    private Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap, DeleteSwitch deletes) {
        this.tables = tables;
        this.profile = profile;
        this.out = out;
        this.functions = new FunctionIndex(tables, profile.control());
        this.coordinates = new Coordinates(profile);
        this.run = new BlockRun(tables, functions, profile, coordinates);
        this.errorCap = errorCap;
        this.deletes = deletes;
        this.state = ModalState.initial(profile);
        this.cycles = new CycleExpansion(ports);
        this.offsets = new OffsetAndReturn(ports);
        this.findings = new FindingReport(out);
        this.repeats = new RepeatWarnings(profile, out);
        this.release = new BlockRelease(profile, functions, out);
        this.advisories = new Advisories(functions);
    }

    /** Where Threading marks its G32 passes for the continuous threads. */
    ThreadChain threadChain() {
        return release.threadChain();
    }

    /** The modal state after the last accepted block. */
    public ModalState state() {
        return state;
    }

    /**
     * Checks the next block as the program gives it. Usually one checked block or none; none while
     * a G71/G72/G73's contour is being read ahead, and the whole expanded cycle at its last block;
     * a G90/G94 block gives its moves.
     */
    public List<CheckedBlock> check(RawBlock b) {
        from = b.origin();
        List<CheckedBlock> made = checkBlock(b); // first: the state after it is the one released with
        return release.release(b, made, state);
    }

    private List<CheckedBlock> checkBlock(RawBlock b) {
        if (stopped) {
            return List.of();
        }
        Span first = b.words().isEmpty() ? b.last() : b.words().get(0).span();
        if (out.errorCount() >= errorCap) {
            out.error(Code.E116_ERROR_CAP, first, out.errorCount());
            stopped = true;
            return List.of();
        }
        if (deletes.refused(b, first, out)) {
            blocks++;
            return List.of();
        }
        deletes.follow(b, this);
        b = deletes.running(b);
        if (b == null) {
            return List.of();
        }
        boolean isFirst = blocks++ == 0;
        if (state.ended()) {
            // the control never runs a block after M30/M02 (issue 31: a warning, where the thesis
            // made it an error; docs/thesis.md), once for the blocks after an end, none of them
            // checked as running
            if (!warnedAfterEnd) {
                out.report(Diagnostic.warning(Code.E053_M30_NOT_LAST, first));
                warnedAfterEnd = true;
            }
            return List.of();
        }
        warnedAfterEnd = false;
        return flow(b, isFirst);
    }

    /** A counted block in the program's flow: a corner block held, part of a contour being read, a cycle, or a block. */
    List<CheckedBlock> flow(RawBlock b, boolean isFirst) {
        return corners.flow(b, isFirst);
    }

    /** A block with its chamfer or corner words taken out ({@link CornerInsertion}). */
    List<CheckedBlock> flowOn(RawBlock b, boolean isFirst) {
        if (cycles.reading()) {
            return cycles.read(b);
        }
        if (b.macro() != null) {
            // a macro statement is run by gcnc.flow; one reaching the checker was not followed
            out.error(Code.E111_MACRO_NOT_SUPPORTED_YET, b.last(), b.macro().strip());
            return List.of();
        }
        if (b.malformed() || advisories.cAxis(b, out)) {
            state = Salvage.keep(b, state, functions, profile);
            return List.of();
        }
        // the compensation in force, or the one the block turns on ("G42"); null when neither
        boolean inForce = state.nose() != NoseSide.OFF;
        String compensation = inForce ? state.nose().g() : NoseConflict.turningOn(b, functions);
        if (compensation != null && !NoseConflict.judge(b, functions, inForce, compensation, out)) {
            return List.of(); // E178: the control alarms
        }
        Word g10 = OffsetSetting.word(b, functions);
        if (g10 != null) {
            return offsets.setOffset(b, g10, isFirst); // G10 L2: a work offset written by the program
        }
        Word g30 = ReferenceReturn.word(b, functions);
        if (g30 != null) {
            return offsets.returnToReference(b, g30, isFirst); // G30: to the profile's reference.N
        }
        Word cycle = cycles.cycleWord(b);
        if (cycle != null) {
            return cycles.start(b, cycle, isFirst);
        }
        if (cycles.repeats(b)) {
            if (compensation != null) {
                // a modal cycle (G90/G94, G92, G32, G81-G83) runs again, with the compensation suspended
                NoseConflict.again(b, cycles.repeating(b), functions, inForce, compensation, out);
            }
            return cycles.repeat(b, isFirst);
        }
        cycles.note(b);
        CheckedBlock made = checked(b, isFirst, null, null, null, 0);
        return made == null ? List.of() : List.of(made);
    }

    /** One block through every check, committing its state ({@link CycleHost#one}: a cycle's origin, or null). */
    Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin) {
        return Optional.ofNullable(checked(b, isFirst, origin, null, null, 0));
    }

    /**
     * A thread pass written as a G01 block, checked like any cut and built as a spindle-synchronised
     * motion, starting {@code startAngle} degrees past the spindle's whole revolution ({@link CycleHost#thread}).
     */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut,
                                  double startAngle) {
        return Optional.ofNullable(checked(b, isFirst, origin, thread, pullOut, startAngle));
    }

    /** The block checked and committed as {@link #one} says, or null after its errors (no Optional per block). */
    private CheckedBlock checked(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut,
                                 double startAngle) {
        BlockDraft d = run.start(b, state, isFirst);
        d.thread = thread;
        d.pullOut = pullOut;
        d.startAngle = startAngle;
        scratch.clear();
        CheckedBlock result = run.run(d, scratch, true);
        findings.block(scratch, b, origin);
        boolean sequence = origin == null || !origin.again();
        if (result == null) {
            recover(b, isFirst, sequence);
            return null;
        }
        commit(d, sequence);
        advisories.accepted(d, result, out);
        if (findings.open() && MotionKind.cuts(result)) {
            findings.closeCauses();
        }
        if (from != gcnc.diag.Origin.PROGRAM) {
            result = result.from(from); // a called program's block: the simulator places its findings there
        }
        CheckedBlock made = origin == null ? result : origin.label(result);
        release.made(made, b, d.prior, state, origin, thread != null);
        return made;
    }

    /**
     * What a block would do from {@code from}, checked but not committed, or null after its errors
     * ({@link CycleHost#dry}); {@code sequence} false for a look-ahead that the block's real run
     * follows ({@link CornerInsertion}): its N is noted then, not here, or every held block would
     * report its own N again (E114).
     */
    Dry dry(RawBlock b, ModalState from, Diagnostics found, boolean sequence) {
        BlockDraft d = run.start(b, from, false);
        CheckedBlock r = run.run(d, found, false);
        if (r == null) {
            return null;
        }
        if (sequence) {
            repeats.sequence(d);
        }
        return new Dry(r, d.next.build());
    }

    /** A cycle's contour with its chamfers and corners made, followed from {@code from} ({@link CornerInsertion#inContour}). */
    List<RawBlock> cornersInContour(List<RawBlock> blocks, ModalState from) {
        return corners.inContour(blocks, from);
    }

    /** Reports findings of a block checked outside the flow (a contour read ahead), remembering them. */
    void reportAside(Diagnostics found) {
        findings.aside(found);
    }

    Diagnostics out() {
        return out;
    }

    /**
     * A block refused for one word that is not part of its move (the thesis's R on a G01): when
     * the block without it ({@code fixed}) is sound, the state it would leave, as if the
     * programmer had fixed what was reported; null when {@code fixed} has errors of its own
     * ({@link BlockRun#fixed}). Nothing is committed: {@link #takeFixed} takes it.
     */
    ModalState fixed(RawBlock fixed) {
        return run.fixed(fixed, state);
    }

    /** Takes the state {@link #fixed} gave for a refused block (the caller reported the error; the block is not run). */
    void takeFixed(ModalState fixed) {
        state = fixed;
    }

    /** Whether the C axis is engaged (after a C-axis option code): C is then an axis word, not a chamfer. */
    boolean cAxisOn() {
        return advisories.cAxisOn();
    }

    /** The cycle whose contour is being read ("G71"), or null. */
    String readingContour() {
        return cycles.reading() ? cycles.readingName() : null;
    }

    /** Puts the motion G back after an inserted corner arc ({@link CornerHost#keepMotion}). */
    void keepMotion(int motion) {
        ModalState.Next n = state.next();
        n.motion = motion;
        state = n.build();
    }

    /** Whether the block starts or runs again a cycle (not a plain move). */
    boolean startsCycle(RawBlock b) {
        return cycles.cycleWord(b) != null || cycles.repeats(b);
    }

    FunctionIndex functions() {
        return functions;
    }

    MachineProfile profile() {
        return profile;
    }

    Coordinates coordinates() {
        return coordinates;
    }

    /** The checker for the other position of the block delete switch, from the state reached so far. */
    Checker fork() {
        Checker c = new Checker(tables, profile, out.sibling(), errorCap, deletes.otherPosition());
        c.state = state;
        c.release = release.copy(c.functions, c.out);
        c.advisories = advisories.copy();
        c.corners = corners.copy(c.ports);
        c.coordinates.takeWork(coordinates); // work offsets written by G10 so far
        c.blocks = blocks;
        c.repeats.takeFrom(repeats);
        return c;
    }

    /**
     * Takes the block's next state, with its warnings: M codes without output (E113), a repeated N
     * (E114; not for a contour block followed again by G70: {@code sequence} false).
     */
    private void commit(BlockDraft d, boolean sequence) {
        repeats.unpowered(d);
        if (sequence) {
            repeats.sequence(d);
        }
        state = d.next.build();
    }

    /**
     * After an error: if the block is clean but for prerequisite rules (an F, M11, M03 or G50 S
     * missing before a cut, an S above the clamp), take the state it would have left, as if the
     * programmer had fixed what was reported. Otherwise its F, G01, S or M03 would be lost and
     * every later block would report an echo of this one instead of its own errors. The re-run
     * reports nothing. A block with any other error keeps only its unambiguous modal words.
     */
    private void recover(RawBlock b, boolean isFirst, boolean sequence) {
        BlockDraft d = run.start(b, state, isFirst);
        Diagnostics none = new Diagnostics();
        if (!run.words(d, none, false)) {
            state = Salvage.keep(b, state, functions, profile);
        } else if (run.motion(d, none) != null) {
            commit(d, sequence);
        } else {
            // only the move failed (travel, arc geometry): the words were sound, so the control, once
            // the operator fixed the end point, leaves the block's motion G in force and the tool there
            state = Salvage.moved(b, state, d, functions, profile);
        }
    }

    /** End of the program: it must have ended (52: M30, or what the control's table says ends one). */
    public void finish(int lastLine) {
        from = gcnc.diag.Origin.PROGRAM; // past the last block
        corners.finish(lastLine);
        cycles.finish();
        release.finish(lastLine);
        findings.closeCauses();
        if (!stopped && !state.ended()) {
            out.error(Code.E052_NO_M30, Span.of(Math.max(1, lastLine), 1), profile.control().endCodes());
        }
        deletes.finish(lastLine, findings);
    }
}
