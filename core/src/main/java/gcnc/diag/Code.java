package gcnc.diag;

/**
 * Every diagnostic gcnc can report, with a stable number that is never reused.
 * 1-54 are the thesis's Table 5; gcnc's own codes start at 100:
 * 100-199 checker (G-code semantics), 200-299 Galil backend (but 240-249: checker again, the
 * chamfered thread pull-out, since the threads' E190-E199 are full), 300-399 simulator,
 * 400-499 tables and machine profiles, 500-599 command line and files. Issue 17's language work
 * has 600-619 (the parser's leniency, G01 chamfers and corners), 620-639 (blocks under nose
 * compensation, G32 sequences, hole cycles, G10, G30), 640-659 (what the control runs though the
 * result may not be what was meant) and 700-729 (threads and codes the CAM posts write);
 * 680-699 are program flow and macros again (the flow's E130-E159 are full) and the run's caps.
 * Message texts live in tables/errors.csv; {@code CodeTableTest} keeps the two in step.
 */
public enum Code {
    /** Table 5, error 1. */
    E001_G_NUMBER_EXPECTED,
    /** Table 5, error 2. */
    E002_M_NUMBER_EXPECTED,
    /** Table 5, error 3. */
    E003_ILLEGAL_CHARACTER,
    /** Table 5, error 4. */
    E004_UNDEFINED_FUNCTION,
    /** Table 5, error 5. */
    E005_COMMENT_NOT_CLOSED,
    /** Table 5, error 6. */
    E006_NUMBER_EXPECTED,
    /** Table 5, error 7. */
    E007_DUPLICATE_PARAMETER,
    /** Table 5, error 8. */
    E008_PARAMETER_TOO_SMALL,
    /** Table 5, error 9. */
    E009_PARAMETER_TOO_LARGE,
    /** Table 5, error 10. */
    E010_SYNTAX,
    /** Table 5, error 11. */
    E011_UNDEFINED_G,
    /** Table 5, error 12. */
    E012_UNDEFINED_M,
    /** Table 5, error 13. */
    E013_INTEGER_EXPECTED,
    /** Table 5, error 14. */
    E014_DECIMAL_EXPECTED,
    /** Table 5, error 15. */
    E015_OUT_OF_RANGE,
    /** Table 5, error 16. */
    E016_GROUP_CONFLICT,
    /** Table 5, error 17. */
    E017_G04_WITH_OTHER,
    /** Table 5, error 18. */
    E018_G28_WITH_OTHER,
    /** Table 5, error 19. */
    E019_G29_WITH_OTHER,
    /** Table 5, error 20. */
    E020_G50_G92_WITH_OTHER,
    /** Table 5, error 21. */
    E021_X_NOT_ALLOWED,
    /** Table 5, error 22. */
    E022_Z_NOT_ALLOWED,
    /** Table 5, error 23. */
    E023_U_NOT_ALLOWED,
    /** Table 5, error 24. */
    E024_W_NOT_ALLOWED,
    /** Table 5, error 25. */
    E025_R_NOT_ALLOWED,
    /** Table 5, error 26. */
    E026_I_NOT_ALLOWED,
    /** Table 5, error 27. */
    E027_K_NOT_ALLOWED,
    /** Table 5, error 28. */
    E028_X_AND_U,
    /** Table 5, error 29. */
    E029_Z_AND_W,
    /** Table 5, error 30. */
    E030_PARAMETER_EXPECTED,
    /** Table 5, error 31. */
    E031_S_EXPECTED,
    /** Table 5, error 32. */
    E032_UNASSOCIATED_PARAMETER,
    /** Table 5, error 33. */
    E033_PROGRAM_NAME_TWICE,
    /** Table 5, error 34. */
    E034_PROGRAM_NAME_LATE,
    /** Table 5, error 35. */
    E035_TWO_G_WITH_PARAMETERS,
    /** Table 5, error 36. */
    E036_P_NOT_ALLOWED,
    /** Table 5, error 37. */
    E037_SPINDLE_DIRECTION_BEFORE_CUT,
    /** Table 5, error 38. */
    E038_CHUCK_OPEN_CUT,
    /** Table 5, error 39. */
    E039_FEED_NOT_SET,
    /** Table 5, error 40. */
    E040_SPINDLE_RUNNING_CHUCK_OPEN,
    /** Table 5, error 41. */
    E041_G50_NOT_SET_BEFORE_CUT,
    /** Table 5, error 42. */
    E042_G29_WITHOUT_G28,
    /** Table 5, error 43. */
    E043_LINE_NUMBER_ORDER,
    /** Table 5, error 44. */
    E044_NO_MOTION_G,
    /** Table 5, error 45. */
    E045_OUT_OF_MEMORY,
    /** Table 5, error 46. */
    E046_UNDEFINED_TOOL,
    /** Table 5, error 47. */
    E047_TOOL_OFFSET_RANGE,
    /** Table 5, error 48. */
    E048_S_ABOVE_G50,
    /** Table 5, error 49. */
    E049_NO_ARC_RADIUS,
    /** Table 5, error 50. */
    E050_S_BEFORE_G50,
    /** Table 5, error 51. */
    E051_SPINDLE_DIRECTION,
    /** Table 5, error 52. */
    E052_NO_M30,
    /** Table 5, error 53. */
    E053_M30_NOT_LAST,
    /** Table 5, error 54. */
    E054_NESTED_COMMENT,

    // ---- gcnc's own codes ----
    // 100-199: checker (parse and check packages). Add new codes in number order below this line.
    /** Checker: an arc's R is shorter than half the chord between its start and end points. */
    E101_ARC_RADIUS_TOO_SMALL,
    /** Checker: an I/K arc's end point is off the circle by more than the tolerance. */
    E102_ARC_END_OFF_CIRCLE,
    /** Checker: the feed exceeds the machine's maximum (feed.max). */
    E103_FEED_ABOVE_MAXIMUM,
    /** Checker: feed per revolution (G95/G99) with no spindle speed programmed. */
    E104_FEED_PER_REV_NO_SPEED,
    /** Checker: an R arc whose end point is its start point (a full circle needs I/K). */
    E105_ARC_FULL_CIRCLE_WITH_R,
    /** Checker: an arc leaves the travel between end points that are inside it. */
    E106_ARC_BEYOND_TRAVEL,
    /** Checker (warning): a coordinate without a decimal point, read in least increments, far from its neighbours. */
    E107_NO_DECIMAL_POINT,
    /** Checker: a word the control knows that has no meaning in this block (Q in a G01 block). */
    E108_WORD_NOT_USED,
    /** Parser: words of text outside a comment (a note the programmer forgot to put in parentheses). */
    E109_TEXT_OUTSIDE_COMMENT,
    /** Checker: a function the control has that gcnc cannot follow yet (cycles, compensation, subprograms). */
    E110_NOT_SUPPORTED_YET,
    /** Parser: Fanuc macro B (# variables, [ ] expressions) is not supported yet. */
    E111_MACRO_NOT_SUPPORTED_YET,
    /** Checker: G17 or G19 on a lathe, which cuts in the ZX plane (G18) only. */
    E112_PLANE_NOT_ZX,
    /** Checker (warning): an M code the machine profile gives no output: it does nothing on that machine. */
    E113_M_WITHOUT_OUTPUT,
    /** Checker (warning): a sequence number that an earlier block already has. */
    E114_DUPLICATE_SEQUENCE_NUMBER,
    /** Note: later blocks that broke the same prerequisite as the first one reported (the checker), or got the same warning with the same arguments (any stage: Diagnostics folds it). */
    E115_SAME_CAUSE,
    /** Checker: the error cap was reached; checking stopped there. */
    E116_ERROR_CAP,
    /** Checker: G53 with an incremental word or under G91: machine coordinates are absolute. */
    E117_G53_ABSOLUTE_ONLY,
    /** Checker (note): the finding before it occurs only with the block delete switch in the other position. */
    E118_BLOCK_DELETE_VARIANT,
    /** Checker: an rpm above the machine's spindle.max_rpm (E015 is the travel's: the two need different words). */
    E119_S_ABOVE_MACHINE_MAXIMUM,
    /** Parser: the letter O typed for a zero inside a number (Z-3O.), with the number it surely meant. */
    E120_LETTER_O_IN_NUMBER,
    /** Parser: a decimal comma (Z-30,5), with the number written with a point. */
    E121_DECIMAL_COMMA,
    /** Checker: a G04 dwell of negative time (the backend would write WT with a negative time). */
    E122_NEGATIVE_DWELL,
    /** Program flow: M98 calls a program that is not after the main program's end in the file (no folder to look in). */
    E130_NO_PROGRAM_HERE,
    /** Program flow: M98 calls a program that is neither in the file nor a file beside it. */
    E131_NO_PROGRAM_BESIDE,
    /** Program flow: a call (M98, M97) without P. */
    E132_CALL_WITHOUT_P,
    /** Program flow: a program that calls itself, directly or through others. */
    E133_RECURSIVE_CALL,
    /** Program flow: calls nested deeper than the control allows. */
    E134_CALLS_TOO_DEEP,
    /** Program flow: a repeat count (L, or the leading digits of a Fanuc P) that is not 1 to 9999. */
    E135_BAD_REPEAT_COUNT,
    /** Program flow (note): the call that led to the finding before it, one note per level. */
    E136_CALLED_FROM,
    /** Program flow: the program after its first call is longer than gcnc holds in memory. */
    E137_TOO_LONG_TO_HOLD,
    /** Program flow (note): a program after the main program's end that nothing calls, or a label there that a GOTO or M97 names and this run never reached: only parsed. */
    E138_NEVER_CALLED,
    /** Program flow (warning): M99 in the main program, which the control runs again from its top. */
    E139_M99_IN_MAIN,
    /** Program flow: a called program that ends without M99. */
    E140_NO_M99,
    /** Macro B: GOTO, END or DO with no label or loop to go to in the program (as far as gcnc holds it). */
    E141_NO_JUMP_TARGET,
    /** Program flow: two programs with the same number after the main program's end. */
    E142_DUPLICATE_PROGRAM,
    /** Program flow: the repeat count given twice (a Fanuc P with more than 4 digits and an L). */
    E143_TWO_REPEAT_COUNTS,
    /** Program flow (note): as E136, for a call written in a file of its own (named). */
    E144_CALLED_FROM_FILE,
    /** Program flow (note): as E136, for a call in the program file when the finding is in another file. */
    E145_CALLED_FROM_PROGRAM_FILE,
    /** Macro B: a value that cannot be had: a vacant variable in a word, a division by zero, a function outside its domain. */
    E146_MACRO_NO_VALUE,
    /** Macro B: a variable only the machine knows when it runs (positions, modal state, clocks, values set before this program). */
    E147_MACRO_RUN_TIME_ONLY,
    /** Macro B: #3000, the program's own alarm, is reached. */
    E148_MACRO_ALARM,
    /** Macro B: a loop (WHILE, or a GOTO that jumps back) that runs past gcnc's limit: an endless loop. */
    E149_MACRO_ENDLESS_LOOP,

    // 150-169: G70/G71/G72 contour cycles (gcnc.check.cycle, docs/cycles.md).
    /** Checker: a cycle's P or Q names a block that never comes (the program ends first). */
    E150_CYCLE_LABEL_NOT_FOUND,
    /** Checker: the N of a cycle's P or Q appears twice in its contour. */
    E151_CYCLE_LABEL_TWICE,
    /** Checker: no longer reported (issue 17): a block between a cycle and N(P) is warning E644. */
    E152_CONTOUR_NOT_NEXT,
    /** Checker: no N(Q) within the look-ahead limit after a G71/G72. */
    E153_CONTOUR_TOO_LONG,
    /** Checker: a contour goes back along an axis it must follow one way (type I: both; type II: the cutting axis). */
    E154_CONTOUR_NOT_MONOTONIC,
    /** Checker: the contour's first move goes along the cutting axis (type I: the depth axis only). */
    E155_CONTOUR_FIRST_MOVE,
    /** Checker: a depth of cut of zero or less. */
    E156_CYCLE_DEPTH,
    /** Checker: a G71/G72 without a depth of cut or a retract (no D, no first block, no control setting). */
    E157_CYCLE_DEPTH_MISSING,
    /** Checker: a negative retract. */
    E158_CYCLE_RETRACT,
    /** Checker: a finishing allowance whose sign puts it inside the part. */
    E159_CYCLE_ALLOWANCE_SIGN,
    /** Checker: the cycle starts inside the contour (or its allowance). */
    E160_CYCLE_START_INSIDE,
    /** Checker: a word a cycle block does not take. */
    E161_CYCLE_WORD,
    /** Checker: a function a cycle's contour cannot hold (an M, a T, a G other than a move). */
    E162_CONTOUR_WORD,
    /** Checker: a contour with no move after its first. */
    E163_CONTOUR_EMPTY,
    /** Checker: a cycle option gcnc cannot follow yet (the rough allowances I/K). */
    E164_CYCLE_OPTION_NOT_SUPPORTED,
    /** Checker (note): where a finding inside an expanded cycle comes from. */
    E165_CYCLE_PASS,
    /** Checker: a G70 whose P/Q is the contour of no earlier G71/G72/G73. */
    E166_FINISH_WITHOUT_CONTOUR,
    /** Checker: a depth of cut so small that the cycle would make more passes than gcnc expands. */
    E167_CYCLE_TOO_MANY_PASSES,
    /** Checker: a cycle block without its P or Q. */
    E168_CYCLE_P_Q_MISSING,
    /** Checker: a G90/G94 single-pass cycle without its X (or U) or its Z (or W). */
    E169_SINGLE_CYCLE_END_MISSING,
    /** Nose compensation: the start-up move after G41/G42 is shorter than the nose radius. */
    E170_NOSE_START_UP_TOO_SHORT,
    /** Nose compensation: an arc as the start-up move or as the G40 move. */
    E171_NOSE_ARC_START_OR_EXIT,
    /** Nose compensation: a concave corner tighter than the nose (the offset path runs backwards). */
    E172_NOSE_INTERFERENCE,
    /** Nose compensation: a concave arc smaller than the nose radius. */
    E173_NOSE_ARC_TOO_TIGHT,
    /** Nose compensation (warning): G41 to G42 (or back) without G40 between; the control changes sides. */
    E174_NOSE_SIDE_CHANGE,
    /** Nose compensation (warning): the program ends with G41/G42 in force. */
    E175_NOSE_AT_END,
    /** Nose compensation: more blocks without a move than gcnc looks ahead. */
    E176_NOSE_TOO_MANY_STILL_BLOCKS,
    /** Nose compensation (note): the tool offset in force has no nose radius in the profile. */
    E177_NOSE_NO_RADIUS,
    /** Nose compensation: G31 (skip) with G41/G42 in force, which the control alarms (Fanuc PS0035). */
    E178_NOSE_FUNCTION_IN_FORCE,
    /** Nose compensation: the compensated path leaves the travel where the programmed one did not. */
    E179_NOSE_BEYOND_TRAVEL,
    /** Checker: a peck depth, step or G83 Q of zero or less. */
    E180_PECK_NOT_POSITIVE,
    /** Checker: a G74/G75 peck deeper than the whole cut. */
    E181_PECK_DEEPER_THAN_CUT,
    /** Checker: a peck or drilling cycle without what it needs (its end point, its peck, its retract). */
    E182_PECK_CYCLE_MISSING,
    /** Checker: a G74/G75 relief larger than the step between its cuts. */
    E183_RELIEF_TOO_LARGE,
    /** Checker: a negative G74/G75 relief when the cycle steps (its sign is then the step's). */
    E184_RELIEF_SIGN,
    /** Checker: a G74/G75 whose end point lies along the step axis but that gives no step. */
    E185_STEP_MISSING,
    /** Checker (warning): a drilling cycle off the spindle centre with a tool that does not turn. */
    E186_DRILL_OFF_CENTRE,
    /** Checker: a drilling cycle whose R plane is not between its start and its bottom. */
    E187_DRILL_R_PLANE,
    /** Checker: a word of a peck or drilling cycle that gcnc cannot follow yet (L repeats). */
    E188_PECK_OPTION_NOT_SUPPORTED,
    /** Checker: a type II G71/G72 contour with a pocket and a finishing allowance along the cutting axis. */
    E189_TYPE_TWO_CUT_ALLOWANCE,
    /** Checker: a thread (G32/G33, G92/G78, G76) on a machine whose profile has no spindle encoder. */
    E190_NO_SPINDLE_ENCODER,
    /** Checker: a thread cut under G96 constant surface speed (threading needs G97). */
    E191_THREAD_NEEDS_G97,
    /** Checker: lead x spindle speed is faster than the Z axis's maximum feed. */
    E192_THREAD_TOO_FAST,
    /** Checker: a thread's height is deeper than the sharp V of its lead (0.866 x lead; above 0.65 x it is warning E640). */
    E193_THREAD_TOO_DEEP,
    /** Checker: a G76 first depth of cut (Fanuc Q, Haas D) of zero or less. */
    E194_THREAD_FIRST_DEPTH,
    /** Checker: a thread block without a word it needs (F, X/Z, K, D, P, Q). */
    E195_THREAD_WORD_MISSING,
    /** Checker: a thread that advances more along X than along Z (lead along X is not supported). */
    E196_THREAD_NOT_ALONG_Z,
    /** Checker: a thread word with a value the control does not accept (G76 P digits, angle, A, P). */
    E197_THREAD_WORD_VALUE,
    /** Checker: a thread lead of zero or less. */
    E198_THREAD_LEAD,
    /** Checker, note: which pass of a thread cycle (G76, G92/G78) a finding is in. */
    E199_THREAD_PASS,

    // 200-299: Galil backend (galil package).
    /** A count, speed or time the galil dialect would send does not fit the controller's 32-bit registers. */
    E201_GALIL_RANGE,
    /** No CR with a whole-count radius ends within one count of the arc's programmed end point. */
    E202_ARC_NOT_REPRESENTABLE,
    /** The spindle speed needs more than the 10 V an OF output gives. */
    E203_SPINDLE_VOLTS,
    /** The spindle speed needs between 9.998 V and 10 V; OF is clamped to 9.998 V. */
    E204_SPINDLE_VOLTS_CLAMPED,
    /** A number has more integer digits than the thesis dialect's FloatToStrF format prints. */
    E205_THESIS_NUMBER,
    /** The thesis's I/K two-piece arc formula (GenCirInterp) has no real solution. */
    E206_THESIS_ARC,
    /** A cutting feed is below one count per second, the slowest vector speed VS can give. */
    E207_FEED_TOO_SLOW,
    /** A thread's gear ratio (axis counts per spindle encoder count) beyond Galil's GR range of 127.9999. */
    E208_GEAR_RATIO_RANGE,
    /** The thesis dialect has no electronic gearing: a thread cannot be written in it. */
    E209_THESIS_NO_GEARING,
    /** Checker (Fanuc): C or R without a comma at a corner not between the two axes: the control wants ,C or ,R (PS0054). */
    E210_CORNER_WANTS_COMMA,

    // 220-239: the controller's limits (gcnc.machine.ControllerLimits; tables/galil_models.csv,
    // docs/galil.md "The controller's limits"): a value the controller refuses (an error, TC 6 or
    // the download's TC 60-62) or rounds (a warning: the machine would not do exactly what was written).
    /** VS outside the model's vector speed range (2 to 15,000,000 counts/s). */
    E220_VECTOR_SPEED_RANGE,
    /** A segment speed {@code <o} or {@code >p} of VP or CR outside the model's range (2 to 15,000,000 counts/s). */
    E221_SEGMENT_SPEED_RANGE,
    /** VA or VD outside the model's acceleration range (1,024 to 1,073,740,800 counts/s^2). */
    E222_ACCELERATION_RANGE,
    /** A VP segment longer than the model takes in one segment (8,388,607 counts). */
    E223_SEGMENT_TOO_LONG,
    /** A CR radius outside the model's range (10 to 6,000,000 counts). */
    E224_ARC_RADIUS_RANGE,
    /** A CR arc whose radius times its degrees is not below the model's 450,000,000. */
    E225_ARC_TOO_LONG,
    /** WT outside the model's range (2 to 2,147,483,646 ms). */
    E226_DWELL_RANGE,
    /** A program line longer than the model's 80 characters (TC 60 at download). */
    E227_LINE_TOO_LONG,
    /** A program with more lines than the model's memory holds (TC 60 at download). */
    E228_TOO_MANY_LINES,
    /** A program with more labels than the model holds (TC 62). */
    E229_TOO_MANY_LABELS,
    /** A label name longer than the model takes (7 characters). */
    E230_LABEL_TOO_LONG,
    /** A program that creates more variables than the model holds. */
    E231_TOO_MANY_VARIABLES,
    /** Arrays with more elements together than the model holds. */
    E232_TOO_MANY_ARRAY_ELEMENTS,
    /** A sequence whose path is not below the model's total distance (2^30 counts) before BGS. */
    E233_SEQUENCE_TOO_LONG,
    /** More segments before BGS than the model's sequence buffer holds (511; TC 164). */
    E234_TOO_MANY_SEGMENTS,
    /** Warning: VA or VD is not a multiple of 1,024; written as the multiple the controller would take (rounded down). */
    E235_ACCELERATION_ROUNDED,
    /** Warning: a vector or segment speed is odd; written as the even speed below it (the controller's resolution is 2). */
    E236_SPEED_ROUNDED,
    /** Warning: a dwell of an odd number of milliseconds; written as the even one above it (WT's resolution is 2). */
    E237_DWELL_ROUNDED,
    /**
     * The program form was asked for ({@code --form program}) and the program has more lines than
     * the model's program memory: DL would refuse it. The message says how large the stream form is.
     */
    E238_PROGRAM_DOES_NOT_FIT,
    /**
     * The stream form's resident program (set-up, routines, the blocks that must run inside the
     * controller) has more lines than the model's program memory.
     */
    E239_RESIDENT_DOES_NOT_FIT,

    // 240-249: checker (check package) again: the chamfered pull-out of a thread pass under Haas M23
    // (docs/threading.md). Next to the backend's thread codes because E190-E199 are full.
    /** Checker: the chamfered pull-out (M23) is as long as the pass's Z travel or longer. */
    E240_THREAD_CHAMFER_TOO_LONG,
    /** Checker: the chamfered pull-out (M23) would end beyond the X travel. */
    E241_THREAD_CHAMFER_TRAVEL,
    /** Checker: the chamfered pull-out (M23) would move X faster than the machine's maximum feed. */
    E242_THREAD_CHAMFER_TOO_FAST,
    /**
     * Stream form: a block that must run inside the controller (a thread) writes more commands than
     * one routine of the resident program is given ({@link gcnc.dmc.StreamSplit#RUN_LIMIT}).
     */
    E243_BLOCK_TOO_LONG_TO_EMBED,
    /** Replay of the stream form: the resident program is longer than a replay reads of it. */
    E244_RESIDENT_TOO_LONG_TO_REPLAY,
    /** Warning, replay of the stream form: the stream is not the one the resident program's map names (another compile). */
    E245_STREAM_NOT_THIS_RESIDENT,

    // 250-259: the machine around the motion (gcnc.galil.MachineCode; docs/galil.md).
    /** Warning: a dwell shorter than the 2 ms WT takes (G04 P1): the DMC waits 2 ms, as the clamp says. */
    E250_DWELL_BELOW_WT,
    /** The spindle speed needs more than the 10 V an analog output (AO) gives. */
    E251_SPINDLE_AO_VOLTS,
    /** Warning: the spindle speed needs between 9.998 V and 10 V; AO is clamped to 9.998 V. */
    E252_SPINDLE_AO_CLAMPED,

    // 253-256: the planner's profile keys and limits (gcnc.plan, gcnc.machine.Blending; docs/galil.md).
    /** Profile: {@code plan.on_the_fly} names an M code that is not an output M of the control (a spindle, chuck, stop or call code must happen at rest). */
    E253_ON_THE_FLY_NOT_OUTPUT,

    // 300-399: simulator (sim package).
    /** A DMC line the simulator does not know. */
    E300_SIM_UNKNOWN_INSTRUCTION,
    /** A DMC instruction with missing or malformed arguments. */
    E301_SIM_BAD_ARGUMENTS,
    /** The path leaves an axis's travel somewhere along a segment. */
    E302_SIM_TRAVEL,
    /** The tool tip or holder enters the chuck. */
    E303_SIM_CHUCK_COLLISION,
    /** The tool tip or holder enters the tailstock. */
    E304_SIM_TAILSTOCK_COLLISION,
    /** A rapid move goes through material that has not been cut. */
    E305_SIM_RAPID_INTO_STOCK,
    /** A cutting move while the outputs say the spindle is stopped. */
    E306_SIM_FEED_SPINDLE_STOPPED,
    /** A cutting move while the outputs say the chuck is open. */
    E307_SIM_FEED_CHUCK_OPEN,
    /** A replayed sequence does not end where, or run the way, the G-code block says. */
    E308_SIM_PATH_MISMATCH,
    /** A CR arc with zero sweep: the machine does not move but the program expects an arc. */
    E309_SIM_ZERO_SWEEP_ARC,
    /** A position or argument outside the controller's 32-bit range. */
    E310_SIM_COUNT_RANGE,
    /** The DMC of a block makes a different number of moves than the block has. */
    E311_SIM_SEQUENCE_COUNT,
    /** A directive after EN is never executed. */
    E312_SIM_AFTER_END,
    /** VM or SH names axes other than the profile's vector plane. */
    E313_SIM_VECTOR_PLANE,
    /** Vector segments that no BGS starts. */
    E314_SIM_SEQUENCE_NOT_STARTED,
    /** The tool holder (not the insert) reaches into stock during a cut: the insert is too small for the cut. */
    E315_SIM_HOLDER_IN_STOCK,
    /** Note: no blank was given, so the stock checks were skipped. */
    E316_SIM_NO_STOCK,
    /** A geared thread pass that does not end where its settling move goes: the gear ratios give the wrong lead or taper. */
    E317_SIM_THREAD_LEAD,
    /** Gearing engaged without GA naming the spindle encoder as the master. */
    E318_SIM_THREAD_NO_MASTER,
    /** Gearing engaged without the wait for the spindle's next whole revolution: passes start at different angles. */
    E319_SIM_THREAD_UNSYNCHRONISED,
    /** (warning) The passes of a thread may start a number of counts apart: GR without a phase correction. */
    E340_SIM_THREAD_PHASE,
    /** A thread pass's run-in is shorter than the axis needs to reach the geared speed. */
    E260_THREAD_RUN_IN,
    /**
     * (warning) A Denford / MIRAC set-up line ({@code [BILLET X.. Z..}, {@code [TOOLDEF ..}): the
     * training control's own word for its simulation, read as a comment; not a block of the control.
     */
    E261_DENFORD_SETUP_LINE,
    /** G43 / G44 / G49 (tool length compensation, machining-centre codes) on a lathe control that has none. */
    E262_MILL_TOOL_LENGTH_G,
    /**
     * (warning) An rpm S above the G50 (G92 on Fanuc system B) S limit on a control that clamps it
     * ({@code spindle_above_clamp = clamp}: Fanuc, Haas): the spindle turns at the limit.
     */
    E280_S_CLAMPED_BY_LIMIT,
    /** During a cut, an insert edge that does not cut (its back) meets material first: turning back toward the tailstock too deep. */
    E320_SIM_BACK_OF_INSERT,
    /**
     * Warning, once per station: a station the profile does not describe (no station.N or
     * sim.tool.N) is checked as the profile's default tool; what is found about its outline rests on
     * that assumption, and the findings say so.
     */
    E321_SIM_STATION_ASSUMED,
    /**
     * Warning, once per station: a station the profile does not describe, on a profile with no
     * default tool either: checked at its tip only, the holder and back-of-insert checks skipped.
     */
    E322_SIM_STATION_TIP_ONLY,
    /** A drill, centre drill or tap meets material with an edge that does not cut: moved sideways, or a tap into solid material. */
    E323_SIM_AXIAL_TOOL_SIDEWAYS,
    /** Checker warning: one cycle block expands into far more pecks or passes than its text suggests (a value without its decimal point). */
    E330_CYCLE_MANY_PECKS,
    /** Replay warning: the source map beside a DMC records another DMC (its hash differs): its lines are not used. */
    E331_MAP_NOT_THIS_DMC,
    /** A blended sequence takes a corner faster than the machine's acceleration and corner deviation allow. */
    E332_SIM_CORNER_TOO_FAST,
    /** A blended segment is too short for the machine to change from its entry speed to its exit speed. */
    E333_SIM_SPEED_CHANGE_TOO_SHORT,

    // 334-339: the planner's work checked by the replay (docs/galil.md, "Continuous contouring").
    /**
     * An AV trip point (the sum of the sequence's AV distances: AV is relative) past the end of the
     * sequence it waits on: the controller never reaches it; what it does then its reference does not say.
     */
    E334_SIM_TRIP_PAST_END,
    /** An output or speed set on the way (after AV) at a point of the path that is not where its block stands in the program. */
    E335_SIM_SWITCHED_ELSEWHERE,
    /** IT below 1 (smoothing): the replay runs vector motion unfiltered, as IT 1; not simulated yet. */
    E336_SIM_SMOOTHING,

    // 400-499: tables and machine profiles.
    /** A table file or machine profile is malformed; the message says what and where. */
    E400_TABLE,
    /** A number in a profile or control larger in size than any Galil register (2^31 - 1). */
    E401_PROFILE_NUMBER_TOO_LARGE,
    /** A profile value outside the range gcnc takes for it (counts per mm, r/min, feed.per_f). */
    E402_PROFILE_VALUE_RANGE,
    /** A work or tool offset that, in counts, does not fit a 32-bit position register. */
    E403_PROFILE_COUNTS_OVERFLOW,
    /** A table, control or profile file larger than gcnc reads (a link to a device, a file of another kind). */
    E404_TABLE_FILE_TOO_LARGE,
    /**
     * Profile: spindle.max_rpm needs more than the 9.998 V the OF output gives (but not more than
     * 10 V, E410) at spindle.rpm_per_volt: every program at the machine's own top speed would get
     * E204 (its spindle clamped, a little slower) at every S that asks for it.
     */
    E405_SPINDLE_TOP_SPEED_CLAMPED,
    /** Profile: spindle.max_rpm needs more than the 10 V the OF output gives at spindle.rpm_per_volt: every compile at top speed would be E203. */
    E410_SPINDLE_TOP_SPEED_VOLTS,
    /** Profile: galil.model names no model of tables/galil_models.csv. */
    E420_UNKNOWN_GALIL_MODEL,
    /** Profile: a channel (x.galil, z.galil, spindle.axis, spindle.encoder_axis) the model does not have. */
    E421_CHANNEL_BEYOND_MODEL,
    /** Profile: vector.acceleration or vector.deceleration outside what the model's VA and VD take. */
    E422_ACCELERATION_BEYOND_MODEL,
    /** Profile: rapid.speed or feed.max outside what the model's VS takes. */
    E423_SPEED_BEYOND_MODEL,
    /** Profile: an M code's output (SB n, CB n) the model does not have. */
    E424_OUTPUT_BEYOND_MODEL,
    /** Profile: galil.firmware is not a firmware revision (1.2a, 1.0c ...). */
    E425_FIRMWARE_REVISION,
    /** Profile: spindle.output is neither OF (on spindle.axis) nor AO n. */
    E430_SPINDLE_OUTPUT,
    /** Profile: spindle.at_speed is neither IN n, a dwell in seconds, nor none. */
    E431_SPINDLE_AT_SPEED,
    /** Profile: a turret key without the others it needs (station outputs, strobe, in-position input). */
    E432_TURRET_INCOMPLETE,
    /** Profile: the turret's station outputs cannot code every station of tools.count. */
    E433_TURRET_STATIONS,
    /** Profile: homing.check is neither position, IN n, nor none. */
    E434_HOMING_CHECK,
    /** Profile: an input (IN n, turret.in_position) that is no digital input @IN reads on the model (command reference @IN). */
    E436_INPUT_RANGE,
    /** Profile: spindle.output = AO n with n outside 1,000-8,999, the only I/O numbers AO takes (command reference AO). */
    E437_ANALOG_OUTPUT_RANGE,
    // 450-459: wear offsets in a profile or its offsets file (docs/profiles.md, "Wear offsets").
    /** Offsets file: a key other than wear.N (N = 1 to 99). */
    E450_OFFSETS_FILE_KEY,
    /** Profile or offsets file: wear.N with a third value, the nose radius's wear, which gcnc does not support yet. */
    E451_WEAR_NOSE_NOT_SUPPORTED_YET,
    /** Profile or offsets file: wear.N for a tool offset the profile does not have. */
    E452_WEAR_NO_TOOL_OFFSET,
    /** Profile or offsets file: a wear larger in size than wear.max_total. */
    E453_WEAR_BEYOND_TOTAL,
    /** Profile: wear.max_step larger than wear.max_total. */
    E454_WEAR_STEP_ABOVE_TOTAL,
    /** The offsets file named (--offsets, offsets.file) does not exist. */
    E455_OFFSETS_FILE_MISSING,
    /** An input file could not be read or an output file written. */
    E500_IO,
    /** The output named (-o, --svg) is the program being read, under this or another name. */
    E501_OUTPUT_IS_INPUT,
    /** The output named is a directory (or {@code /}), not a file. */
    E502_OUTPUT_IS_DIRECTORY,
    /** A line of a program longer than gcnc reads (BoundedReader.LINE_LIMIT); the rest of it is skipped. */
    E503_LINE_TOO_LONG,
    /** A program text longer than gcnc reads (BoundedReader.TEXT_LIMIT); reading ends there. */
    E504_TEXT_TOO_LONG,
    /** The file a call would read (O1000.nc) is a directory or a device, not a program file. */
    E505_CALLED_NOT_A_FILE,
    /**
     * The Java heap ran out (an input gcnc failed to bound, or a heap set too small with -Xmx): one
     * line and exit status 2, never a stack trace or the status that means "the program has errors".
     */
    E506_OUT_OF_MEMORY,
    /** A side file gcnc writes unasked (the source map, OUT.map) is a symbolic link: gcnc does not write through it. */
    E510_SIDE_FILE_IS_LINK,
    /** Simulation: the blank's diameter (a stock header, NO STOCK, the profile's) is more than twice the X travel's reach. */
    E511_BLANK_TOO_WIDE,
    /** Simulation: the blank sticks out of the jaws further than the Z travel is long. */
    E512_BLANK_STICKS_OUT_TOO_FAR,
    /** Simulation: the blank is longer than gcnc models (ten times the Z travel's length). */
    E513_BLANK_TOO_LONG,

    // 600-619: the parser's leniency and G01 chamfering and corner rounding (issue 17).
    /** Parser: a space inside a number (X10 5 reads as X105; not warned in a T word, T1 01). */
    E600_SPACE_IN_NUMBER,
    /** Parser (Haas, Fanuc): a '(' comment with no ')' on its line, which the control ends at the end of the block. */
    E601_COMMENT_NOT_CLOSED_ON_ITS_LINE,
    /** Parser: a block after a DOS end-of-file mark (Ctrl-Z), where a transfer program may stop. */
    E602_TEXT_AFTER_END_OF_FILE_MARK,
    /** Checker: G01 chamfering or corner rounding on a control that has none (the thesis's). */
    E604_NO_CORNER_FUNCTION,
    /** Checker: ,A with both end coordinates or alone, not as the two-block direct drawing form gcnc reads (not supported yet). */
    E606_ANGLE_NOT_SUPPORTED_YET,
    /** Checker: a chamfer or corner radius on a block that is not a G01 (Fanuc PS0050). */
    E607_CORNER_NOT_ON_G01,
    /** Checker: two corner words in one block, ,C and ,R or I and K (Fanuc PS0053). */
    E608_TWO_CORNERS,
    /** Checker: no move follows a chamfer or corner radius block (Fanuc PS0051). */
    E609_CORNER_NO_NEXT_MOVE,
    /** Checker: the move after a chamfer or corner radius is not a G01 (Fanuc PS0052). */
    E610_CORNER_NEXT_NOT_G01,
    /** Checker: a chamfer or corner radius longer than one of its two moves (Fanuc PS0055). */
    E611_CORNER_TOO_LARGE,
    /** Checker: a 90-degree chamfer or corner R (I, K; Fanuc C, R) between moves not along the two axes (Fanuc PS0054). */
    E612_CORNER_NOT_SQUARE,
    /** Checker: the two moves of a chamfer or corner radius are in line: no corner. */
    E613_CORNER_IN_LINE,
    /** Checker (Fanuc): the sign of a 90-degree chamfer or corner R points away from the next move. */
    E615_CORNER_SIGN,

    // 620-639: the language CAM posts write (issue 17): blocks under nose compensation, G32
    // sequences, hole cycles, G10/G30/G49.
    /**
     * Nose compensation (warning): G28, G29, G30, G53 or a position register under G41/G42; the
     * control cancels the offset for the block's move and restores it from the next move.
     */
    E620_NOSE_CANCELLED_FOR_THE_BLOCK,
    /** Nose compensation (warning): a T word under G41/G42; the new offset's nose applies from the next move. */
    E621_NOSE_TOOL_CHANGE,
    /**
     * Nose compensation (note): G71/G72/G73 under G41/G42; the control roughs the offset contour,
     * gcnc the programmed one. A note: the program is the Fusion posts' normal one and runs right.
     */
    E622_NOSE_ROUGHING_CYCLE,
    /** Nose compensation (warning): G90/G94 under G41/G42; the control offsets each path of the cycle. */
    E623_NOSE_SINGLE_CYCLE,
    /** Nose compensation (warning): a thread, peck or drilling cycle under G41/G42; not offset, the compensation resumes after. */
    E624_NOSE_NOT_OFFSET,
    /** G10 with an L other than 2 (tool offsets, parameters): not supported yet. */
    E625_G10_NOT_SUPPORTED,
    /** G10 L2 without P, or with a P that names no work offset (P0-P6). */
    E626_G10_WORK_OFFSET_NUMBER,
    /** A G32 continues a thread across a block that moves, changes M, S or T, or too many blocks: not supported yet. */
    E627_THREAD_CONTINUED_ACROSS,
    /** A G32 continues a thread with another lead (or spindle direction): variable lead is not supported yet. */
    E628_THREAD_LEAD_CHANGES,
    /** A tapping cycle with the spindle turning against the tap (G84 under M04, G184 under M03): warning. */
    E629_TAP_AGAINST_SPINDLE,
    /** G30 with a P other than 2, 3 or 4. */
    E630_G30_REFERENCE_NUMBER,
    /** G30 to a reference point the machine profile does not give (reference.N). */
    E631_G30_NO_REFERENCE,
    /** Checker: a ,A line that never meets the end coordinate given (along the other axis; Fanuc PS0057). */
    E632_ANGLE_NO_SOLUTION,
    /** Checker: ,A on a block that is not a G01 move (not supported yet). */
    E633_ANGLE_NOT_ON_G01,
    /** Checker: the two angles of the two-block ,A form are parallel: no corner (Fanuc PS0057). */
    E634_ANGLES_PARALLEL,
    // 640-659: checker again: what the control runs though the result may not be what was meant
    // (issue 17; tables/error_basis.csv says which control behaviour each rule stands for).
    /** Checker: a thread height above a standard thread's 0.65 x lead but within the sharp V (0.866 x lead): cut as written. */
    E640_THREAD_DEEPER_THAN_STANDARD,
    /** Checker: a G76 started between the thread's root and its top (X + 2K): the control runs it. */
    E641_THREAD_START_BELOW_TOP,
    /** Checker: U, W or D in a G70: the control ignores them. */
    E642_FINISH_WORD_IGNORED,
    /** Checker: a G70 whose P and Q name part of a stored G71/G72/G73 contour: the control finishes those blocks. */
    E643_FINISH_PART_OF_CONTOUR,
    /** Checker: a block between a G71/G72/G73 and its contour's first block: the control never runs it. */
    E644_BLOCK_BEFORE_CONTOUR,
    /** Checker: G90 or G94 with no end point, where they are the turning/facing cycles (Fanuc system A, Haas). */
    E645_CYCLE_WITHOUT_END_POINT,
    /** Checker: a cut with tool offset 00 set by a T word: no geometry offset is applied. */
    E646_CUT_WITHOUT_TOOL_OFFSET,
    /** Checker: the feed mode changes (G98/G99, G94/G95) with no new F: the F in force is read in the new unit. */
    E647_FEED_MODE_WITHOUT_F,
    /** Checker: G96 without S after a G97 S: the control takes that S as the surface speed. */
    E648_CSS_TAKES_RPM,
    /** Checker (note): a C-axis or live-tool M code in a program with no C-axis motion: accepted, it drives nothing. */
    E649_M_FOR_AXIS_NOT_USED,
    /** Checker: C-axis motion (a C word after a C-axis M code) is not supported yet. */
    E650_C_AXIS_NOT_SUPPORTED,
    // 660-679: the machine as a shop sets it up (tool table, work zero from the blank).
    /**
     * Warning: a feed per minute with the spindle stopped by the program: not a cut unless it meets
     * stock, which only the simulation knows (compile reports E306 then); check cannot tell.
     */
    E660_FEED_SPINDLE_STOPPED_NOT_JUDGED,
    /**
     * Warning: a feed per minute with the spindle stopped and the chuck open: a bar or stock pull,
     * not a cut unless it meets stock (compile's simulation: E306, E307).
     */
    E661_PULL_NOT_JUDGED,
    /**
     * Note: the work offsets a shop sets on the blank's face ({@code work.G54 = 0, face}) follow the
     * blank given for this run ({@code --stock D,L,S}): where they are now.
     */
    E662_WORK_ZERO_FROM_BLANK,
    /**
     * Warning: the blank given for this run has its face elsewhere than the G54 the profile pins:
     * the program's Z0 is not the face it was written for.
     */
    E663_WORK_ZERO_PINNED,
    // 670-679: waivers, (GCNC ALLOW E642: reason) (issue 31; gcnc.diag.Waivers, docs/language.md "Waivers")
    /** Parser (warning): a waiver without a reason after its ':': it waives nothing until it says why. */
    E670_WAIVER_NO_REASON,
    /** Parser (warning): a waiver names a code gcnc does not have: it waives nothing. */
    E671_WAIVER_UNKNOWN_CODE,
    /** Warning: a waiver on a block where its code is not found: it waives nothing. */
    E672_WAIVER_UNUSED,
    /** Warning: a FILE waiver whose code is not found in the rest of the file: it waives nothing. */
    E673_WAIVER_FILE_UNUSED,
    /** Warning: a waiver names a simulator error (a collision, a limit, the replay): it cannot be waived. */
    E674_WAIVER_NOT_ALLOWED,
    /** Compile error: an error is waived, but the block it was found in was never translated. */
    E675_WAIVED_ERROR_NOT_TRANSLATED,
    /** Parser (warning): a comment that starts GCNC ALLOW but is not a waiver's form. */
    E676_WAIVER_FORM,
    /** Warning: a waiver names one of the waivers' own codes (E670-E679), which cannot be waived. */
    E677_WAIVER_OF_WAIVER,
    /** Note: the finding before it was found this many times at its place (a loop's passes); kept once. */
    E680_FOLDED,
    /** Note: the cap on warnings and notes was reached; later ones are not kept. */
    E681_OTHER_CAP,
    /** {@code #3000 = n}: n is not an alarm number (0 to 200); the control stops with an alarm of its own. */
    E682_MACRO_ALARM_NUMBER,
    /** A macro value outside what a variable holds (0, or 10^-29 to 10^47 in size): alarm 111. */
    E683_MACRO_VALUE_RANGE,
    /** An end code (M30, M02) in a called program: the whole run ends there, the caller never resumes. */
    E685_END_IN_CALLED_PROGRAM,
    // 700-729: threads and codes the CAM posts write (issue 17).
    /**
     * A mode of the control that changes nothing in the path gcnc checks and writes (Fanuc G61
     * exact stop mode, G64 cutting mode, G23 stroke check off): read as a no-op, said as a note.
     */
    E700_MODE_ONLY,
    /**
     * A mode of the control given values gcnc does not follow (Fanuc G22 X Z I K, the stored stroke
     * check's forbidden area): the machine alarms if a move enters it, and gcnc does not check that.
     */
    E701_MODE_VALUES_NOT_CHECKED,
    /**
     * A G code written with a decimal point (Fanuc G12.1/G13.1 polar interpolation, G54.1 P added
     * work coordinates, G50.3, G30.1, G07.1): not supported yet, named (rather than E013).
     */
    E702_DOTTED_G_NOT_SUPPORTED,
    /** A spindle orientation angle (Haas M19 P whole degrees, R decimal degrees) outside 0-360. */
    E703_ORIENT_ANGLE,
    /**
     * A G28 with no axis word on a control where it moves nothing (Fanuc: G28 returns the axes it
     * names): the block runs and nothing homes, which a Haas habit did not mean. A warning.
     */
    E704_BARE_G28_MOVES_NOTHING,
    /**
     * Text after the closing '%' (end of tape), which a control never reads (Fanuc and Haas stop
     * at it): not read by gcnc either, said once as a note at its first character.
     */
    E705_AFTER_TAPE_END,
    /**
     * Program flow: the run went through more blocks than its budget (ProgramFlow.budget: a constant
     * and so many per line of the program), inside a loop still running: taken for endless.
     */
    E710_MACRO_BUDGET,

    // --- drilling and tapping as the Fusion fanuc post writes them (issue 17, drill): E720-E729
    /**
     * Checker (note): M29, rigid tapping: the control gears the tap to the spindle; gcnc's G84
     * feeds it at the F in force and reverses the spindle, as for a floating holder.
     */
    E720_RIGID_TAP_NOT_GEARED,

    // --- gcnc run, the sender (issue 20, run; docs/run.md): E815-E829
    /** Sender: the serial device named by --port does not exist. */
    E815_PORT_MISSING,
    /** Sender: the serial device exists but another program holds it (or it may not be opened). */
    E816_PORT_HELD,
    /** Sender: no connection to the controller (TCP refused, unreachable, timed out). */
    E817_NO_CONNECTION,
    /** Sender: the controller is not the model the machine profile names (^R^V), or not a Galil. */
    E818_WRONG_CONTROLLER,
    /** Sender: the program needs more of the controller (lines, labels, variables, buffer) than it has. */
    E819_CAPACITY,
    /** Sender: the controller answered ? or stopped the program with an error: its TC code and text, at the G-code line. */
    E820_CONTROLLER_ERROR,
    /** Sender: the link closed during the run; the last block completed and the one executing are named. */
    E821_CONNECTION_DROPPED,
    /** Sender: no reply within the timeout. */
    E822_NO_REPLY,
    /** Sender: a reply that is not Galil's protocol. */
    E823_GARBAGE,
    /** Sender: the program read back with UL is not the one downloaded with DL. */
    E824_READBACK_DIFFERS,
    /** Sender: the controller cannot run the program (a limit switch active, a sequence moving, a program running; or it ended the program early). */
    E825_NOT_READY,
    /** Sender: the axes are not where the program was verified to start (home). */
    E826_NOT_AT_START,
    /** Sender: --resume-at cannot continue from where the axes are. */
    E827_CANNOT_RESUME,
    /** Sender (warning): the operator stopped the run. */
    E828_STOPPED_BY_OPERATOR,
    /** Sender (warning): motors are off on the program's axes; its SH turns them on. */
    E829_MOTORS_OFF,
    /** Sender: the profile's Galil model is a bus card (ISA/PCI) that a serial or TCP sender cannot reach. */
    E830_BUS_ONLY_MODEL,
    /** Sender: the vector buffer is not empty after CS S (_LMS below the model's whole buffer). */
    E831_BUFFER_NOT_EMPTY,
    /** Sender: the saved probe report says the controller contradicts a reference fact the run relies on. */
    E832_PROBE_CONTRADICTS,
    /** Sender and probe: a probe report that cannot be read or written. */
    E833_PROBE_REPORT,
    /** Probe: the motion test was asked for without the operator's typed confirmation. */
    E834_PROBE_NOT_CONFIRMED,
    /** Probe: the motion test cannot start (a program runs, a sequence moves, a limit is active). */
    E835_PROBE_NOT_READY,
    /** Probe (warning): the controller answered against a reference fact (a row of the report). */
    E836_PROBE_CONTRADICTION,
    /** Sender: the way back's feed is missing, not above 0, or above the machine's fastest cutting feed. */
    E837_WAY_BACK_FEED,
    /** Sender: the simulator finds a leg of the way back touching the part or the machine. */
    E838_WAY_BACK_COLLIDES,
    /** Sender: the way back was asked for without the operator's typed confirmation. */
    E839_WAY_BACK_NOT_CONFIRMED,
    /** Sender: the way back cannot be checked by the simulator (no stock). */
    E840_WAY_BACK_UNCHECKED,
    /** Probe: the link closed while the probe asked the controller; no report is written. */
    E841_PROBE_DROPPED,
    /** Probe: no reply within the timeout to one of the probe's questions; no report is written. */
    E842_PROBE_NO_REPLY,
    /** Probe: a reply that is not Galil's protocol; no report is written. */
    E843_PROBE_GARBAGE,
    /** Probe: the unit answered ? to a command the probe needs (TC1 says why); no report is written. */
    E844_PROBE_REFUSED,
    /** Profile: stop.cycle_start is not IN n. */
    E850_CYCLE_START_INPUT,
    /**
     * Sender: the link dropped after the program started: the controller may run on without the host
     * (docs/run.md, "Resume"); E821 is a link that dropped before anything moved.
     */
    E851_LINK_DROPPED_RUNNING,
    /** Simulate (note): the DMC is a stream form's resident program: its motion is in the stream beside it. */
    E864_RESIDENT_WITHOUT_STREAM,
    /** Sender: the serial port named is not a character device (a plain file, a folder, a pipe). */
    E865_PORT_NOT_A_DEVICE,

    // --- gcnc offsets wear, the test cut (issue 34; docs/command-line.md): E870-E879
    /** Test cut: the offset named is not T01, T0101 or a number 1 to 99. */
    E870_WEAR_OFFSET_NAME,
    /** Test cut: --measured and --programmed are not an axis letter and a number each, on the same axis. */
    E871_WEAR_MEASUREMENT,
    /** Test cut: the change is larger than wear.max_step (a slip of the keyboard). */
    E872_WEAR_STEP,
    /** Test cut: the wear after the change would be larger than wear.max_total. */
    E873_WEAR_TOTAL,
    /** Test cut: the program re-verified with the new wear has an error it did not have. */
    E874_WEAR_NEW_FINDING,
    /** Test cut: the program has errors before the wear changes, so it cannot be re-verified. */
    E875_WEAR_PROGRAM_NOT_CLEAN,
    /** Test cut: a shipped profile and no offsets file named: nowhere to keep the wear. */
    E876_WEAR_NOWHERE_TO_SAVE,
    /** Test cut: the program does not use the offset named (its DMC is the same with the new wear). */
    E877_WEAR_OFFSET_UNUSED,
    /**
     * Sender: the vector buffer ran dry before VE (the host, in the stream form, or the program's thread, in the
     * program form, did not keep a fed sequence fed): the axes stopped mid-sequence.
     */
    E890_BUFFER_STARVED;

    /** The number is the one in the name ({@code E037_...} is 37), written once. */
    private final int number = Integer.parseInt(name(), 1, 4, 10);

    public int number() {
        return number;
    }

    /** The form users see and search for: {@code E037}. */
    public String id() {
        return name().substring(0, 4);
    }

    /** The code with number {@code n}, if gcnc has one. */
    public static java.util.Optional<Code> find(int n) {
        for (Code c : values()) {
            if (c.number == n) {
                return java.util.Optional.of(c);
            }
        }
        return java.util.Optional.empty();
    }

    public static Code byNumber(int n) {
        return find(n).orElseThrow(() -> new IllegalArgumentException("no diagnostic code " + n));
    }
}
