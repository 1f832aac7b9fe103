package gcnc.machine;

import gcnc.ir.Point;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A lathe and its Galil controller, read from {@code tables/machines/<name>.machine}.
 * All positions and offsets are machine counts (the loader converts the file's millimetres);
 * the simulator's chuck, tailstock, stock and tool outlines are in {@link #model()}. Everything
 * here was checked when the profile was loaded ({@link ProfileLoader}).
 *
 * @param name            profile name
 * @param galilModel      the controller model (galil.model, default DMC-4040) and its limits ({@link GalilModels})
 * @param x               lathe X (radial) axis
 * @param z               lathe Z axis
 * @param diameterX       X and U are programmed as diameters (I is always a radius)
 * @param noPointMm       value of a whole number written without decimal point in G21, in mm
 *                        (1 = read literally as the thesis does; 0.001 = Fanuc least increment)
 * @param noPointInch     the same in G20, in inches
 * @param home            where the machine starts, and the G28 reference point, machine counts
 * @param rapidSpeed      G00 vector speed, counts/s
 * @param maxFeed         fastest cutting feed, counts/s
 * @param acceleration    vector acceleration, counts/s^2
 * @param deceleration    vector deceleration, counts/s^2
 * @param maxRpm          spindle speed the machine can reach
 * @param rpmPerVolt      spindle drive gain for OF
 * @param spindleAxis     Galil channel whose OF drives the spindle (thesis: the third, C)
 * @param rearToolPost    the tool post is behind the spindle centre (G02/G03 sense flips)
 * @param workOffsets     G54..G59 (keys 54..59), machine counts of the work zero
 * @param toolOffsets     offset number (1..) to tool offset, counts
 * @param tools           how many tools the turret holds (T numbers 1..tools)
 * @param outputs         M code to the Galil output directives it becomes (e.g. 3 -> [CB4, SB3])
 * @param feedPerF        counts/s per unit/min of F, when the machine is calibrated that way
 *                        (the thesis machine: VS = F x 20); 0 = from counts per mm or inch
 * @param file            the profile as written (its path, and each value's place)
 * @param control         the control the machine runs (what the program's words mean)
 * @param units           G20/G21 in force at power-up (Haas setting 9), from the profile or its control
 * @param machineZero     where G53 X0 Z0 is, machine counts (the reference point unless the profile says)
 * @param chuckByProgram  the program must close the chuck before it cuts (else the operator did)
 * @param model           the lathe's solid parts and the tools' outlines, for the simulator
 * @param spindleEncoder  the spindle encoder threads are geared to, or null when the machine has none
 * @param noses           offset number (1..) to the insert's nose radius and tip direction (key
 *                        {@code nose.N}); an offset without one has radius 0
 * @param threadChamfer   the chamfered pull-out of a G76/G92 pass under Haas M23 (keys
 *                        {@code thread.chamfer_leads}, {@code thread.chamfer_angle})
 * @param wear            the wear offsets, apart from the geometry in {@code toolOffsets} (keys
 *                        {@code wear.N}, the offsets file); the tool moves by both ({@link #appliedOffset})
 */
public record MachineProfile(String name, GalilModel galilModel, Axis x, Axis z, boolean diameterX,
                             double noPointMm, double noPointInch, Point home, double rapidSpeed,
                             double maxFeed, double acceleration, double deceleration, double maxRpm,
                             double rpmPerVolt, char spindleAxis, boolean rearToolPost,
                             Map<Integer, Point> workOffsets, Map<Integer, Point> toolOffsets, int tools,
                             Map<Integer, List<String>> outputs, double feedPerF, ProfileFile file,
                             Control control, Units units, Point machineZero, boolean chuckByProgram,
                             MachineModel model, SpindleEncoder spindleEncoder,
                             Map<Integer, Nose> noses, ThreadChamfer threadChamfer, ToolWear wear) {
    public MachineProfile {
        java.util.Objects.requireNonNull(wear);
        noses = Map.copyOf(noses);
        workOffsets = Map.copyOf(workOffsets);
        toolOffsets = Map.copyOf(toolOffsets);
        outputs = Map.copyOf(outputs);
    }

    /** The checks of every number gcnc hands this machine's controller ({@link #galilModel}'s limits). */
    public ControllerLimits controllerLimits() {
        return new ControllerLimits(galilModel);
    }

    /** The Galil channel of {@link #spindleAxis} (0 = A/X): the OF or gains that drive the spindle address it. */
    public int spindleChannel() {
        return Plane.channel(spindleAxis);
    }

    /** The spindle encoder threads are geared to; empty on a machine that cannot cut threads (E190). */
    public Optional<SpindleEncoder> encoder() {
        return Optional.ofNullable(spindleEncoder);
    }

    /** The nose of tool offset {@code n} (radius 0 when the profile gives none, or for offset 0). */
    public Nose nose(int n) {
        return noses.getOrDefault(n, Nose.NONE);
    }

    /**
     * Reference point {@code n} (2 to 4: Fanuc G30 P2-P4), from the profile's {@code reference.N =
     * x, z} in mm as {@code home} (checked inside the travel when the profile was loaded), machine
     * counts; empty when the profile names none.
     */
    public Optional<Point> reference(int n) {
        Optional<ProfileFile.Entry> e = file == null ? Optional.empty() : file.entry("reference." + n);
        if (e.isEmpty()) {
            return Optional.empty();
        }
        try {
            double[] v = file.pair(e.get());
            return Optional.of(new Point(v[0] * x.countsPerMm(), v[1] * z.countsPerMm()));
        } catch (gcnc.tables.TableException ex) {
            throw new IllegalStateException("reference." + n + " was checked when the profile was loaded", ex);
        }
    }

    public Optional<Point> workOffset(int g) {
        return Optional.ofNullable(workOffsets.get(g));
    }

    /** Tool offset {@code n}'s geometry ({@code tool.N}), machine counts; empty when the profile has no offset n. */
    public Optional<Point> toolOffset(int n) {
        return Optional.ofNullable(toolOffsets.get(n));
    }

    /**
     * Where tool offset {@code n} puts the tool, as a Fanuc or Haas control applies it: its geometry
     * plus its wear ({@link ToolWear#inCounts}), machine counts; empty when the profile has no offset n.
     */
    public Optional<Point> appliedOffset(int n) {
        return toolOffset(n).map(g -> {
            Point w = wear.inCounts(n, x, z, diameterX);
            return new Point(g.x() + w.x(), g.z() + w.z());
        });
    }

    /** The same machine with another wear table (a test cut's, {@code gcnc.TestCut}). */
    public MachineProfile withWear(ToolWear w) {
        return new MachineProfile(name, galilModel, x, z, diameterX, noPointMm, noPointInch, home, rapidSpeed,
                maxFeed, acceleration, deceleration, maxRpm, rpmPerVolt, spindleAxis, rearToolPost, workOffsets,
                toolOffsets, tools, outputs, feedPerF, file, control, units, machineZero, chuckByProgram,
                model, spindleEncoder, noses, threadChamfer, w);
    }

    /**
     * The same machine with the blank given for a run sticking out {@code mm} from the jaws: the
     * work offsets a shop sets on the blank's face ({@code work.G54 = 0, face}) follow it; pinned
     * ones stay. Unchanged when the stick-out is the profile's or no offset is on the face.
     */
    public MachineProfile withStickout(double mm) {
        MachineModel.WorkZero w = model.workZero();
        if (w.atFace().isEmpty() || model.chuck().isEmpty() || mm == w.stickout()) {
            return this;
        }
        Map<Integer, Point> work = new java.util.HashMap<>(workOffsets);
        double faceZ = (model.chuck().get().faceZ() + mm) * z.countsPerMm();
        for (int g : w.atFace()) {
            work.put(g, new Point(work.get(g).x(), faceZ));
        }
        return new MachineProfile(name, galilModel, x, z, diameterX, noPointMm, noPointInch, home, rapidSpeed,
                maxFeed, acceleration, deceleration, maxRpm, rpmPerVolt, spindleAxis, rearToolPost, work,
                toolOffsets, tools, outputs, feedPerF, file, control, units, machineZero, chuckByProgram,
                model.withStickout(mm), spindleEncoder, noses, threadChamfer, wear);
    }

    /**
     * The same machine with the optional stop switch {@code on} or off (M01 stops as M00 when on):
     * {@code gcnc run --optional-stop}, the studio's toggle, over the control's {@code stop.optional}.
     */
    public MachineProfile withOptionalStop(boolean on) {
        if (on == control.stop().optional()) {
            return this;
        }
        return new MachineProfile(name, galilModel, x, z, diameterX, noPointMm, noPointInch, home, rapidSpeed,
                maxFeed, acceleration, deceleration, maxRpm, rpmPerVolt, spindleAxis, rearToolPost, workOffsets,
                toolOffsets, tools, outputs, feedPerF, file, control.withOptionalStop(on), units, machineZero,
                chuckByProgram, model, spindleEncoder, noses, threadChamfer, wear);
    }

    public List<String> outputsFor(int m) {
        return outputs.getOrDefault(m, List.of());
    }
}
