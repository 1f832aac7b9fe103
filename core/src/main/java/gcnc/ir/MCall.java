package gcnc.ir;

/** A miscellaneous function that took effect in a block (the profile maps it to outputs). */
public record MCall(int code) {
    public String name() {
        return String.format("M%02d", code);
    }
}
