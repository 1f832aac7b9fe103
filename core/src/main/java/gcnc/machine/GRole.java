package gcnc.machine;

/**
 * What a G code does, in gcnc's terms: the {@code function} column of a control's g_codes.csv.
 * The checker works on these, not on the numbers a control happens to use (Fanuc B's G92 is
 * Fanuc A's G50). {@link #number()} is the function's number in the thesis's Table 3, the
 * checker's function numbers (reading §6); gcnc's additions take the number Fanuc A gives them.
 */
public enum GRole {
    RAPID(0), LINEAR(1), ARC_CW(2), ARC_CCW(3), DWELL(4), EXACT_STOP(9),
    PLANE_XY(17), PLANE_ZX(18), PLANE_YZ(19), INCH(20), METRIC(21), HOME(28), FROM_HOME(29), SKIP(31),
    /** G30: return to the second (P2, third P3, fourth P4) reference point via an intermediate point (gcnc.check.ReferenceReturn). */
    OTHER_HOME(30),
    NOSE_COMP_CANCEL(40),
    /** G41/G42: the checker offsets the path by the nose radius (gcnc.check.NoseCompensation). */
    NOSE_COMP_LEFT(41), NOSE_COMP_RIGHT(42),
    REGISTER_AND_CLAMP(50), MACHINE_COORDINATES(53),
    /** G10 L2: a work offset written by the program (gcnc.check.OffsetSetting), handled before the syntax actions. */
    SET_OFFSETS(10),
    /**
     * G70 finishing along a contour, G71 stock removal in turning, G72 stock removal in facing,
     * G73 pattern repeat:
     * expanded by the checker into ordinary moves (gcnc.check.cycle, docs/cycles.md).
     */
    FINISHING_CYCLE(70), TURNING_CYCLE(71), FACING_CYCLE(72), PATTERN_CYCLE(73),
    /**
     * The single-pass cycles of group 1: turning along Z (Fanuc A and Haas G90, Fanuc B G77) and
     * facing along X (G94, Fanuc B G79), modal: a later block with X or Z makes the cycle again.
     */
    TURNING_SINGLE_CYCLE(90), FACING_SINGLE_CYCLE(94),
    /**
     * The peck cycles: G74 face grooving and peck drilling (pecks along Z, steps along X) and G75
     * OD/ID grooving and parting (pecks along X, steps along Z), one-shot, expanded into moves
     * (docs/cycles.md).
     */
    FACE_PECK_CYCLE(74), GROOVE_PECK_CYCLE(75),
    /**
     * The drilling cycles on the spindle axis (Haas G81 drill, G82 spot drill with a dwell, G83
     * peck drill), modal in their group until G80 or a motion G: expanded into moves.
     */
    DRILL_CYCLE(81), SPOT_DRILL_CYCLE(82), PECK_DRILL_CYCLE(83),
    /**
     * Tapping on the spindle axis (Haas G84, and G184 for a left-hand tap): the tap fed in, the
     * spindle reversed at the bottom, fed out to the R plane, the spindle turned back; modal as
     * the drilling cycles.
     */
    TAP_CYCLE(84), REVERSE_TAP_CYCLE(184),
    /**
     * Boring on the spindle axis, modal as the drilling cycles (docs/cycles.md): Haas G85 bore in
     * and out at the feed (Fanuc G85 face boring, with its dwell P), G86 bore and stop (the spindle
     * stopped at the bottom, a rapid out, the spindle started again), G89 bore, dwell, bore out.
     */
    BORE_CYCLE(85), BORE_STOP_CYCLE(86), BORE_DWELL_CYCLE(89),
    /**
     * The return level of the drilling and tapping cycles (Fanuc system B/C G98, G99: a modal
     * group of their own): after the hole the tool returns to the initial level (where the cycle
     * started) or to the R point. The numbers are gcnc's own (G98/G99 are the feed modes of
     * system A and Haas).
     */
    CYCLE_RETURN_INITIAL(-98), CYCLE_RETURN_R(-99),
    /**
     * Threading, spindle-synchronised (docs/threading.md): G32 one pass (Fanuc B G33, modal in
     * group 1), G92 the single-pass thread cycle (Fanuc B G78, modal in group 1) and G76 the
     * multiple-pass thread cycle (one-shot). Expanded by the checker into thread passes; the numbers
     * are gcnc's own (G92's Fanuc A number is the thesis's register).
     */
    THREAD(32), THREAD_SINGLE_CYCLE(-92), THREAD_CYCLE(76),
    WORK_1(54), WORK_2(55), WORK_3(56), WORK_4(57), WORK_5(58), WORK_6(59), CYCLE_CANCEL(80),
    ABSOLUTE(90), INCREMENTAL(91), REGISTER(92), FEED_PER_MINUTE(94), FEED_PER_REV(95), CSS(96), RPM(97),
    /**
     * G61 exact stop mode (Haas "exact stop modal", Fanuc "exact stop mode"): every move decelerates
     * to rest and is checked in position before the next starts, until G64. The checker hands it on
     * ({@code CheckedBlock.stopAt}) and the planner ends its vector sequence after every motion.
     */
    EXACT_STOP_MODE(61),
    /** G64 cutting mode (Haas "exact stop modal cancel"): consecutive moves blend again; the power-up mode. */
    CUTTING_MODE(64),
    /**
     * A mode of the control that changes nothing in the path gcnc checks and writes (Fanuc G22/G23
     * stored stroke check): read, with the note E700 saying so (its words, such as G22's area, are
     * its own and move nothing).
     */
    MODE_ONLY(-3),
    /**
     * Haas G103 P n, limit block lookahead (0-15 blocks; P0 or no P: no limit): on the Haas it decides
     * how far ahead of the motion macro statements run and blocks are prepared. gcnc works out every
     * macro before the run and plans over a look-ahead of its own, so the path is the same: the
     * note E700, and P is held to 0-15.
     */
    LOOKAHEAD_LIMIT(103),
    /**
     * G65 P L, the macro call (Fanuc custom macro B, Haas macros): the program P runs with a new
     * level of local variables #1-#33, the block's other addresses its arguments (A #1, B #2, ...).
     * Followed by gcnc.flow, which hands the checker the called program's blocks; met by the
     * checker (a block it sees without the flow in front of it) it is not followed, E110.
     */
    MACRO_CALL(65),
    /** A function gcnc cannot follow yet: using it is E110, never a misreading. */
    UNSUPPORTED(-2);

    private final int number;

    GRole(int number) {
        this.number = number;
    }

    /** The thesis's Table 3 number of this function (the checker's function number). */
    public int number() {
        return number;
    }

    /** A function gcnc names as not supported yet (E110). */
    public boolean unsupported() {
        return this == UNSUPPORTED;
    }

    /** G90/G94 (Fanuc B G77/G79): a single-pass cycle the checker expands into its four moves. */
    public boolean singleCycle() {
        return this == TURNING_SINGLE_CYCLE || this == FACING_SINGLE_CYCLE;
    }

    /** G32/G33, G92/G78 or G76: a thread the checker expands into spindle-synchronised passes. */
    public boolean thread() {
        return this == THREAD || this == THREAD_SINGLE_CYCLE || this == THREAD_CYCLE;
    }

    /** G70, G71, G72 or G73: a cycle the checker expands into moves along a contour. */
    public boolean contourCycle() {
        return this == FINISHING_CYCLE || this == TURNING_CYCLE || this == FACING_CYCLE || this == PATTERN_CYCLE;
    }

    /** G74 or G75: a peck cycle (grooving, parting, face peck drilling) the checker expands. */
    public boolean peckCycle() {
        return this == FACE_PECK_CYCLE || this == GROOVE_PECK_CYCLE;
    }

    /** G81-G86, G89 (G184): a drilling, tapping or boring cycle on the spindle axis, modal until G80. */
    public boolean drillCycle() {
        return this == DRILL_CYCLE || this == SPOT_DRILL_CYCLE || this == PECK_DRILL_CYCLE || tapCycle()
                || boreCycle();
    }

    /** G85, G86, G89: a boring cycle, the tool fed out of the hole (or, G86, the spindle stopped first). */
    public boolean boreCycle() {
        return this == BORE_CYCLE || this == BORE_STOP_CYCLE || this == BORE_DWELL_CYCLE;
    }

    /** G84/G184: a drilling cycle whose spindle reverses at the bottom. */
    public boolean tapCycle() {
        return this == TAP_CYCLE || this == REVERSE_TAP_CYCLE;
    }

    public boolean motion() {
        return number >= 0 && number <= 3;
    }

    /** The role named in a control's table ({@code arc_cw}), or null. */
    public static GRole named(String s) {
        for (GRole r : values()) {
            if (r.name().equalsIgnoreCase(s)) {
                return r;
            }
        }
        return null;
    }
}
