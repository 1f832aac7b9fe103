package gcnc.check;

import gcnc.check.action.SyntaxAction;
import gcnc.check.action.SyntaxActions;
import gcnc.check.block.BlockCheck;
import gcnc.check.block.BlockChecks;
import gcnc.check.geom.Coordinates;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.util.BitSet;
import java.util.EnumMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * The checking stage: each block's words go through the thesis's syntax actions, then the
 * end-of-block operations in their fixed order, then motion building. The first error of a block
 * is reported and the block is dropped; the modal state changes only for a block without errors,
 * or one whose only errors are broken prerequisites ({@link #recover}); a block rejected for
 * anything else still keeps its unambiguous modal words ({@link Salvage}).
 *
 * <p>One root cause, one error: a prerequisite broken again by later blocks (a program that never
 * starts the spindle) is reported at its first block, with a note that counts the later ones.
 * <p>What the control runs but may not be meant (a cut with offset 00, a feed mode without F, G96
 * without S, C-axis codes) is judged after each accepted block by {@link Advisories} (issue 17).
 * <p>Block delete: once a '/' block appears, a second checker follows the program with the
 * switch in the other position, so both variants are checked; what only the other finds is
 * reported with a note saying so.
 */
public final class Checker {
    /** After this many errors the checker reports E116 once and stops (the run keeps no more: {@link Diagnostics}). */
    public static final int ERROR_CAP = Diagnostics.ERROR_CAP;
    /** Prerequisite errors that later blocks repeat until the program fixes the cause. */
    private static final Set<Code> ROOT_CAUSES = Set.of(Code.E037_SPINDLE_DIRECTION_BEFORE_CUT,
            Code.E038_CHUCK_OPEN_CUT, Code.E039_FEED_NOT_SET, Code.E041_G50_NOT_SET_BEFORE_CUT,
            Code.E050_S_BEFORE_G50, Code.E051_SPINDLE_DIRECTION, Code.E103_FEED_ABOVE_MAXIMUM,
            Code.E104_FEED_PER_REV_NO_SPEED);
    private static final int NOTE_LINES = 5;

    private final Tables tables;
    private final MachineProfile profile;
    private final Diagnostics out;
    private final FunctionIndex functions;
    private final SyntaxActions actions = new SyntaxActions();
    private final Coordinates coordinates;
    private final MotionBuilder motions;
    /** The draft of the block being checked, started afresh for each ({@link BlockDraft}). */
    private final BlockDraft draft;
    private final int errorCap;
    /** One block's findings before they are reported (reused: nothing allocated per block). */
    private final Diagnostics scratch = new Diagnostics();
    private final Map<Code, Cause> causes = new EnumMap<>(Code.class);
    /** M codes already warned about (E113), N numbers seen (E114, controls where N may repeat). */
    private final BitSet warnedM = new BitSet();
    private final BitSet seenN = new BitSet();
    /** The block delete switch as this checker follows the program: true = '/' blocks are skipped. */
    private final boolean skipDeleted;
    /** The other position of the switch, from the first '/' block on; null before (and in the other itself). */
    private Checker other;
    private final boolean isOther;
    private ModalState state;
    /** The cycles (G70-G73, G90/G94): the contour read ahead, the stored contours, the expansion. */
    private final CycleExpansion cycles;
    /** Findings of contour blocks read ahead, so that following them again (G70) does not repeat them. */
    private final Set<String> aside = new HashSet<>();
    private long blocks;
    private boolean stopped;
    /** Warning E053 given for the blocks after the end in force (once, not per block). */
    private boolean warnedAfterEnd;
    /** G41/G42: the compensated path, and what it needs to know of each block the flow made. */
    private NoseCompensation nose;
    /** What the control runs but may not be meant: offset 00 cuts, a feed mode without F, C-axis codes. */
    private Advisories advisories;
    /** Consecutive G32 blocks: one continuous thread (docs/threading.md). */
    private final ThreadChain threadChain;
    private final Map<CheckedBlock, NoseCompensation.Info> noseInfo = new java.util.IdentityHashMap<>();
    /** This checker to a class that only looks (made before {@link #corners}, which hands it on). */
    private final Lookahead lookahead = new Lookahead() {
        @Override
        public Dry peek(RawBlock b, ModalState from, Diagnostics found) {
            return Checker.this.peek(b, from, found);
        }

        @Override
        public boolean startsCycle(RawBlock b) {
            return Checker.this.startsCycle(b);
        }

        @Override
        public ModalState fixed(RawBlock fixed) {
            return Checker.this.fixed(fixed);
        }

        @Override
        public boolean cAxisOn() {
            return Checker.this.cAxisOn();
        }

        @Override
        public MachineProfile profile() {
            return profile;
        }

        @Override
        public Coordinates coordinates() {
            return coordinates;
        }
    };
    /** G01 chamfering and corner rounding: a corner block held until its next move (docs/chamfer.md). */
    private CornerInsertion corners = new CornerInsertion(this);

    /** A root cause already reported, and the later blocks that broke the same rule. */
    private static final class Cause {
        final Diagnostic first;
        int later;
        final StringBuilder lines = new StringBuilder();

        Cause(Diagnostic first) {
            this.first = first;
        }
    }

    public Checker(Tables tables, MachineProfile profile, Diagnostics out) {
        this(tables, profile, out, ERROR_CAP);
    }

    Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap) {
        this(tables, profile, out, errorCap, profile.control().blockDelete() == Control.BlockDelete.ON, false);
    }

    private Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap, boolean skipDeleted,
                    boolean isOther) {
        this.tables = tables;
        this.profile = profile;
        this.out = out;
        this.functions = new FunctionIndex(tables, profile.control());
        this.coordinates = new Coordinates(profile);
        this.motions = new MotionBuilder(profile, coordinates);
        this.draft = new BlockDraft(tables, functions, profile, coordinates);
        this.errorCap = errorCap;
        this.skipDeleted = skipDeleted;
        this.isOther = isOther;
        this.state = ModalState.initial(profile);
        this.cycles = new CycleExpansion(this);
        this.nose = new NoseCompensation(profile, out);
        this.advisories = new Advisories(functions);
        this.threadChain = new ThreadChain(out);
    }

    /** Where Threading marks its G32 passes for the continuous threads. */
    ThreadChain threadChain() {
        return threadChain;
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
        List<CheckedBlock> made = compensated(b, checkBlock(b));
        if (threadChain.idle()) {
            ThreadRunIn.check(made, profile, out);
            return made; // no G32 held or made: nothing to join
        }
        List<CheckedBlock> emit = new java.util.ArrayList<>(made.size() + 1);
        threadChain.accept(made, emit);
        if (state.ended()) {
            threadChain.end(emit);
        }
        ThreadRunIn.check(emit, profile, out); // a continuous G32 thread as one pass, once joined
        return emit;
    }

    /** The blocks through the nose radius compensation (G41/G42), which may hold some back. */
    private List<CheckedBlock> compensated(RawBlock b, List<CheckedBlock> made) {
        if (noseInfo.isEmpty() && !nose.active()) {
            return made; // no G41/G42 before or in these blocks: nothing to offset, nothing held
        }
        List<CheckedBlock> emit = new java.util.ArrayList<>(made.size() + 1);
        for (CheckedBlock c : made) {
            NoseCompensation.Info info = noseInfo.get(c);
            nose.accept(c, info != null ? info : new NoseCompensation.Info(NoseSide.OFF,
                    profile.nose(state.toolOffset()), state.toolOffset(), Span.of(c.line(), 1)), emit);
        }
        noseInfo.clear();
        if (state.ended()) {
            nose.end(b.words().isEmpty() ? b.last() : b.words().get(0).span(), emit);
        }
        return emit;
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
        if (b.blockDelete() > 0) {
            if (profile.control().blockDelete() == Control.BlockDelete.NONE) {
                blocks++;
                int at = b.deleteColumn() > 0 ? b.deleteColumn() : Math.max(1, first.column() - 1);
                out.error(Code.E010_SYNTAX, Span.of(b.line(), at), "'/'");
                return List.of();
            }
            if (other == null && !isOther) {
                other = fork();
            }
        }
        if (other != null) {
            other.check(b);
        }
        if (b.blockDelete() > 0 && skipDeleted) {
            // with the switch on a '/' block is skipped; a '/' in the middle runs the words before it
            RawBlock kept = b.deleteColumn() > 0 ? b.beforeDelete() : null;
            if (kept == null) {
                return List.of();
            }
            b = kept;
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
            return setOffset(b, g10, isFirst); // G10 L2: a work offset written by the program
        }
        Word g30 = ReferenceReturn.word(b, functions);
        if (g30 != null) {
            return returnToReference(b, g30, isFirst); // G30: to the profile's reference.N
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

    /**
     * G10 L2: the block of its other words checked and committed, then the offset it writes
     * ({@link OffsetSetting}).
     */
    private List<CheckedBlock> setOffset(RawBlock b, Word g, boolean isFirst) {
        CycleBlocks.Split split = OffsetSetting.read(b, g, out);
        List<CheckedBlock> done = new java.util.ArrayList<>(1);
        if (split.words() == null) {
            return done;
        }
        if (split.passOn() != null) {
            one(split.passOn(), isFirst, null).ifPresent(done::add);
        }
        OffsetSetting.offset(g, split.words(), state, profile, coordinates, out)
                .ifPresent(w -> coordinates.setWork(w.index(), w.at()));
        return done;
    }

    /** G30: the block of its other words, then the two rapids, each checked and committed ({@link ReferenceReturn}). */
    private List<CheckedBlock> returnToReference(RawBlock b, Word g, boolean isFirst) {
        CycleBlocks.Split split = ReferenceReturn.read(b, g, out);
        List<CheckedBlock> done = new java.util.ArrayList<>(3);
        if (split.passOn() != null) {
            one(split.passOn(), isFirst, null).ifPresent(done::add);
        }
        if (split.words() == null) {
            return done;
        }
        Optional<gcnc.ir.Point> ref = ReferenceReturn.reference(g, split.words(), profile, out);
        if (ref.isEmpty()) {
            return done;
        }
        ModalState start = state;
        gcnc.ir.Point via = CycleBlocks.target(this, b, split.words().axes(), start);
        if (via == null) {
            return done;
        }
        List<gcnc.check.cycle.Move> moves = ReferenceReturn.moves(split.words(), ref.get(), via);
        done.addAll(CycleBlocks.write(this, "G" + g.number(), b.line(), g.span(), moves, 1, start, -1, null));
        return done;
    }

    /**
     * One block through every check, committing its state: a block of the program, or one that a
     * cycle made or follows again ({@code origin} not null: its findings get a note saying which
     * pass, and its frame names the pass for the simulator's findings).
     */
    Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin) {
        return one(b, isFirst, origin, null, null);
    }

    /**
     * A thread pass written as a G01 block (its F the lead per revolution), checked like any cut
     * and built as a spindle-synchronised {@link gcnc.ir.Motion.Thread}; {@code thread} names the
     * function ("G32", "G76") for its findings; {@code pullOut}, when not null, ends it with Haas
     * M23's chamfer instead of at the block's end point.
     */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut) {
        return thread(b, isFirst, origin, thread, pullOut, 0);
    }

    /** As above, the pass starting {@code startAngle} degrees past the spindle's whole revolution (Q of G92, Haas G76). */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut,
                                  double startAngle) {
        return Optional.ofNullable(checked(b, isFirst, origin, thread, pullOut, startAngle));
    }

    private Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin, String thread,
                                       PullOut pullOut) {
        return Optional.ofNullable(checked(b, isFirst, origin, thread, pullOut, 0));
    }

    /** The block checked and committed as {@link #one} says, or null after its errors (no Optional per block). */
    private CheckedBlock checked(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut,
                                 double startAngle) {
        BlockDraft d = draft.start(b, state, isFirst);
        d.thread = thread;
        d.pullOut = pullOut;
        d.startAngle = startAngle;
        scratch.clear();
        CheckedBlock result = run(d, scratch, true);
        report(b, origin);
        boolean sequence = origin == null || !origin.again();
        if (result == null) {
            recover(b, isFirst, sequence);
            return null;
        }
        commit(d, sequence);
        advisories.accepted(d, result, out);
        if (!causes.isEmpty() && cuts(result)) {
            closeCauses();
        }
        if (out.place() != gcnc.diag.Origin.PROGRAM) {
            result = result.from(out.place()); // a called program's block: the simulator places its findings there
        }
        CheckedBlock made = origin == null ? result : origin.label(result);
        if (state.nose() != NoseSide.OFF || d.prior.nose() != NoseSide.OFF) {
            // a block without this record has G40 in force before and after it (most blocks: nothing allocated)
            noseInfo.put(made, new NoseCompensation.Info(state.nose(), profile.nose(state.toolOffset()),
                    state.toolOffset(), b.words().isEmpty() ? b.last() : b.words().get(0).span(),
                    NoseConflict.suspend(b, functions, d.prior.nose(),
                            origin == null ? null : origin.cycle(), thread != null)));
        }
        return made;
    }

    /** What a block would do from {@code from}, checked but not committed, or null after its errors. */
    record Dry(CheckedBlock block, ModalState next) {
    }

    /**
     * A contour block followed from {@code from} without changing the program's state: its words
     * and geometry checked (not the prerequisites: the cycle's own moves are checked for those),
     * findings to {@code found}.
     */
    Dry dry(RawBlock b, ModalState from, Diagnostics found) {
        return dry(b, from, found, true);
    }

    /**
     * A look-ahead that the block's real run follows ({@link CornerInsertion}): its N is noted
     * then, not here, or every held block would report its own N again (E114).
     */
    Dry peek(RawBlock b, ModalState from, Diagnostics found) {
        return dry(b, from, found, false);
    }

    private Dry dry(RawBlock b, ModalState from, Diagnostics found, boolean sequence) {
        BlockDraft d = draft.start(b, from, false);
        CheckedBlock r = run(d, found, false);
        if (r == null) {
            return null;
        }
        if (sequence) {
            noteSequence(d);
        }
        return new Dry(r, d.next.build());
    }

    /** A cycle's contour with its chamfers and corners made, followed from {@code from} ({@link CornerInsertion#inContour}). */
    List<RawBlock> cornersInContour(List<RawBlock> blocks, ModalState from) {
        return corners.inContour(blocks, from);
    }

    /** Reports findings of a block checked outside the flow (a contour read ahead), remembering them. */
    void reportAside(Diagnostics found) {
        for (Diagnostic diag : found.sorted()) {
            if (aside.add(key(diag))) {
                out.report(diag);
            }
        }
    }

    Diagnostics out() {
        return out;
    }

    /**
     * A block refused for one word that is not part of its move (the thesis's R on a G01): when
     * the block without it ({@code fixed}) is sound, the state it would leave, as if the
     * programmer had fixed what was reported; null when {@code fixed} has errors of its own.
     * Nothing is committed: {@link #takeFixed} takes it.
     */
    ModalState fixed(RawBlock fixed) {
        BlockDraft d = draft.start(fixed, state, false);
        Diagnostics none = new Diagnostics();
        if (!words(d, none, false) || motions.build(d, none) == null) {
            return null;
        }
        // as a block whose move failed (recover): its motion G and its end point, nothing else of it
        return Salvage.moved(fixed, state, d, functions, profile);
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

    /**
     * Puts the motion G back after an inserted corner arc: the program's G01 stays in force (the
     * arc is the control's, not a G02/G03 of the program).
     */
    void keepMotion(int motion) {
        ModalState.Next n = state.next();
        n.motion = motion;
        state = n.build();
    }

    /** Whether the block starts or runs again a cycle (not a plain move). */
    boolean startsCycle(RawBlock b) {
        return cycles.cycleWord(b) != null || cycles.repeats(b);
    }

    /** This checker seen by a class that only looks ({@link ContourCorners}): peeks and questions, no commit. */
    Lookahead lookahead() {
        return lookahead;
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
    private Checker fork() {
        Checker c = new Checker(tables, profile, out.sibling(), errorCap, !skipDeleted, true);
        c.state = state;
        c.nose = nose.copy(c.out);
        c.advisories = advisories.copy();
        c.corners = corners.copy(c);
        c.coordinates.takeWork(coordinates); // work offsets written by G10 so far
        c.blocks = blocks;
        c.seenN.or(seenN);
        c.warnedM.or(warnedM);
        return c;
    }

    /**
     * Reports the block's findings, folding a repeated root cause into its first report; a block
     * of a cycle adds a note naming its pass, and a contour block followed again (G70) does not
     * repeat what reading it ahead already reported.
     */
    private void report(RawBlock b, CycleOrigin origin) {
        if (scratch.size() == 0) {
            return;
        }
        for (Diagnostic diag : scratch.sorted()) {
            if (origin != null && origin.again() && aside.contains(key(diag))) {
                continue;
            }
            Cause c = causes.get(diag.code());
            if (c != null && diag.severity() == Severity.ERROR) {
                c.later++;
                if (c.later <= NOTE_LINES) {
                    c.lines.append(c.lines.length() == 0 ? "" : ", ").append(b.line());
                } else if (c.later == NOTE_LINES + 1) {
                    c.lines.append(", ...");
                }
                continue;
            }
            if (ROOT_CAUSES.contains(diag.code())) {
                causes.put(diag.code(), new Cause(diag));
            }
            out.report(diag);
            if (origin != null && origin.noted() && diag.severity() != Severity.NOTE) {
                out.report(origin.note(diag.span()));
            }
        }
    }

    /** Whether the block cuts: a feed, an arc or a thread pass (not a rapid or a dwell). */
    static boolean cuts(CheckedBlock b) {
        for (gcnc.ir.Motion m : b.motions()) {
            if (m.accept(CUTS)) {
                return true;
            }
        }
        return false;
    }

    /** Whether a motion cuts: a feed, an arc or a thread pass. */
    private static final gcnc.ir.Motion.Visitor<Boolean> CUTS = new gcnc.ir.Motion.Visitor<>() {
        @Override
        public Boolean linear(gcnc.ir.Motion.Linear l) {
            return !l.rapid();
        }

        @Override
        public Boolean arc(gcnc.ir.Motion.Arc a) {
            return true;
        }

        @Override
        public Boolean dwell(gcnc.ir.Motion.Dwell d) {
            return false;
        }

        @Override
        public Boolean thread(gcnc.ir.Motion.Thread t) {
            return true;
        }
    };

    /** A clean cut: every prerequisite holds again, so a later break is a new cause. */
    private void closeCauses() {
        if (causes.isEmpty()) {
            return;
        }
        for (Cause c : causes.values()) {
            note(c);
        }
        causes.clear();
    }

    private void note(Cause c) {
        if (c.later > 0) {
            out.report(new Diagnostic(Code.E115_SAME_CAUSE, Severity.NOTE, c.first.span(),
                    List.of(Integer.toString(c.later), c.lines.toString()), c.first.origin().withoutCalls()));
        }
    }

    /**
     * Takes the block's next state, with its warnings: M codes without output (E113), a repeated N
     * (E114; not for a contour block followed again by G70: {@code sequence} false).
     */
    private void commit(BlockDraft d, boolean sequence) {
        java.util.List<Word> ws = d.unpowered();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            int m = (int) w.code();
            if (!warnedM.get(m)) {
                warnedM.set(m);
                out.report(Diagnostic.warning(Code.E113_M_WITHOUT_OUTPUT, w.span(), m, profile.name()));
            }
        }
        if (sequence) {
            noteSequence(d);
        }
        state = d.next.build();
    }

    /** A repeated N (E114) where N may repeat; remembers the block's N. */
    private void noteSequence(BlockDraft d) {
        if (d.has(gcnc.ir.Letter.N) && !profile.control().increasingN() && d.block.depth() == 0) {
            long n = (long) d.value(gcnc.ir.Letter.N);
            if (n >= 0 && n < Integer.MAX_VALUE) {
                if (seenN.get((int) n)) {
                    Word w = d.word(gcnc.ir.Letter.N);
                    out.report(Diagnostic.warning(Code.E114_DUPLICATE_SEQUENCE_NUMBER, w.span(), w.number()));
                }
                seenN.set((int) n);
            }
        }
    }

    /**
     * After an error: if the block is clean but for prerequisite rules (an F, M11, M03 or G50 S
     * missing before a cut, an S above the clamp), take the state it would have left, as if the
     * programmer had fixed what was reported. Otherwise its F, G01, S or M03 would be lost and
     * every later block would report an echo of this one instead of its own errors. The re-run
     * reports nothing. A block with any other error keeps only its unambiguous modal words.
     */
    private void recover(RawBlock b, boolean isFirst, boolean sequence) {
        BlockDraft d = draft.start(b, state, isFirst);
        Diagnostics none = new Diagnostics();
        if (!words(d, none, false)) {
            state = Salvage.keep(b, state, functions, profile);
        } else if (motions.build(d, none) != null) {
            commit(d, sequence);
        } else {
            // only the move failed (travel, arc geometry): the words were sound, so the control, once
            // the operator fixed the end point, leaves the block's motion G in force and the tool there
            state = Salvage.moved(b, state, d, functions, profile);
        }
    }

    private CheckedBlock run(BlockDraft d, Diagnostics out, boolean prerequisites) {
        return words(d, out, prerequisites) ? motions.build(d, out) : null;
    }

    /** The syntax actions and the end-of-block checks; false after an error. */
    private boolean words(BlockDraft d, Diagnostics out, boolean prerequisites) {
        Word unsupported = d.unsupported;
        if (unsupported != null) {
            actions.action(17).apply(unsupported, d, out);
            return false;
        }
        List<Word> words = d.block.words();
        for (int i = 0; i < words.size() && !d.failed(); i++) {
            Word w = words.get(i);
            SyntaxAction a = actions.lookUp(w, d, out);
            if (a != null) {
                a.apply(w, d, out);
            }
        }
        for (int i = 0; i < BlockChecks.ORDER.size() && !d.failed(); i++) {
            BlockCheck c = BlockChecks.ORDER.get(i);
            if (prerequisites || !c.prerequisite()) {
                c.run(d, out);
            }
        }
        return !d.failed();
    }

    /** End of the program: it must have ended (52: M30, or what the control's table says ends one). */
    public void finish(int lastLine) {
        corners.finish(lastLine);
        cycles.finish();
        if (nose.active()) {
            nose.end(Span.of(Math.max(1, lastLine), 1), new java.util.ArrayList<>()); // nothing can be sent after the end
        }
        for (Cause c : causes.values()) {
            note(c);
        }
        causes.clear();
        if (!stopped && !state.ended()) {
            out.error(Code.E052_NO_M30, Span.of(Math.max(1, lastLine), 1), profile.control().endCodes());
        }
        if (other != null) {
            other.finish(lastLine);
            merge(other.out, !skipDeleted);
        }
    }

    /** Adds what only the other position of the block delete switch found, each with a note saying so. */
    private void merge(Diagnostics found, boolean switchOn) {
        Set<String> mine = new HashSet<>();
        for (Diagnostic d : out.sorted()) {
            mine.add(key(d));
        }
        for (Diagnostic d : found.sorted()) {
            if (mine.add(key(d))) {
                out.report(d);
                if (d.severity() != Severity.NOTE) {
                    out.report(new Diagnostic(Code.E118_BLOCK_DELETE_VARIANT, Severity.NOTE, d.span(),
                            List.of(switchOn ? "on" : "off"), d.origin().withoutCalls()));
                }
            }
        }
    }

    private static String key(Diagnostic d) {
        return d.code() + "@" + d.origin().file() + ":" + d.span() + d.args();
    }
}
