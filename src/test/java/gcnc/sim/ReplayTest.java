package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.galil.GalilLine;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ReplayTest {
    static MachineProfile profile(String name) throws Exception {
        return ProfileLoader.load(name, TableSource.builtIn(), Tables.builtIn());
    }

    static List<String> codes(Diagnostics d) {
        List<String> out = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            out.add(x.code().id() + "@" + x.span().line());
        }
        return out;
    }

    /**
     * Table 5.2 replayed by itself on the thesis's machine: the three zero-sweep CRs (N240, N260,
     * N410) are flagged where they are; nothing else is wrong with the moves before the first of them.
     */
    @Test
    void thesisTableFiveTwoReplayedAlone() throws Exception {
        Diagnostics d = new Diagnostics();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(
                ReplayTest.class.getResourceAsStream("bishop.thesis.dmc"), StandardCharsets.UTF_8))) {
            SimReport r = DmcReplay.replay(in, profile("thesis-2004"), SimOptions.defaults(), d);
            assertTrue(r.sequences() > 50);
        }
        List<String> c = codes(d);
        long zero = c.stream().filter(s -> s.startsWith("E309")).count();
        assertEquals(3, zero, c.toString());
        int firstZero = d.sorted().stream().filter(x -> x.code().id().equals("E309")).findFirst().orElseThrow().span().line();
        assertTrue(d.sorted().stream().noneMatch(x -> x.span().line() < firstZero), c.toString());
    }

    @Test
    void sourceMapCommentsLocateFindings() throws Exception {
        Diagnostics d = new Diagnostics();
        String dmc = "#GCNC\nSH XY\nVM XY\nNO L12\nVS 100000\nFOO\nEN\n";
        DmcReplay.replay(new BufferedReader(new StringReader(dmc)), profile("generic"), SimOptions.defaults(), d);
        assertEquals(List.of("E300@12"), codes(d));
    }

    @Test
    void withoutSourceMapFindingsAreAtTheDmcLine() throws Exception {
        Diagnostics d = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader("#GCNC\nSH XY\nVM XY\nFOO 1\nEN\n")),
                profile("generic"), SimOptions.defaults(), d);
        assertEquals(List.of("E300@4"), codes(d));
    }

    @Test
    void shippedProfilesHaveASimulatorModel() throws Exception {
        for (String name : new String[] {"generic", "thesis-2004"}) {
            SimMachine m = SimMachine.read(profile(name));
            assertTrue(m.stock().isPresent(), name);
            assertEquals(2, m.chuck().length, name);
        }
    }
}
