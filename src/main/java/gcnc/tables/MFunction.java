package gcnc.tables;

/**
 * A row of Table 4: a miscellaneous function, its group and the moment it is applied
 * (1 start of block, 0 during, 99 end of block), with its texts.
 */
public record MFunction(int code, int group, int moment, String english, String spanish) {
    /** Moments 0 and 1 go out before the block's motion, 99 after it (decision D2). */
    public boolean beforeMotion() {
        return moment != 99;
    }

    public String name() {
        return String.format("M%02d", code);
    }
}
