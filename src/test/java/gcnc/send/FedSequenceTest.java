package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Session;
import gcnc.machine.MachineProfile;
import java.io.BufferedReader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Where the program form looks for a starvation (E890): the controller's lines that lie wholly inside a
 * sequence fed while it runs, past its BGS and before its VE, where thread 0 stands only while the
 * sequence must be moving. A line holding the BGS (the thread may stand before it) or the VE (it may be
 * past it, at a normal end), a sequence that fits (VE before BGS) and the wait-for-room routine after
 * the program's EN are none.
 */
class FedSequenceTest {
    static final List<String> DMC = List.of("#GCNC", "SH XY", "VM XY", "VA 2000000", "VD 2000000",
            "VS 1000", "VP 1000,0", "VP 2000,0", "BGS", "VP 3000,0", "JS #LMWAIT", "VP 3500,0", "JS #LMWAIT",
            "VP 4000,0", "VE", "AMS",
            "VS 500", "VP 5000,0", "VE", "BGS", "AMS", "EN",
            "#LMWAIT", "JP #LMWAIT,_LMS<101", "EN");
    static final String MAP = "# source part.nc\n1 0\n6 4\n7 5\n8 6\n10 7\n12 8\n14 9\n17 10\n22 0\n";

    @Test
    void onlyTheLinesBetweenAFedSequencesBgsAndItsVeAreFed() throws Exception {
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        DmcProgram p = DmcProgram.read(DMC, MapReader.read(new BufferedReader(new StringReader(MAP))), haas);
        Download whole = Download.whole(p);
        List<String> fed = new ArrayList<>();
        for (int i = 0; i < whole.lines().size(); i++) {
            fed.add(whole.lines().get(i) + " -> " + whole.fedSequenceOn(i, p));
        }
        int vs = DMC.indexOf("VS 1000"); // one command a line in DMC: its index is the command's in the piece
        assertEquals(List.of(
                "#GCNC;SH XY;VM XY;VA 2000000;VD 2000000;VS 1000;VP 1000,0;VP 2000,0;BGS -> -1",
                "VP 3000,0;JS #LMWAIT -> " + vs,
                "VP 3500,0;JS #LMWAIT -> " + vs,
                "VP 4000,0;VE;AMS -> -1",
                "VS 500;VP 5000,0;VE;BGS;AMS -> -1",
                "EN -> -1",
                "#LMWAIT;JP #LMWAIT,_LMS<101 -> -1",
                "EN -> -1"), fed);
        assertEquals(-1, whole.fedSequenceOn(whole.lines().size(), p), "beyond the piece");
        assertEquals(-1, whole.fedSequenceOn(-1, p), "thread 0 not running");
    }
}
