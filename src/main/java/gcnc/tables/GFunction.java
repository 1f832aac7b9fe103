package gcnc.tables;

/** A row of Table 3: a preparatory function, its modal group (0 = one-shot) and its texts. */
public record GFunction(int code, int group, String english, String spanish) {
    public boolean modal() {
        return group != 0;
    }

    public String name() {
        return String.format("G%02d", code);
    }
}
