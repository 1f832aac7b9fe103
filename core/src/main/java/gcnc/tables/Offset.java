package gcnc.tables;

/** A row of Tables 8 and 9: an offset in X and Z (the thesis's Y column is dropped). */
public record Offset(double x, double z) {
    public static final Offset ZERO = new Offset(0, 0);
}
