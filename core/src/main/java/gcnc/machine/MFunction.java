package gcnc.machine;

/**
 * A row of a control's M table (the thesis's Table 4): the code as the control writes it, its
 * group, the moment it is applied (1 start of block, 0 during, 99 end of block), what it does,
 * and whether the machine needs an output for it (E113 when the profile gives none).
 */
public record MFunction(int code, int group, int moment, MRole role, boolean needsOutput, String english,
                        String spanish) {
    /** Moments 0 and 1 go out before the block's motion, 99 after it (decision D2). */
    public boolean beforeMotion() {
        return moment != 99;
    }

    public String name() {
        return code < 10 ? "M0" + code : "M" + code;
    }
}
