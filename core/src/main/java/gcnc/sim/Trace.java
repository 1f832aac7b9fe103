package gcnc.sim;

import gcnc.dmc.DmcPrinter;
import gcnc.dmc.Instruction;
import gcnc.machine.MachineProfile;
import java.io.IOException;

/**
 * The --trace listing: each directive with the G-code line it came from, the machine position
 * after it (machine mm, X as the machine axis) and the outputs that are on. Streams; the first
 * write error stops it (the caller owns the sink and sees its own error).
 */
final class Trace {
    private final Appendable sink;
    private final double kx;
    private final double kz;
    private boolean broken;

    Trace(Appendable sink, MachineProfile p) {
        this.sink = sink;
        this.kx = p.x().countsPerMm();
        this.kz = p.z().countsPerMm();
    }

    void line(Instruction l, double x, double z, int tool, String outputs) {
        if (broken) {
            return;
        }
        try {
            sink.append(DmcPrinter.print(l.command())).append("\t; L").append(Integer.toString(l.source().line()))
                    .append(" X").append(MotionChecks.mm(x / kx)).append(" Z").append(MotionChecks.mm(z / kz))
                    .append(" T").append(Integer.toString(tool)).append(" outputs ").append(outputs).append('\n');
        } catch (IOException e) {
            broken = true;
        }
    }
}
