package gcnc.dmc;

/** Galil's axis letters and the channel places per-axis commands put their values at. */
public final class Channels {
    /** The letter the reader gives each place: X Y Z W, then E..H. */
    private static final String LETTERS = "XYZWEFGH";

    private Channels() {
    }

    /** 0 for A or X, 1 for B or Y, 2 for C or Z, 3 for D or W, 4.. for E..H; -1 for any other character. */
    public static int index(char letter) {
        switch (letter) {
            case 'X': return 0;
            case 'Y': return 1;
            case 'Z': return 2;
            case 'W': return 3;
            default:
                return letter >= 'A' && letter <= 'H' ? letter - 'A' : -1;
        }
    }

    /** The letter the reader names a place by. */
    static char letter(int index) {
        return LETTERS.charAt(index);
    }

    /** Whether two letters name the same channel ({@code A} and {@code X}). */
    public static boolean same(char a, char b) {
        return index(a) >= 0 && index(a) == index(b);
    }
}
