package gcnc.galil;

import java.util.ArrayList;
import java.util.List;

/**
 * A deliberately small, independent reading of the galil dialect's motion lines (tests only; it
 * shares nothing with the generator): VP is the end point relative to the sequence start, CR runs
 * radius r from start angle theta through delta degrees (0 along + first channel, CCW positive),
 * and at BGS the controller's whole-count position becomes the sequence's end, rounded.
 */
final class PathReader {
    private long u;
    private long v;
    private final List<long[]> ends = new ArrayList<>();

    PathReader(long u, long v) {
        this.u = u;
        this.v = v;
    }

    /** The position after each sequence, in Galil plane coordinates. */
    List<long[]> read(List<String> lines) {
        double cu = u;
        double cv = v;
        for (String line : lines) {
            if (line.length() > 80) {
                throw new AssertionError("line over 80 characters: " + line);
            }
            if (line.startsWith("VP ")) {
                String[] a = line.substring(3).split(",");
                cu = u + Long.parseLong(a[0]);
                cv = v + Long.parseLong(a[1]);
            } else if (line.startsWith("CR ")) {
                String[] a = line.substring(3).split(",");
                double r = Long.parseLong(a[0]);
                double t = Math.toRadians(Double.parseDouble(a[1]));
                double d = Math.toRadians(Double.parseDouble(a[2]));
                cu += r * (Math.cos(t + d) - Math.cos(t));
                cv += r * (Math.sin(t + d) - Math.sin(t));
            } else if (line.equals("BGS")) {
                u = Math.round(cu);
                v = Math.round(cv);
                cu = u;
                cv = v;
                ends.add(new long[] {u, v});
            }
        }
        return ends;
    }
}
