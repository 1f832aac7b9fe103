package gcnc.sim;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.Tables;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/**
 * A tiny lathe for the simulator's tests: 1 count per mm so numbers read as they are, lathe Z on
 * Galil X (first plane channel), lathe X on Galil Y, signs +1. Chuck jaws z -20..0 up to r 40,
 * stock r 20 from z -20 to 100, tailstock centre at z 200 (quill r 15), home (90, 250).
 */
final class SimFixture {
    static final String PROFILE = """
            name = tiny
            z.galil = X
            x.galil = Y
            x.counts_per_mm = 1
            z.counts_per_mm = 1
            x.programming = radius
            x.travel = -2, 100
            z.travel = -50, 300
            home = 90, 250
            rapid.speed = 1000
            feed.max = 500
            vector.acceleration = 10000
            vector.deceleration = 10000
            spindle.max_rpm = 3000
            spindle.rpm_per_volt = 300
            spindle.axis = C
            m.3 = CB2, SB1
            m.4 = SB2, SB1
            m.5 = CB1
            m.10 = SB4
            m.11 = CB4
            chuck.face_z = 0
            chuck.jaw_diameter = 80
            chuck.jaw_length = 20
            chuck.diameter = 120
            stock.diameter = 40
            stock.length = 120
            stock.stickout = 100
            tailstock.centre_z = 200
            tailstock.quill_diameter = 30
            sim.tool.default.insert = 0, 0; 3, 0; 3, 6; 0, 6
            sim.tool.default.holder = 0, 6; 10, 6; 10, 20; 0, 20
            """;

    static final Feed FEED = new Feed(100, 100);

    final Diagnostics diagnostics = new Diagnostics();
    final Simulator sim;
    Point at = new Point(90, 250);
    int line = 1;

    SimFixture() throws Exception {
        this(PROFILE, SimOptions.defaults());
    }

    SimFixture(String profileText, SimOptions options) throws Exception {
        MachineProfile p = ProfileLoader.read(ProfileFile.parse("tiny.machine", profileText), Tables.builtIn());
        sim = new Simulator(p, options, diagnostics);
        sim.begin(lines(0, "#GCNC", "SH XY", "VM XY", "VA 10000", "VD 10000"));
    }

    static List<Instruction> lines(int source, String... text) {
        List<Instruction> out = new ArrayList<>();
        for (String t : text) {
            out.add(new Instruction(java.util.Objects.requireNonNull(gcnc.dmc.DmcReader.read(t, (code, args) -> {
                throw new IllegalArgumentException(code + " " + java.util.Arrays.toString(args));
            }), t), gcnc.dmc.Source.line(source)));
        }
        return out;
    }

    /** A block with the given motions and DMC (all DMC lines carry the block's line number). */
    void block(List<Motion> motions, String... dmc) {
        Point end = at;
        for (Motion m : motions) {
            if (m instanceof Motion.Linear l) {
                end = l.to();
            } else if (m instanceof Motion.Arc a) {
                end = a.to();
            }
        }
        // a line the reader refuses is reported as a replay of the file reports it (DmcReplay), and left out
        List<Instruction> read = new ArrayList<>();
        for (String t : dmc) {
            gcnc.dmc.Command c = gcnc.dmc.DmcReader.read(t, (code, args) -> sim.fault(gcnc.dmc.Source.line(line), code, args));
            if (c != null) {
                read.add(new Instruction(c, gcnc.dmc.Source.line(line)));
            }
        }
        sim.block(new CheckedBlock(line, OptionalDouble.empty(), OptionalInt.empty(), List.<MCall>of(), motions,
                List.<MCall>of(), end), read);
        at = end;
        line++;
    }

    /** Spindle on and chuck closed, as the profile's M11 and M03 outputs. */
    void start() {
        block(List.of(), "CB4", "CB2", "SB1");
    }

    /** A straight move to (x, z) with the DMC a backend would write for it. */
    void move(boolean rapid, double x, double z) {
        Point to = new Point(x, z);
        long dz = Math.round(z - at.z());
        long dx = Math.round(x - at.x());
        block(List.of(new Motion.Linear(rapid, at, to, rapid ? null : FEED)),
                "VS " + (rapid ? 1000 : 100), "VP " + dz + "," + dx, "VE", "BGS", "AMS");
    }

    List<String> codes() {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : diagnostics.sorted()) {
            out.add(d.code().id() + "@" + d.span().line());
        }
        return out;
    }
}
