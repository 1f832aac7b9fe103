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
 * The variables the pre-flight counts against the controller's free ones ({@link DmcProgram#variables}):
 * every variable the program assigns, a thread's phase errors ({@code gpu=(_TPC-gsp)*_GRX-...}) among them,
 * which the count left out while it tested four kinds of command by name.
 */
class ProgramVariablesTest {
    @Test
    void aThreadsSyncPointAndPhaseErrorsAreCounted() throws Exception {
        List<String> dmc = new ArrayList<>(ResumeTest.DMC);
        dmc.addAll(List.of("#THREAD", "gline=9", "gsp=(@INT[_TPC/4096]+1)*4096+2048", "gpu=(_TPC-gsp)*_GRX-(_RPX-35480)",
                "gpv=(_TPC-gsp)*_GRY-(_RPY-0)", "gdl=TIME+2000", "EN"));
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        DmcProgram p = DmcProgram.read(dmc, MapReader.read(new BufferedReader(new StringReader(ResumeTest.MAP))), haas);
        assertEquals(List.of("TOOL", "gdl", "gline", "gpu", "gpv", "gsp"), p.variables());
    }
}
