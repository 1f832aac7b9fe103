package gcnc.controller;

import java.util.Locale;

/**
 * The Galil models the virtual controller can be: what {@code ^R^V} answers and the memory a sender's
 * pre-flight reads ({@code _DL}, {@code _UL}, {@code _DA}, {@code _DM}, the line count a DL may fill).
 *
 * <p>Numbers from the command reference (docs/virtual-controller.md, "Memory"): program lines 0-3,999 on
 * firmware 1.2a and later, 0-1,999 before; 510 labels; 16,000 array elements, 24,000 on 1.2a and later;
 * 511 vector-buffer slots. The variable and array-name counts of these models are not published (the
 * reference says to ask {@code _UL}/{@code _DA}); 510 and 30 are assumed.
 */
public enum Model {
    /** A 4-axis Accelera on current firmware: the default. */
    DMC4040("DMC4040 Rev 1.2d", 4, 8, 4000, 24000),
    /** The 3-axis Accelera of the generic profile: the two lathe axes and the spindle's channel. */
    DMC4030("DMC4030 Rev 1.2d", 3, 8, 4000, 24000),
    /** The 2-axis Accelera, enough for a lathe's two axes and no spindle channel. */
    DMC4020("DMC4020 Rev 1.2d", 2, 8, 4000, 24000),
    /** An 8-axis Accelera with 16 outputs. */
    DMC4080("DMC4080 Rev 1.2d", 8, 16, 4000, 24000),
    /** A firmware before 1.2a: half the program lines and 16,000 array elements (a smaller controller for tests). */
    DMC2143("DMC2143 Rev 1.0h", 4, 8, 2000, 16000);

    /** The reply to {@code ^R^V}: model and firmware revision. */
    public final String revision;
    final int axes;
    final int outputs;
    final int lines;
    final int arrayElements;
    static final int LABELS = 510;
    static final int VARIABLES = 510;
    static final int ARRAYS = 30;
    static final int SLOTS = 511;
    static final int LINE_CHARS = 80;

    Model(String revision, int axes, int outputs, int lines, int arrayElements) {
        this.revision = revision;
        this.axes = axes;
        this.outputs = outputs;
        this.lines = lines;
        this.arrayElements = arrayElements;
    }

    /** The model named (any case, with or without "DMC-"), or null. */
    public static Model named(String name) {
        String n = name.toUpperCase(Locale.ROOT).replace("-", "");
        for (Model m : values()) {
            if (m.name().equals(n)) {
                return m;
            }
        }
        return null;
    }
}
