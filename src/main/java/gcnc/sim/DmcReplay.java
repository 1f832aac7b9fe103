package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.galil.GalilLine;
import gcnc.machine.MachineProfile;
import java.io.BufferedReader;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * Replays a .dmc file by itself (a user's hand-edited program, or --trace): no G-code to compare
 * against, so conformance is off and a sequence counts as a rapid when its VS equals the
 * profile's rapid.speed. Findings are located at the G-code line when the file carries
 * {@code NO L<line>} source-map comments, else at the DMC line. Streams in chunks.
 */
public final class DmcReplay {
    private DmcReplay() {
    }

    public static SimReport replay(BufferedReader in, MachineProfile profile, SimOptions options,
                                   Diagnostics diagnostics) {
        Simulator sim = new Simulator(profile, options, diagnostics);
        List<GalilLine> chunk = new ArrayList<>();
        int dmcLine = 0;
        int source = -1;
        try {
            for (String l = in.readLine(); l != null; l = in.readLine()) {
                dmcLine++;
                String t = l.strip();
                if (t.startsWith("NO L")) {
                    source = sourceLine(t.substring(4), source);
                }
                chunk.add(new GalilLine(l, source > 0 ? source : dmcLine));
                if (chunk.size() == 1024) {
                    sim.replay(chunk);
                    chunk.clear();
                }
            }
        } catch (IOException e) {
            diagnostics.error(Code.E500_IO, Span.of(Math.max(1, dmcLine), 1), e.getMessage());
        }
        sim.replay(chunk);
        sim.end(List.of());
        return sim.report();
    }

    private static int sourceLine(String digits, int otherwise) {
        try {
            return Integer.parseInt(digits.strip());
        } catch (NumberFormatException e) {
            return otherwise;
        }
    }
}
