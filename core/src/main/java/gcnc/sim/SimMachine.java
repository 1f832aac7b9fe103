package gcnc.sim;

import gcnc.machine.MachineModel;
import gcnc.machine.MachineProfile;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The simulator's machine model: the profile's {@link MachineModel} (docs/simulator.md lists
 * its keys) in counts, in the half-section (z, r) with r the radius from the spindle centreline.
 * Absent chuck/tailstock/stock keys switch the matching check off.
 *
 * @param centreX   machine X (counts) of the spindle centreline
 * @param chuck     jaw and body outlines, empty when the profile has no chuck keys
 * @param chuckFace z of the jaws' front face (stock stick-out is measured from it)
 * @param tailstock the quill outline, empty when there is no tailstock
 * @param stock     the default blank (diameter, length, stick-out), if the profile gives one
 * @param tools     tool number to outline (insert + holder), relative to the tip
 * @param defaultTool outline for tools without their own
 */
public record SimMachine(double centreX, Shape[] chuck, double chuckFace, Shape[] tailstock, Optional<StockSize> stock,
                         Map<Integer, ToolShape> tools, ToolShape defaultTool) {

    /**
     * A tool's outline relative to its tip: insert and holder, each convex, and the insert's edges
     * that do not cut ({@link MachineModel.ToolOutline#back}); what it is, its name in the profile,
     * and the side of the centreline it works on (1 = +X, -1 = -X, a gang lathe's).
     */
    public record ToolShape(Shape insert, Shape holder, int[] back, MachineModel.ToolKind kind, String name, int side) {
        Shape[] parts() {
            return holder == null ? new Shape[] {insert} : new Shape[] {insert, holder};
        }
    }

    public ToolShape tool(int n) {
        return tools.getOrDefault(n, defaultTool);
    }

    /** Whether the profile describes station {@code n} (station.N, sim.tool.N): else it is checked as the default. */
    public boolean described(int n) {
        return tools.containsKey(n);
    }

    /**
     * The model of a loaded profile in counts. It cannot fail: the profile's keys were checked
     * when it was loaded ({@link MachineModel}), so nothing about the machine is ever reported at a
     * line of the program.
     */
    public static SimMachine read(MachineProfile p) {
        MachineModel m = p.model();
        double kx = p.x().countsPerMm();
        double kz = p.z().countsPerMm();
        Shape[] chuck = new Shape[0];
        double face = Double.NaN;
        if (m.chuck().isPresent()) {
            MachineModel.Chuck c = m.chuck().get();
            face = c.faceZ() * kz;
            double jawL = c.jawLength() * kz;
            double far = 1e12;
            chuck = new Shape[] {Shape.rect(face - jawL, 0, face, c.jawDiameter() / 2 * kx),
                    Shape.rect(-far, 0, face - jawL, c.diameter() / 2 * kx)};
        }
        Shape[] tail = new Shape[0];
        if (m.tailstock().isPresent()) {
            double cz = m.tailstock().get().centreZ() * kz;
            double qr = m.tailstock().get().quillDiameter() / 2 * kx;
            // The centre's 60-degree cone, then the quill.
            double cone = qr * Math.tan(Math.toRadians(30));
            tail = new Shape[] {new Shape(new double[] {cz, cz + cone, cz + cone}, new double[] {0, qr, 0}),
                    Shape.rect(cz + cone, 0, 1e12, qr)};
        }
        Optional<StockSize> stock = m.stock().map(b -> new StockSize(b.diameter(), b.length(), b.stickout()));
        Shapes shapes = new Shapes(kx, kz);
        Map<Integer, ToolShape> tools = new HashMap<>();
        for (Map.Entry<Integer, MachineModel.ToolOutline> t : m.tools().entrySet()) {
            tools.put(t.getKey(), shapes.tool(t.getValue()));
        }
        return new SimMachine(m.centreX() * kx, chuck, face, tail, stock, tools, shapes.tool(m.defaultTool()));
    }

    /**
     * Outlines in counts; an outline shared by several tools (the default holder) becomes one
     * shape, as it was one outline in the profile.
     */
    private static final class Shapes {
        private final double kx;
        private final double kz;
        private final Map<MachineModel.Outline, Shape> done = new IdentityHashMap<>();

        Shapes(double kx, double kz) {
            this.kx = kx;
            this.kz = kz;
        }

        ToolShape tool(MachineModel.ToolOutline t) {
            return new ToolShape(shape(t.insert()), t.holder() == null ? null : shape(t.holder()), t.back(), t.kind(),
                    t.name(), t.side());
        }

        private Shape shape(MachineModel.Outline o) {
            return done.computeIfAbsent(o, k -> {
                double[] z = new double[k.dz().length];
                double[] r = new double[k.dx().length];
                for (int i = 0; i < z.length; i++) {
                    z[i] = k.dz()[i] * kz;
                    r[i] = k.dx()[i] * kx;
                }
                return new Shape(z, r);
            });
        }
    }
}
