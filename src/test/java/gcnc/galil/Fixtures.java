package gcnc.galil;

import gcnc.diag.Diagnostics;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.Axis;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/** Profiles and hand-built blocks for the backend tests. */
final class Fixtures {
    private Fixtures() {
    }

    static MachineProfile profile(String name) {
        try {
            return ProfileLoader.load(name, TableSource.builtIn(), Tables.builtIn());
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }

    /** {@code base} with other Galil letters and signs for lathe X and Z, starting at {@code home}. */
    static MachineProfile mapped(MachineProfile base, char xLetter, int xSign, char zLetter, int zSign, Point home) {
        Axis x = base.x();
        Axis z = base.z();
        return new MachineProfile(base.name() + "-variant", base.galilModel(),
                new Axis(xLetter, x.countsPerMm(), x.countsPerInch(), xSign, x.min(), x.max()),
                new Axis(zLetter, z.countsPerMm(), z.countsPerInch(), zSign, z.min(), z.max()),
                base.diameterX(), base.noPointMm(), base.noPointInch(), home, base.rapidSpeed(), base.maxFeed(),
                base.acceleration(), base.deceleration(), base.maxRpm(), base.rpmPerVolt(), base.spindleAxis(),
                base.rearToolPost(), base.workOffsets(), base.toolOffsets(), base.tools(), base.outputs(),
                base.feedPerF(), base.file(), base.control(), base.units(), base.machineZero(), base.chuckByProgram(),
                base.model(), base.spindleEncoder(), base.noses(), base.threadChamfer(), base.wear());
    }

    static CheckedBlock motions(int line, Point end, Motion... ms) {
        return new CheckedBlock(line, OptionalDouble.empty(), OptionalInt.empty(), List.of(), List.of(ms),
                List.of(), end);
    }

    static CheckedBlock mcalls(int line, Point end, int... codes) {
        List<MCall> before = new ArrayList<>();
        for (int c : codes) {
            before.add(new MCall(c));
        }
        return new CheckedBlock(line, OptionalDouble.empty(), OptionalInt.empty(), before, List.of(), List.of(), end);
    }

    static Motion.Linear rapid(Point from, Point to) {
        return new Motion.Linear(true, from, to, null);
    }

    /** Runs one program through a dialect and returns the texts of its lines. */
    static List<String> run(String dialect, MachineProfile p, Diagnostics d, CheckedBlock... blocks) {
        List<String> out = new ArrayList<>();
        java.util.function.Consumer<Instruction> sink = l -> out.add(l.text());
        Dialect g = Dialect.create(Dialect.Kind.of(dialect), p, d);
        g.begin(sink);
        for (CheckedBlock b : blocks) {
            g.block(b, sink);
        }
        g.end(sink);
        return out;
    }
}
