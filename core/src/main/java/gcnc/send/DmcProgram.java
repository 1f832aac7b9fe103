package gcnc.send;

import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/**
 * The compiled program the sender downloads, read once: its lines, the G-code line each came from
 * (the source map), the motions it makes ({@link Sequence}) with their places in the plane, and how
 * long each line's work takes. Read from the DMC text the galil dialect writes
 * (docs/dmc-format.md), not from the compiler's objects, so that what is followed is exactly what
 * was downloaded and read back.
 */
public final class DmcProgram {
    private final List<String> lines;
    private final int[] sourceLines;
    private final String[] sourceFiles;
    private final List<Sequence> sequences;
    /** For each line, the index of the sequence it belongs to, or -1. */
    private final int[] sequenceOf;
    /** Seconds of the program's estimated time done when line i starts. */
    private final double[] secondsBefore;
    private final double totalSeconds;
    private final Plane plane;

    /**
     * The vector plane: the two Galil channels in channel order (A before B, as {@code VM} lists
     * them), which lathe axis each is, and their signs.
     *
     * @param first      channel index (A/X = 0 ... H = 7) of the plane's first channel
     * @param second     channel index of the second
     * @param xFirst     lathe X is the first channel (else lathe Z is)
     */
    public record Plane(int first, int second, boolean xFirst, int xSign, int zSign) {
        public static Plane of(MachineProfile p) {
            int x = channel(p.x().galil());
            int z = channel(p.z().galil());
            return new Plane(Math.min(x, z), Math.max(x, z), x < z, p.x().sign(), p.z().sign());
        }

        /** The channel index of a Galil axis letter: X Y Z W = A B C D = 0 1 2 3, E..H = 4..7. */
        public static int channel(char c) {
            return switch (Character.toUpperCase(c)) {
                case 'X' -> 0;
                case 'Y' -> 1;
                case 'Z' -> 2;
                case 'W' -> 3;
                default -> Character.toUpperCase(c) - 'A';
            };
        }

        /** Machine counts (lathe X as a radius, Z) of a point in Galil plane coordinates. */
        public double[] machine(double[] galil) {
            double x = (xFirst ? galil[0] : galil[1]) * xSign;
            double z = (xFirst ? galil[1] : galil[0]) * zSign;
            return new double[] {x, z};
        }

        /** Galil plane coordinates of machine counts. */
        public double[] galil(double x, double z) {
            double gx = x * xSign;
            double gz = z * zSign;
            return xFirst ? new double[] {gx, gz} : new double[] {gz, gx};
        }
    }

    private DmcProgram(List<String> lines, int[] sourceLines, String[] sourceFiles, List<Sequence> sequences,
                       int[] sequenceOf, double[] secondsBefore, double totalSeconds, Plane plane) {
        this.lines = lines;
        this.sourceLines = sourceLines;
        this.sourceFiles = sourceFiles;
        this.sequences = sequences;
        this.sequenceOf = sequenceOf;
        this.secondsBefore = secondsBefore;
        this.totalSeconds = totalSeconds;
        this.plane = plane;
    }

    /**
     * Reads a program.
     *
     * @param lines        the DMC, one directive a line
     * @param map          the source map read back ({@link MapReader})
     * @param profile      the machine it was compiled for: the plane, home, acceleration
     */
    public static DmcProgram read(List<String> lines, MapReader.Map map, MachineProfile profile) {
        Plane plane = Plane.of(profile);
        int n = lines.size();
        int[] source = new int[n];
        String[] files = new String[n];
        for (int i = 0; i < n; i++) {
            source[i] = map.line(i + 1);
            files[i] = map.file(i + 1);
        }
        Walker w = new Walker(plane, plane.galil(profile.home().x(), profile.home().z()), profile.acceleration());
        for (int i = 0; i < n; i++) {
            w.line(i, lines.get(i));
        }
        return new DmcProgram(List.copyOf(lines), source, files, Collections.unmodifiableList(w.sequences),
                w.sequenceOf(n), w.secondsBefore(n), w.seconds, plane);
    }

    public List<String> lines() {
        return lines;
    }

    public Plane plane() {
        return plane;
    }

    /** The G-code line a program line (0-based) came from; 0 for the header and footer. */
    public int sourceLine(int index) {
        return index >= 0 && index < sourceLines.length ? sourceLines[index] : 0;
    }

    /** The G-code file a program line came from when the map names one (a called program), else null. */
    public String sourceFile(int index) {
        return index >= 0 && index < sourceFiles.length ? sourceFiles[index] : null;
    }

    public List<Sequence> sequences() {
        return sequences;
    }

    /** The sequence line {@code index} belongs to, or null. */
    public Sequence sequenceAt(int index) {
        int s = index >= 0 && index < sequenceOf.length ? sequenceOf[index] : -1;
        return s < 0 ? null : sequences.get(s);
    }

    /** Estimated seconds of work done before line {@code index} starts. */
    public double secondsBefore(int index) {
        return index <= 0 ? 0 : index >= secondsBefore.length ? totalSeconds : secondsBefore[index];
    }

    public double totalSeconds() {
        return totalSeconds;
    }

    /** The first program line of the run of lines that came from the G-code line of line {@code index}. */
    public int blockStart(int index) {
        int s = sourceLine(index);
        int i = index;
        while (i > 0 && sourceLine(i - 1) == s) {
            i--;
        }
        return i;
    }

    /**
     * The G-code line of the block before the one line {@code index} belongs to (the last block
     * completed when {@code index} is executing), or 0 when there is none.
     */
    public int blockBefore(int index) {
        for (int i = blockStart(index) - 1; i >= 0; i--) {
            if (sourceLine(i) > 0) {
                return sourceLine(i);
            }
        }
        return 0;
    }

    /** The program lines (0-based) of the sequences of G-code line {@code line}, in order. */
    public List<Sequence> sequencesOf(int line) {
        List<Sequence> out = new ArrayList<>();
        for (Sequence s : sequences) {
            if (sourceLine(s.first()) == line) {
                out.add(s);
            }
        }
        return out;
    }

    /** The first program line that came from G-code line {@code line}, or -1. */
    public int firstLineOf(int line) {
        for (int i = 0; i < sourceLines.length; i++) {
            if (sourceLines[i] == line) {
                return i;
            }
        }
        return -1;
    }

    /** The labels the program declares ({@code #NAME} at a line's start). */
    public int labels() {
        int n = 0;
        for (String l : lines) {
            if (l.startsWith("#")) {
                n++;
            }
        }
        return n;
    }

    /** The variables the program assigns ({@code NAME=...}, lower or upper case, not an axis operand). */
    public List<String> variables() {
        java.util.Set<String> names = new java.util.TreeSet<>();
        for (String l : lines) {
            int eq = l.indexOf('=');
            if (eq > 0 && l.substring(0, eq).matches("[A-Za-z][A-Za-z0-9]{0,7}") && !l.substring(0, eq).matches("[A-Z]{2}[A-H]?")) {
                names.add(l.substring(0, eq));
            }
        }
        return List.copyOf(names);
    }

    /** The longest run of segments one sequence puts in the vector buffer. */
    public int mostSegments() {
        int m = 0;
        for (Sequence s : sequences) {
            m = Math.max(m, s.pieces().size());
        }
        return m;
    }

    /** The two letters of a DMC directive ({@code VP}, {@code SB}), upper case, or "" for a label or comment. */
    static String op(String line) {
        String t = line.strip();
        if (t.length() < 2 || t.startsWith("#") || t.startsWith("'")) {
            return "";
        }
        return t.substring(0, 2).toUpperCase(Locale.ROOT);
    }

    /** The comma-separated arguments after a directive's two letters; an empty one is NaN. */
    static double[] args(String line) {
        String t = line.strip().substring(2).strip();
        int speeds = t.indexOf('<') >= 0 ? t.indexOf('<') : t.indexOf('>');
        if (speeds >= 0) {
            t = t.substring(0, speeds).strip(); // a segment's own speeds (VP a,b <o >p) are not its arguments
        }
        if (t.isEmpty()) {
            return new double[0];
        }
        String[] f = t.split(",", -1);
        double[] v = new double[f.length];
        for (int i = 0; i < f.length; i++) {
            String s = f[i].strip();
            try {
                v[i] = s.isEmpty() ? Double.NaN : Double.parseDouble(s);
            } catch (NumberFormatException e) {
                v[i] = Double.NaN;
            }
        }
        return v;
    }

    /** Follows the program's geometry line by line, as the controller will move. */
    private static final class Walker {
        final Plane plane;
        final double acceleration;
        final List<Sequence> sequences = new ArrayList<>();
        final List<Integer> owner = new ArrayList<>();
        final List<Double> before = new ArrayList<>();
        double[] pos;
        double[] cursor;
        double speed;
        int first = -1;
        List<Sequence.Piece> pieces = new ArrayList<>();
        boolean thread;
        double seconds;

        Walker(Plane plane, double[] home, double acceleration) {
            this.plane = plane;
            this.pos = home.clone();
            this.cursor = home.clone();
            this.acceleration = acceleration > 0 ? acceleration : 256000;
        }

        void line(int i, String text) {
            before.add(seconds);
            owner.add(first >= 0 ? sequences.size() : -1);
            String op = op(text);
            switch (op) {
                case "VS" -> {
                    double[] a = args(text);
                    speed = a.length > 0 && !Double.isNaN(a[0]) ? a[0] : speed;
                    begin(i);
                }
                case "VP" -> {
                    begin(i);
                    double[] a = args(text);
                    double[] to = {pos[0] + a[0], pos[1] + a[1]};
                    pieces.add(new Sequence.Line(cursor, to));
                    cursor = to;
                }
                case "CR" -> {
                    begin(i);
                    double[] a = args(text);
                    double r = a[0];
                    double th = Math.toRadians(a[1]);
                    double d = Math.toRadians(a[2]);
                    double[] c = {cursor[0] - r * Math.cos(th), cursor[1] - r * Math.sin(th)};
                    double[] to = {c[0] + r * Math.cos(th + d), c[1] + r * Math.sin(th + d)};
                    pieces.add(new Sequence.Arc(cursor, to, c, r, a[1], a[2]));
                    cursor = to;
                }
                case "GA" -> {
                    begin(i);
                    thread = true;
                }
                case "PA" -> {
                    double[] a = args(text);
                    double p1 = plane.first() < a.length ? a[plane.first()] : Double.NaN;
                    double p2 = plane.second() < a.length ? a[plane.second()] : Double.NaN;
                    cursor = new double[] {Double.isNaN(p1) ? cursor[0] : p1, Double.isNaN(p2) ? cursor[1] : p2};
                }
                case "AM" -> end(i);
                default -> {
                }
            }
            if (op.equals("WT")) {
                double[] a = args(text);
                seconds += a.length > 0 && !Double.isNaN(a[0]) ? a[0] / 1000 : 0;
            }
            if (first >= 0 && owner.get(i) < 0) {
                owner.set(i, sequences.size());
            }
        }

        private void begin(int i) {
            if (first < 0) {
                first = i;
                cursor = pos.clone();
                pieces = new ArrayList<>();
                thread = false;
            }
        }

        private void end(int i) {
            if (first < 0) {
                return;
            }
            double length = 0;
            for (Sequence.Piece p : pieces) {
                length += p instanceof Sequence.Arc a ? Math.abs(a.radius() * Math.toRadians(a.delta()))
                        : Math.hypot(p.to()[0] - p.from()[0], p.to()[1] - p.from()[1]);
            }
            double t = 0;
            if (speed > 0 && length > 0) {
                // a trapezoid: the time to speed up and slow down, or a triangle on a short move
                double ramp = speed * speed / acceleration;
                t = length >= ramp ? length / speed + speed / acceleration : 2 * Math.sqrt(length / acceleration);
            }
            sequences.add(new Sequence(first, i, pos.clone(), cursor.clone(), thread ? 0 : speed,
                    thread ? List.of() : List.copyOf(pieces), t));
            for (int k = first; k <= i; k++) {
                owner.set(k, sequences.size() - 1);
            }
            seconds += t;
            pos = cursor.clone();
            first = -1;
        }

        int[] sequenceOf(int n) {
            int[] a = new int[n];
            for (int i = 0; i < n; i++) {
                a[i] = owner.get(i);
            }
            return a;
        }

        double[] secondsBefore(int n) {
            double[] a = new double[n];
            for (int i = 0; i < n; i++) {
                a[i] = before.get(i);
            }
            return a;
        }
    }
}
