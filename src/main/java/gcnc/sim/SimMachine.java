package gcnc.sim;

import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.tables.TableException;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * The simulator's machine model, read from the keys the simulator owns in a machine profile
 * (docs/simulator.md lists them). Everything here is in counts, in the half-section (z, r) with
 * r the radius from the spindle centreline. Absent chuck/tailstock/stock keys switch the matching
 * check off.
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

    /** A tool's outline relative to its tip: insert and holder, each convex. */
    public record ToolShape(Shape insert, Shape holder) {
        Shape[] parts() {
            return holder == null ? new Shape[] {insert} : new Shape[] {insert, holder};
        }
    }

    public ToolShape tool(int n) {
        return tools.getOrDefault(n, defaultTool);
    }

    public static SimMachine read(MachineProfile p) throws TableException {
        ProfileFile f = p.file();
        double kx = p.x().countsPerMm();
        double kz = p.z().countsPerMm();
        double centre = f.number("sim.centre_x", 0) * kx;
        Shape[] chuck = new Shape[0];
        double face = Double.NaN;
        if (f.entry("chuck.face_z").isPresent()) {
            face = f.number("chuck.face_z") * kz;
            double jawR = positive(f, "chuck.jaw_diameter") / 2 * kx;
            double jawL = positive(f, "chuck.jaw_length") * kz;
            double bodyR = positive(f, "chuck.diameter") / 2 * kx;
            double far = 1e12;
            chuck = new Shape[] {Shape.rect(face - jawL, 0, face, jawR), Shape.rect(-far, 0, face - jawL, bodyR)};
        }
        Shape[] tail = new Shape[0];
        if (f.entry("tailstock.centre_z").isPresent()) {
            double cz = f.number("tailstock.centre_z") * kz;
            double qr = positive(f, "tailstock.quill_diameter") / 2 * kx;
            // The centre's 60-degree cone, then the quill.
            double cone = qr * Math.tan(Math.toRadians(30));
            tail = new Shape[] {new Shape(new double[] {cz, cz + cone, cz + cone}, new double[] {0, qr, 0}),
                    Shape.rect(cz + cone, 0, 1e12, qr)};
        }
        Optional<StockSize> stock = Optional.empty();
        if (f.entry("stock.diameter").isPresent()) {
            if (Double.isNaN(face)) {
                throw f.fault(f.required("stock.diameter"), "stock.stickout is measured from chuck.face_z: give the chuck too");
            }
            stock = Optional.of(new StockSize(positive(f, "stock.diameter"), positive(f, "stock.length"),
                    positive(f, "stock.stickout")));
        }
        ToolShape def = toolShape(f, "sim.tool.default", kx, kz,
                new ToolShape(new Shape(new double[] {0}, new double[] {0}), null));
        Map<Integer, ToolShape> tools = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("sim.tool.")) {
            String rest = e.key().substring("sim.tool.".length());
            int dot = rest.indexOf('.');
            String id = dot < 0 ? rest : rest.substring(0, dot);
            if (id.equals("default") || tools.containsKey(parseTool(f, e, id))) {
                continue;
            }
            int n = parseTool(f, e, id);
            tools.put(n, toolShape(f, "sim.tool." + n, kx, kz, def));
        }
        return new SimMachine(centre, chuck, face, tail, stock, tools, def);
    }

    private static int parseTool(ProfileFile f, ProfileFile.Entry e, String id) throws TableException {
        try {
            int n = Integer.parseInt(id);
            if (n >= 0) {
                return n;
            }
        } catch (NumberFormatException x) {
            // reported below
        }
        throw f.fault(e, "tool outlines are sim.tool.default.* or sim.tool.<n>.*, not '" + e.key() + "'");
    }

    private static ToolShape toolShape(ProfileFile f, String prefix, double kx, double kz, ToolShape otherwise)
            throws TableException {
        Optional<ProfileFile.Entry> named = f.entry(prefix);
        if (named.isPresent()) {
            otherwise = ToolLibrary.shape(named.get().value(), kx, kz);
            if (otherwise == null) {
                throw f.fault(named.get(), "'" + prefix + "' is a tool from the library: C, D or V and the inscribed"
                        + " circle (C 12.7), T and the edge (T 16), G or P and the width [and reach] (P 3), B and the"
                        + " bar diameter (B 16), not '" + named.get().value() + "'");
            }
        }
        Optional<ProfileFile.Entry> ins = f.entry(prefix + ".insert");
        Optional<ProfileFile.Entry> hol = f.entry(prefix + ".holder");
        for (ProfileFile.Entry e : f.withPrefix(prefix + ".")) {
            if (!e.key().equals(prefix + ".insert") && !e.key().equals(prefix + ".holder")) {
                throw f.fault(e, "a tool outline has '.insert' and '.holder' keys, not '" + e.key() + "'");
            }
        }
        Shape insert = ins.isPresent() ? polygon(f, ins.get(), kx, kz) : otherwise.insert();
        Shape holder = hol.isPresent() ? polygon(f, hol.get(), kx, kz) : otherwise.holder();
        return new ToolShape(insert, holder);
    }

    /** "dz, dx; dz, dx; ..." in mm from the tip (dx radial, + away from the centreline), convex. */
    private static Shape polygon(ProfileFile f, ProfileFile.Entry e, double kx, double kz) throws TableException {
        String[] pts = e.value().split(";");
        double[] z = new double[pts.length];
        double[] r = new double[pts.length];
        for (int i = 0; i < pts.length; i++) {
            String[] zr = pts[i].split(",");
            if (zr.length != 2) {
                throw f.fault(e, "'" + e.key() + "' is a list of 'dz, dx' points separated by ';'");
            }
            try {
                z[i] = Double.parseDouble(zr[0].trim()) * kz;
                r[i] = Double.parseDouble(zr[1].trim()) * kx;
            } catch (NumberFormatException x) {
                throw f.fault(e, "'" + pts[i].trim() + "' is not a 'dz, dx' point (" + e.key() + ")");
            }
        }
        if (!convex(z, r)) {
            throw f.fault(e, "'" + e.key() + "' must be a convex outline (split a concave one into insert and holder)");
        }
        return new Shape(z, r);
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

    private static double positive(ProfileFile f, String key) throws TableException {
        return f.positive(key);
    }
}
