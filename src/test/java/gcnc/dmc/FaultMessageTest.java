package gcnc.dmc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The fault routines' messages as the controller prints them (MG "...",gline: the number with its decimals). */
class FaultMessageTest {
    @Test
    void aRoutinesMessageIsAFaultAtItsLine() {
        assertEquals(Optional.of(new FaultMessage.Fault("LIMIT SWITCH", 14)), FaultMessage.read("LIMIT SWITCH AT G-CODE LINE 14.0000"));
        assertEquals(Optional.of(new FaultMessage.Fault("SPINDLE NOT AT SPEED", 9)),
                FaultMessage.read(" SPINDLE NOT AT SPEED AT G-CODE LINE  9.0000 ")); // MG's leading blank
        assertEquals("POSITION ERROR AT G-CODE LINE 7", new FaultMessage.Fault("POSITION ERROR", 7).toString());
    }

    @Test
    void aProgramStopAndOtherTextAreNoFault() {
        assertEquals(Optional.empty(), FaultMessage.read("PROGRAM STOP AT G-CODE LINE 12.0000")); // M00 waits, it is no fault
        assertEquals(Optional.empty(), FaultMessage.read("HELLO"));
        assertEquals(Optional.empty(), FaultMessage.read("LIMIT SWITCH AT G-CODE LINE"));
        assertEquals(Optional.empty(), FaultMessage.read("LIMIT SWITCH AT G-CODE LINE 99999999999"));
    }
}
