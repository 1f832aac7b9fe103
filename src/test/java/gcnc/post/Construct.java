package gcnc.post;

import gcnc.post.PostStyleGenerator.Post;
import java.util.EnumSet;
import java.util.Set;

/**
 * What a {@link PostStyleGenerator} program may contain, each named after the post function or
 * property that writes it (docs/language.md, "How the posts write a program"); each is written
 * only where its post writes it ({@link #on}).
 */
enum Construct {
    /** haas onSection: a sequence number on every block (property showSequenceNumbers = true). */
    SEQUENCE_NUMBERS,
    /** A safe-start line after the units (G00 G18 G40 G80 with the feed mode), as shop templates add. */
    SAFE_START,
    /** haas onOpen/onClose: M31 chip conveyor on, M33 off (property gotChipConveyor). */
    CHIP_CONVEYOR,
    /** haas onSection: M22 tailstock retract at every tool call (property useTailStock). */
    TAILSTOCK_M22,
    /** onSection: M01 before every tool call but the first (property optionalStop). */
    OPTIONAL_STOP,
    /** writeRetract with safePositionMethod G28 ("G28 U0." then "G28 W0."): the fanuc post's default. */
    RETRACT_G28,
    /** writeRetract with safePositionStyle singleLineXZ: G28 U0. W0. in one block (fanuc B: G91 G28 X0. Z0., G90). */
    RETRACT_ONE_BLOCK,
    /** A rapid to a fixed tool-change position clear of the blank (G0 X.. Z..), as shop templates retract. */
    RETRACT_RAPID,
    /** M5 before the end (the posts leave it implied by M30; shops write it). */
    SPINDLE_STOP_M5,
    /** G00, G01, M03, M08 ... with a leading zero (shop style; the posts write G0, M3). */
    LEADING_ZEROS,
    /** haas onRapid: a move along both axes at once written as G1 at the high feed (axes not synchronized). */
    HIGH_FEED_G1,
    /** initializeActiveFeeds: feeds in #100+ (haas) or #500+ (fanuc) variables, F#nnn (property useParametricFeed). */
    PARAMETRIC_FEED,
    /** setWordSeparator(""): no spaces between words (property separateWordsWithSpace = false). */
    NO_SPACES,
    /** writeBlock under optionalSection: the blocks of an optional operation start with '/'. */
    OPTIONAL_SECTION,
    /** onDwell: G04 P in milliseconds at the bottom of a groove. */
    DWELL,
    /** Finishing with G70 P Q under G42, cancelled with G40 on the way out. */
    FINISH_G70,
    /** Finishing as the posts' onLinear/onCircular write a profile pass: G18, G1 G42 ... G3 R ... G40. */
    FINISH_MOVES,
    /** G75 grooving (haas one block X Z I K; fanuc two blocks G75 R / G75 X Z P Q). */
    GROOVE_G75,
    /** G74 peck drilling on the centreline (haas one block Z K; fanuc two blocks G74 R / G74 Z Q). */
    DRILL_G74,
    /** haas onCyclePoint deep-drilling: G83 X0. Z R Q F, G80. */
    DRILL_G83_HAAS,
    /** onCyclePoint thread-turning with useSimpleThread: G92 (fanuc B: G78), one block per pass. */
    THREAD_G92,
    /** onCyclePoint thread-turning: haas G76 X Z K D A P F in one block; fanuc G76 P Q R / G76 X Z P Q F. */
    THREAD_G76,
    /** onLinear under speed-feed synchronization: one G32 (fanuc B: G33) block per pass between rapids. */
    THREAD_G32,
    /** Haas M24 (thread pulled straight out, not chamfered) before a G76/G92 and M23 after it. */
    THREAD_M24,
    /** Part-off with the cut-off blade (haas T12) or grooving blade (fanuc T5). */
    PART_OFF,
    // --- constructs other helpers implement (issue 17): not written while they are in PENDING
    /** lex: corner chamfer and rounding in a G01 block (haas ",C" ",R"; fanuc "C" "R"). */
    CORNER_CHAMFER_RADIUS,
    /** lex: the DOS end-of-file byte (Ctrl-Z) after the closing '%' of a file sent from Windows. */
    DOS_EOF_BYTE,
    /** comp: G71 roughing started under G42 (the contour carries the compensation; note E622). */
    ROUGH_UNDER_G42,
    /** comp, drill: fanuc G83 face drilling, written by the fanuc post for deep-drilling (Q2.5; fanuc B: G90 G98, R the R point's Z). */
    DRILL_G83_FANUC,
    /** comp, drill: G84 face tapping (haas G84 X0. Z R P F; fanuc M29 S, note E720, then G84). */
    TAP_G84,
    // --- the thread words the posts write that lang2 (issue 17) made gcnc accept
    /** fanuc onCyclePoint: G76 P with the chamfer rr = 10 (one lead), which the post always writes. */
    FANUC_THREAD_CHAMFER,
    /** haas onCyclePoint: G76 A with a decimal point ("A60.", zFormat): 60 degrees. */
    THREAD_ANGLE_WITH_POINT,
    /** haas onCyclePoint: G76 P2, both flanks in turn (infeedMode "alternate"). */
    THREAD_ALTERNATE_FLANKS,
    /** Multi-start threads: G76/G92 Q start angle (haas; fanuc G92, fanuc B G78). */
    THREAD_START_ANGLE,
    // --- constructs the posts write that gcnc rejects today and no helper of issue 17 implements
    /** wcsDefinitions "Extended": haas G154 P1, fanuc G54.1 P1 (E110/E013 today). */
    WCS_EXTENDED;

    /** The constructs a program must also contain for this one to be written (the thread cycle it modifies). */
    Set<Construct> needs() {
        return switch (this) {
            case THREAD_START_ANGLE -> EnumSet.of(THREAD_G92);
            case FANUC_THREAD_CHAMFER, THREAD_ANGLE_WITH_POINT, THREAD_ALTERNATE_FLANKS -> EnumSet.of(THREAD_G76);
            default -> EnumSet.noneOf(Construct.class);
        };
    }

    boolean on(Post p) {
        return switch (this) {
            // the fanuc profile has a grooving blade, no cut-off blade: parting off a bar with it
            // puts its holder in the stock (E315)
            case CHIP_CONVEYOR, TAILSTOCK_M22, HIGH_FEED_G1, DRILL_G83_HAAS, THREAD_M24, PART_OFF,
                 THREAD_ANGLE_WITH_POINT, THREAD_ALTERNATE_FLANKS -> p.haas();
            case DRILL_G83_FANUC, FANUC_THREAD_CHAMFER -> !p.haas();
            // the fanuc post writes "G28 U0." in system B too, where U is no axis word: gcnc says
            // E023 (docs/language.md); system B programs here retract another way
            case RETRACT_G28 -> p != Post.FANUC_B;
            default -> true;
        };
    }
}
