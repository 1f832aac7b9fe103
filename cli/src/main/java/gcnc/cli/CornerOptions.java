package gcnc.cli;

import gcnc.sim.Corner;
import gcnc.sim.SimReport;
import java.math.BigDecimal;
import java.math.RoundingMode;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.Option;
import picocli.CommandLine.TypeConversionException;

/**
 * The corner report: {@code --corners N} lists the N slowest corners of the blended sequences after
 * the simulation's summary, where they are (file, line, N word), how fast the machine takes them and
 * why not faster (docs/galil.md, "The corner report"); the JSON report's {@code corners} holds the
 * same list. Without the option neither is written.
 */
final class CornerOptions {
    /** The most corners the simulator keeps (gcnc.sim.SlowestCorners). */
    static final int MOST = 100;

    @Option(names = "--corners", paramLabel = "N", converter = Count.class,
            description = "After the summary, list the N slowest corners (1 to " + MOST + "): where, how fast and why"
                    + " (the junction's angle, an arc's radius, a short segment, a reversal); also in the JSON report.")
    int corners;

    /** A count of 1 to {@link #MOST}. */
    static final class Count implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String value) {
            int n;
            try {
                n = Integer.parseInt(value.strip());
            } catch (NumberFormatException e) {
                throw new TypeConversionException("'" + value + "' is not a number of corners");
            }
            if (n < 1 || n > MOST) {
                throw new TypeConversionException(n + " corners: gcnc lists 1 to " + MOST);
            }
            return n;
        }
    }

    /** The report with the N slowest corners asked for (none without --corners): what the JSON gets. */
    SimReport kept(SimReport r) {
        return r.withCorners(r.corners(), corners);
    }

    /** Says the N slowest corners after the summary (nothing without --corners). */
    void say(SimReport r, String program, Reporter reporter) {
        if (corners == 0) {
            return;
        }
        Phrases p = reporter.phrases();
        java.util.List<Corner> list = kept(r).corners();
        if (list.isEmpty()) {
            reporter.say(p.get("corners.none"));
            return;
        }
        reporter.say(p.get("corners.heading", list.size()));
        for (Corner c : list) {
            String where = (c.file() == null ? program : c.file()) + ":" + c.line()
                    + (c.number() == null ? "" : " N" + c.number());
            reporter.say(p.get("corners.line", where, decimals(c.speedMmMin(), 1), decimals(c.feedMmMin(), 1),
                    why(c, p)));
        }
    }

    private static String why(Corner c, Phrases p) {
        String angle = decimals(c.angleDeg(), 1);
        return switch (c.why()) {
            case JUNCTION -> p.get("corners.junction", angle, decimals(c.deviationMm(), 4));
            case ARC -> p.get("corners.arc", decimals(c.radiusMm(), 3), angle);
            case ACCELERATION -> p.get("corners.acceleration", decimals(c.lengthMm(), 3), angle);
            case REVERSAL -> p.get("corners.reversal", angle);
        };
    }

    /** {@code v} with {@code n} decimals, half up (BigDecimal: String.format loads the locale data). */
    static String decimals(double v, int n) {
        return BigDecimal.valueOf(v).setScale(n, RoundingMode.HALF_UP).toPlainString();
    }
}
