package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The stream form's resident program (spec/galil-controller.md §6.4, with numbers for its placeholders)
 * on the virtual controller: #AUTO after a reset sets the axes up and starts the segment-synchronised
 * output helper in thread 2; the host streams segments and asks for an output at segment 4; a dwell in
 * thread 1; a command error goes to #CMDERR, which stops the sequence.
 */
class ResidentProgramTest {
    static final List<String> RESIDENT = List.of("#AUTO", "CW1", "JS #SETUP", "XQ #MQ,2", "EN",
            "#SETUP", "SH XY", "KPC=0;KIC=0;KDC=0;ERC=-1", "SH C", "OFC=0", "IT 1", "OE 1,1,0",
            "BLX=-100000;BLY=-100000", "FLX=100000;FLY=100000", "mqseg=-1", "homed=0", "EN",
            "#MQ", "JP #MQ,mqseg<0", "#MQW", "JP #MQW,_CSS<mqseg", "OB mqbit,mqval", "mqseg=-1", "JP #MQ",
            "#DWELL", "WT dwms", "EN",
            "#BAD", "VP 1", "EN",
            "#CMDERR", "MG \"ERR \",_ED{F2.0},\" \",_TC{F1.0}", "ST S", "OFC=0;CB 1", "EN",
            "#LIMSWI", "MG \"LIM\",_SCX,_SCY", "ST S", "OFC=0;CB 1", "RE",
            "#POSERR", "MG \"POSERR\"", "ST S;OFC=0;CB 1", "RE");

    private final VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null);
    private final StringBuilder unsolicited = new StringBuilder();

    ResidentProgramTest() throws GalilException {
        c.download(String.join("\r\n", RESIDENT) + "\r\n", false);
        c.addListener(bytes -> {
            for (byte b : bytes) {
                assertTrue((b & 0x80) != 0, "CW1: unsolicited bytes carry the high bit");
                unsolicited.append((char) (b & 0x7F));
            }
        });
        c.command("RS");
        c.advance(0.01);
    }

    @Test
    void autoSetsUpAndTheHelperSwitchesAnOutputAtItsSegment() throws GalilException {
        assertEquals("-1.0000\r\n", c.command("MG _XQ0"), "#AUTO has ended");
        String mq = c.command("MG _XQ2");
        assertTrue(mq.equals(" 17.0000\r\n") || mq.equals(" 18.0000\r\n"), "#MQ loops on its first lines: " + mq);
        assertEquals(" 0.0000 0.0000\r\n", c.command("MG _MOX,_MOC"), "SH XY, SH C");
        c.command("VM XY");
        c.command("VS 20000");
        for (int i = 1; i <= 8; i++) {
            c.command("VP " + 1000 * i + ",0");
        }
        c.command("mqbit=3");
        c.command("mqval=1");
        c.command("mqseg=4");
        c.command("VE");
        c.command("BGS");
        boolean sawOff = false;
        while (c.moving()) {
            c.advance(0.001);
            int css = c.motion.css();
            if (css < 4) {
                assertFalse(c.output(3), "output 3 before segment 4 (css " + css + ")");
                sawOff = true;
            }
        }
        assertTrue(sawOff);
        assertTrue(c.output(3), "the helper set it when _CSS reached 4");
        assertEquals("-1.0000\r\n", c.command("MG mqseg"), "and went back to waiting");
    }

    @Test
    void aDwellThreadWaitsItsMilliseconds() throws GalilException {
        c.command("dwms=500");
        c.command("XQ #DWELL,1");
        c.advance(0.45);
        assertEquals(" 25.0000\r\n", c.command("MG _XQ1"));
        c.advance(0.1);
        assertEquals("-1.0000\r\n", c.command("MG _XQ1"));
    }

    @Test
    void aCommandErrorGoesToCmderrWhichStopsTheSequence() throws GalilException {
        c.command("VM XY");
        c.command("VS 20000");
        c.command("VP 100000,0");
        c.command("VE");
        c.command("BGS");
        c.command("SB 1");
        c.advance(0.2);
        c.command("XQ #BAD,3");
        c.settle(3);
        assertEquals("ERR 28 4\r\n", unsolicited.toString(), "line 28 (VP 1), TC 4 (operand error)");
        assertEquals(" 4.0000\r\n", c.command("MG _SCS"), "#CMDERR's ST S stopped the sequence");
        assertTrue(c.position(0) < 100000, "before its end: " + c.position(0));
        assertFalse(c.output(1), "and switched the spindle's output off");
    }
}
