package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Phrase;
import gcnc.tables.TableException;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The lathe's solid parts as the simulator models them (docs/simulator.md): the spindle
 * centreline, the chuck, the tailstock, the default blank and the tools' outlines, in the
 * profile's millimetres (machine frame, X as a radius). They are read with the rest of the profile
 * so that a bad value is a fault at its line of the profile when gcnc starts, never an error
 * blamed on a line of the program in the middle of a simulation.
 *
 * @param centreX     machine X of the spindle centreline
 * @param chuck       the jaws and the body behind them; empty when the profile has no chuck
 * @param tailstock   the live centre and its quill; empty when there is none
 * @param stock       the default blank; empty when the profile gives none
 * @param stockHeader a program's stock-header comment may give the blank ({@code stock.header = use});
 *                    false for a profile whose frame is not real millimetres (thesis-2004)
 * @param defaultTool outline of a tool that has none of its own
 * @param tools       tool number to its own outline
 * @param workZero    which work offsets are the face of the blank ({@code work.G54 = 0, face})
 */
public record MachineModel(double centreX, Optional<Chuck> chuck, Optional<Tailstock> tailstock,
                           Optional<Blank> stock, boolean stockHeader, ToolOutline defaultTool,
                           Map<Integer, ToolOutline> tools, WorkZero workZero) {
    public MachineModel {
        tools = Map.copyOf(tools);
    }

    /**
     * The work offsets whose Z is the face of the blank, as a shop sets G54 by touching the face
     * ({@code work.G54 = 0, face}): at {@code chuck.face_z} + the stick-out, the profile's
     * {@code stock.stickout} until a run gives its own blank ({@code --stock D,L,S}).
     *
     * @param atFace   G numbers (54..59) whose Z follows the blank's face; empty: every offset is pinned
     * @param stickout the stick-out the face is at, mm from the jaws' face
     * @param given    the stick-out is the run's blank's, not the profile's (a note says so, E662)
     */
    public record WorkZero(java.util.Set<Integer> atFace, double stickout, boolean given) {
        public WorkZero {
            atFace = java.util.Set.copyOf(atFace);
        }
    }

    /** The same model with the face of the blank {@code stickout} mm in front of the jaws, given for a run. */
    public MachineModel withStickout(double stickout) {
        return new MachineModel(centreX, chuck, tailstock, stock, stockHeader, defaultTool, tools,
                new WorkZero(workZero.atFace(), stickout, true));
    }

    /** The value of a work offset's Z that puts it on the blank's face: {@code work.G54 = 0, face}. */
    public static final String FACE = "face";

    /** {@code face} (X 0) or {@code x, face}: a work offset whose Z is the blank's face. */
    static boolean atFace(String value) {
        String[] xz = value.split(",", -1);
        return xz.length == 1 && xz[0].trim().equalsIgnoreCase(FACE)
                || xz.length == 2 && xz[1].trim().equalsIgnoreCase(FACE);
    }

    /** The jaws (from {@code faceZ - jawLength} to {@code faceZ}) and the body behind them. */
    public record Chuck(double faceZ, double jawDiameter, double jawLength, double diameter) {
    }

    /** The live centre's tip on the axis at {@code centreZ}, then its quill toward +Z. */
    public record Tailstock(double centreZ, double quillDiameter) {
    }

    /** A blank sticking out {@code stickout} in front of the jaws' face; its back end is in the jaws. */
    public record Blank(double diameter, double length, double stickout, double bore) {
        /** A bar: no bore. */
        public Blank(double diameter, double length, double stickout) {
            this(diameter, length, stickout, 0);
        }
    }

    /** A convex polygon of (dz, dx) points from the tool tip; dx radial, + away from the centreline. */
    public record Outline(double[] dz, double[] dx) {
    }

    /** What a tool is, as far as the simulator's checks go. */
    public enum ToolKind {
        TURN, THREAD, GROOVE, PART, BORE,
        /** Drills, centre drills and taps work on the centreline along Z: their sides do not cut (E323). */
        DRILL, CENTRE_DRILL, TAP,
        /**
         * A bar puller (or stock stop): it grips or touches the bar and cuts nothing, so its moves
         * neither take stock nor count as cuts (a pull with the spindle stopped and the chuck open
         * is clean); the chuck and tailstock are still checked against its tip.
         */
        PULLER,
        /** An outline given point by point ({@code sim.tool.<n>.insert}): its back is not known. */
        OUTLINE,
        /** No outline at all: a point at the programmed tip (a profile with no tools). */
        TIP;

        public boolean axial() {
            return this == DRILL || this == CENTRE_DRILL || this == TAP;
        }
    }

    /**
     * A tool's insert and holder; {@code holder} is null when there is none (the tip-only default).
     * {@code back} lists the insert's edges that do not cut (edge i runs from corner i to corner
     * i + 1): the simulator reports material that such an edge meets first (E320, E323). The library
     * knows its shapes' backs; an outline given point by point has none, as its back is not known.
     *
     * @param kind what the tool is
     * @param name how the profile names it, for messages ({@code C 12.7}, {@code drill 10})
     * @param side 1: the tool works on the +X side of the spindle centreline (a turret); -1: on the
     *             -X side, as a gang lathe carries its tools (the outline is mirrored through the axis)
     */
    public record ToolOutline(Outline insert, Outline holder, int[] back, ToolKind kind, String name, int side) {
        public ToolOutline(Outline insert, Outline holder) {
            this(insert, holder, new int[0], ToolKind.OUTLINE, "outline", 1);
        }

        /** The same tool on the other side of the centreline ({@code side -x}) or under another name. */
        ToolOutline with(String newName, int newSide) {
            return new ToolOutline(insert, holder, back, kind, newName, newSide);
        }
    }

    private static final String[] CHUCK = {"chuck.face_z", "chuck.jaw_diameter", "chuck.jaw_length", "chuck.diameter"};
    private static final String[] TAILSTOCK = {"tailstock.centre_z", "tailstock.quill_diameter"};
    private static final String[] STOCK = {"stock.diameter", "stock.length", "stock.stickout"};
    private static final ToolOutline TIP_ONLY = new ToolOutline(new Outline(new double[] {0}, new double[] {0}), null,
            new int[0], ToolKind.TIP, "tip", 1);

    /** Reads and checks the simulator's keys of a profile whose other keys ProfileLoader has read. */
    static MachineModel read(ProfileFile f) throws TableException {
        Optional<Chuck> chuck = chuck(f);
        ToolOutline def = toolOutline(f, "sim.tool.default", TIP_ONLY);
        Optional<Blank> stock = stock(f, chuck);
        return new MachineModel(f.number("sim.centre_x", 0), chuck, tailstock(f, chuck), stock,
                f.choice("stock.header", "use", "use", "ignore").equals("use"), def, tools(f, def),
                workZero(f, chuck, stock));
    }

    /**
     * The work offsets given as {@code x, face}: their Z is the blank's face, which needs the chuck
     * (the face is measured from its jaws) and the profile's blank (its stick-out until a run gives one).
     */
    private static WorkZero workZero(ProfileFile f, Optional<Chuck> chuck, Optional<Blank> stock)
            throws TableException {
        java.util.Set<Integer> atFace = new java.util.TreeSet<>();
        for (ProfileFile.Entry e : f.withPrefix("work.")) {
            if (atFace(e.value())) {
                if (chuck.isEmpty() || stock.isEmpty()) {
                    throw f.fault(e, Phrase.WORK_AT_FACE.with(e.key()));
                }
                atFace.add(Integer.parseInt(e.key().substring("work.G".length())));
            }
        }
        return new WorkZero(atFace, stock.map(Blank::stickout).orElse(0.0), false);
    }

    /**
     * The chuck, if the profile has one. Its face must be short of the end of the Z travel: a
     * part is held in front of the jaws, and with the face at or past the end no tool could reach it.
     */
    private static Optional<Chuck> chuck(ProfileFile f) throws TableException {
        if (!given(f, CHUCK)) {
            return Optional.empty();
        }
        ProfileFile.Entry face = f.required("chuck.face_z");
        double faceZ = f.number(face);
        double zMax = f.pair("z.travel")[1];
        if (faceZ >= zMax) {
            throw f.fault(face, Phrase.CHUCK_FACE.with(written(faceZ), written(zMax)));
        }
        return Optional.of(new Chuck(faceZ, f.positive("chuck.jaw_diameter"), f.positive("chuck.jaw_length"),
                f.positive("chuck.diameter")));
    }

    /** The tailstock, if any; its centre's tip must be in front of the jaws, not inside them. */
    private static Optional<Tailstock> tailstock(ProfileFile f, Optional<Chuck> chuck) throws TableException {
        if (!given(f, TAILSTOCK)) {
            return Optional.empty();
        }
        ProfileFile.Entry centre = f.required("tailstock.centre_z");
        double z = f.number(centre);
        if (chuck.isPresent() && z <= chuck.get().faceZ()) {
            throw f.fault(centre, Phrase.TAILSTOCK_CENTRE.with(written(z),
                    written(chuck.get().faceZ())));
        }
        return Optional.of(new Tailstock(z, f.positive("tailstock.quill_diameter")));
    }

    /** The default blank, if any: measured from the chuck's face, and long enough to reach into the jaws. */
    private static Optional<Blank> stock(ProfileFile f, Optional<Chuck> chuck) throws TableException {
        if (!given(f, STOCK)) {
            return Optional.empty();
        }
        if (chuck.isEmpty()) {
            throw f.faultAtKey(f.required("stock.diameter"),
                    Phrase.STOCK_NEEDS_CHUCK.arg());
        }
        Blank b = new Blank(f.positive("stock.diameter"), f.positive("stock.length"), f.positive("stock.stickout"));
        if (b.stickout() >= b.length()) {
            throw f.fault(f.required("stock.stickout"), Phrase.STICKOUT.with(written(b.stickout()),
                    written(b.length())));
        }
        return Optional.of(b);
    }

    /**
     * Whether a group of keys that only make sense together is given: all of them (true) or none
     * (false). Part of one is a fault at the first key given, naming a missing one: a chuck without
     * its jaws is not a smaller chuck but a mistake.
     */
    private static boolean given(ProfileFile f, String... group) throws TableException {
        ProfileFile.Entry first = null;
        String missing = null;
        for (String key : group) {
            Optional<ProfileFile.Entry> e = f.entry(key);
            if (e.isPresent() && first == null) {
                first = e.get();
            } else if (e.isEmpty() && missing == null) {
                missing = key;
            }
        }
        if (first != null && missing != null) {
            throw f.faultAtKey(first, Phrase.KEYS_TOGETHER.with(first.key(), missing,
                    String.join(", ", group)));
        }
        return first != null;
    }

    /**
     * Per-station outlines: the tool table's ({@code station.N}, {@link ToolTable}) or the library
     * name's ({@code sim.tool.N}), not both; {@code sim.tool.N.insert}/{@code .holder} redraw either,
     * and a station that gives only an insert or a holder takes the other from the default.
     */
    private static Map<Integer, ToolOutline> tools(ProfileFile f, ToolOutline def) throws TableException {
        Map<Integer, ToolOutline> tools = new HashMap<>();
        Map<Integer, ToolTable.Station> stations = ToolTable.read(f);
        Map<Integer, String> ids = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("sim.tool.")) {
            String id = e.key().split("\\.")[2]; // ProfileKeys checked the form: sim.tool.<id>[.insert|.holder]
            if (id.equals("default")) {
                continue;
            }
            int n = Integer.parseInt(id);
            String before = ids.putIfAbsent(n, id);
            if (before != null && !before.equals(id)) {
                throw f.faultAtKey(e, Phrase.TOOL_AGAIN.with(e.key(), n, before));
            }
            ToolTable.Station station = stations.get(n);
            Optional<ProfileFile.Entry> named = f.entry("sim.tool." + id);
            if (station != null && named.isPresent()) {
                throw f.faultAtKey(named.get(), Phrase.STATION_TWICE.with(n, station.entry().key(), named.get().key()));
            }
            tools.put(n, toolOutline(f, "sim.tool." + id, station != null ? station.outline() : def));
        }
        for (ToolTable.Station s : stations.values()) {
            tools.putIfAbsent(s.number(), s.outline());
        }
        return tools;
    }

    private static ToolOutline toolOutline(ProfileFile f, String prefix, ToolOutline otherwise) throws TableException {
        Optional<ProfileFile.Entry> named = f.entry(prefix);
        if (named.isPresent()) {
            otherwise = ToolLibrary.shape(named.get().value());
            if (otherwise == null) {
                throw f.fault(named.get(), Phrase.TOOL_FROM_LIBRARY.with(prefix, named.get().value()));
            }
        }
        Optional<ProfileFile.Entry> insert = f.entry(prefix + ".insert");
        Optional<ProfileFile.Entry> holder = f.entry(prefix + ".holder");
        if (insert.isEmpty() && holder.isEmpty()) {
            return otherwise;
        }
        return new ToolOutline(insert.isPresent() ? outline(f, insert.get()) : otherwise.insert(),
                holder.isPresent() ? outline(f, holder.get()) : otherwise.holder(),
                insert.isPresent() ? new int[0] : otherwise.back(),
                insert.isPresent() ? ToolKind.OUTLINE : otherwise.kind(),
                insert.isPresent() ? "outline" : otherwise.name(), otherwise.side());
    }

    /** "dz, dx; dz, dx; ..." in mm from the tip, convex (the simulator's collision test needs it). */
    private static Outline outline(ProfileFile f, ProfileFile.Entry e) throws TableException {
        String[] points = e.value().split(";", -1);
        double[] dz = new double[points.length];
        double[] dx = new double[points.length];
        for (int i = 0; i < points.length; i++) {
            String[] zx = points[i].split(",", -1);
            if (zx.length != 2) {
                throw f.fault(e, Phrase.POINT_LIST.with(e.key(), "dz, dx"));
            }
            dz[i] = f.number(e, zx[0]);
            dx[i] = f.number(e, zx[1]);
        }
        if (!convex(dz, dx)) {
            throw f.fault(e, Phrase.CONVEX.with(e.key()));
        }
        return new Outline(dz, dx);
    }

    private static boolean convex(double[] z, double[] r) {
        int n = z.length;
        int sign = 0;
        for (int i = 0; i < n && n >= 3; i++) {
            int j = (i + 1) % n;
            int k = (i + 2) % n;
            double c = (z[j] - z[i]) * (r[k] - r[j]) - (r[j] - r[i]) * (z[k] - z[j]);
            int s = c > 0 ? 1 : c < 0 ? -1 : 0;
            if (s != 0 && sign != 0 && s != sign) {
                return false;
            }
            if (s != 0) {
                sign = s;
            }
        }
        return true;
    }
}
