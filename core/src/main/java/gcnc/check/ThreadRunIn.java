package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.check.geom.NumberText;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.List;

/**
 * The run-in a thread pass needs (docs/threading.md, "Run-in and run-out"), held against the whole
 * pass once a continuous G32 thread is joined: the Galil backend engages the gearing at once
 * ({@code GD 0}, COMALL GD: "0 engages gearing instantly"), so Z's commanded speed jumps to lead ×
 * r/min and the axis, which accelerates no faster than the profile's acceleration, lags the helix
 * until it has run v²/2a; after that the phase correction ({@code IP}, a move at Galil's default
 * AC of 256,000 counts/s², COMALL AC) takes back at most what Z runs in two servo samples. A pass
 * shorter than both together never cuts at its lead: E260, an error (the whole thread is the wrong
 * pitch). Where the material begins within a longer pass the checker does not know: the docs ask
 * for the distance before the part.
 */
final class ThreadRunIn {
    /** Galil's default AC (COMALL AC), which the phase correction's IP move runs at: counts/s². */
    static final double IP_ACCELERATION = 256_000;
    /** Two servo samples at Galil's default TM 1000 (COMALL MF's accuracy), seconds. */
    static final double TWO_SAMPLES = 0.002;

    private ThreadRunIn() {
    }

    /**
     * The Z distance, counts, a pass at {@code speed} counts/s needs before it runs on the helix:
     * v²/2a at the profile's {@code acceleration} (counts/s²), plus the distance Z runs while the
     * phase correction moves (a triangle of at most v × 2 samples at {@link #IP_ACCELERATION}).
     */
    static double needed(double speed, double acceleration) {
        double ramp = speed * speed / (2 * acceleration);
        double correction = speed * TWO_SAMPLES;
        return ramp + speed * 2 * Math.sqrt(correction / IP_ACCELERATION);
    }

    /** E260 at each block of {@code blocks} whose thread pass is shorter along Z than its run-in. */
    static void check(List<CheckedBlock> blocks, MachineProfile p, Diagnostics out) {
        for (CheckedBlock b : blocks) {
            for (Motion m : b.motions()) {
                Motion.Thread t = MotionKind.thread(m);
                if (t != null) {
                    check(b, t, p, out);
                }
            }
        }
    }

    private static void check(CheckedBlock b, Motion.Thread t, MachineProfile p, Diagnostics out) {
        double speed = t.lead() * t.rpm() / 60; // Z counts/s
        double need = needed(speed, p.acceleration());
        double given = Math.abs(t.to().z() - t.from().z());
        if (given >= need) {
            return;
        }
        double perMm = p.z().countsPerMm();
        // placed in the block's own file: a continuous G32 thread is joined, and checked, at its last pass
        out.report(Diagnostic.error(Code.E260_THREAD_RUN_IN, Span.of(b.line(), 1), NumberText.plain(given / perMm, 3),
                NumberText.plain(need / perMm, 3), NumberText.plain(speed / perMm * 60, 1),
                NumberText.plain(p.acceleration() / perMm, 0)).in(b.origin()));
    }
}
