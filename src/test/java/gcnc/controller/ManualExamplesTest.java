package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Galil's own worked examples replayed on the virtual controller, expecting the manual's numbers
 * (tables/galil_conformance.csv, docs/galil-conformance.md): where a row of the table says "fine", its
 * example passes here. The quotes are COMALL's (the firmware command reference) unless a test says
 * otherwise. The AV and _CS examples belong to the fixes of those rows, not here.
 */
class ManualExamplesTest {
    private final StringWriter trace = new StringWriter();
    private final VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), trace);

    private String ok(String command) throws GalilException {
        return c.command(command);
    }

    private Tc rejected(String command) {
        return assertThrows(GalilException.class, () -> c.command(command), command).tc;
    }

    /** The kind and end point of each segment the controller executed ("VP 0 10000"), from its trace. */
    private List<String> ends() {
        return trace.toString().lines().filter(l -> !l.startsWith("#")).map(l -> {
            String[] f = l.split(" ");
            return f[2] + " " + f[3] + " " + f[4];
        }).toList();
    }

    private void plane() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        ok("VS 20000");
    }

    /**
     * DMC-40x0 user manual p.87 (M40x0-87): VP 0,10000 / CR 10000,180,-90 / VP 20000,20000, "the last
     * segment C to D 10000 long": VP targets are from the sequence's origin, CR's 180° start puts the
     * centre 10000 along +X of the arc's start, and the negative sweep runs clockwise.
     */
    @Test
    void vectorPositionsAreFromTheSequenceOriginAndArcsTurnAsTheManualDraws() throws GalilException {
        plane();
        ok("DP 5000,-3000");
        ok("VP 0,10000");
        ok("CR 10000,180,-90");
        ok("VP 20000,20000");
        ok("VE");
        ok("BGS");
        c.settle(20);
        // the sequence's origin is where it began (5000,-3000), not the controller's zero
        assertEquals(List.of("VP 5000 7000", "CR 15000 17000", "VP 25000 17000"), ends());
        assertEquals(" 101.0000\r\n", ok("MG _SCS"), "VE: \"VE is required to exit the vector mode gracefully (stop code, SC, 101)\"");
    }

    /** COMALL CR: "A starting position of zero degrees denotes that the radius lies along a vector following the positive X axis" (VMXY; CR 1000,0,270). */
    @Test
    void aCircleStartingAtZeroDegreesHasItsCentreOnTheNegativeXSide() throws GalilException {
        plane();
        ok("CR 1000,0,270");
        ok("VE");
        ok("BGS");
        c.settle(5);
        // centre (-1000,0); 270° counter-clockwise from 0° ends at (-1000,-1000)
        assertEquals(List.of("CR -1000 -1000"), ends());
        assertEquals(Tc.RANGE, rejected("CR 9,0,90"), "n0 min 10");
    }

    /** COMALL VA: ":VA 20000;' Set vector acceleration ... :VA ?;' Return vector acceleration ... 19456". */
    @Test
    void vectorAccelerationIsRoundedDownToItsResolution() throws GalilException {
        ok("VA 20000");
        assertEquals(19456, c.motion.va);
        ok("VA 1024");
        assertEquals(1024, c.motion.va);
        ok("VD 20000");
        assertEquals(19456, c.motion.vd);
        plane();
        ok("VP 100000,0");
        ok("VE");
        ok("BGS");
        assertEquals(Tc.WHILE_RUNNING, rejected("VD 40960"), "VD: Not Valid while in motion");
    }

    /**
     * COMALL TC: "GF32;' Bad command ... ? ... TC1;' Tell error code ... 1 Unrecognized command" and
     * "After TC has been read, the error code is set to zero. _TC contains the value of the error code.
     * Use of the operand does not clear the error code."
     */
    @Test
    void tcReportsOnceAndTheOperandDoesNotClear() throws GalilException {
        assertEquals(Tc.UNRECOGNIZED, rejected("GF32"));
        assertEquals(" 1.0000\r\n", ok("MG _TC"));
        assertEquals(" 1.0000\r\n", ok("MG _TC"), "the operand does not clear it");
        assertTrue(ok("TC1").matches("1\\s+Unrecognized command\r\n"), "code and text");
        assertEquals("0\r\n", ok("TC1"), "read once, set to zero");
        assertEquals(" 0.0000\r\n", ok("MG _TC"));
    }

    /**
     * COMALL XQ: "_XQn contains the current line number of execution for thread n, and -1 if thread t
     * is not running"; BK: "BK 3;' Pause at line 3 (the 4th line)" (lines count from 0); ED: "_ED0 contains
     * the line number of the last line to have an error. _ED1 contains the number of the thread".
     */
    @Test
    void threadLinesCountFromZeroAndMinusOneIsNotRunning() throws GalilException {
        assertEquals("-1.0000\r\n", ok("MG _XQ0"), "no program running");
        c.download(String.join("\r", "#START", "x=1", "y=2", "WT 100", "xx", "EN"), false);
        ok("XQ #START,0");
        c.advance(0.01);
        assertEquals(" 3.0000\r\n", ok("MG _XQ0"), "waiting at WT, the 4th line");
        c.advance(0.2);
        assertEquals("-1.0000\r\n", ok("MG _XQ0"), "xx stopped the program (no #CMDERR)");
        assertEquals(" 4.0000\r\n", ok("MG _ED"), "the bad line, the 5th");
        assertEquals(" 0.0000\r\n", ok("MG _ED1"), "in thread 0");
        assertEquals(" 1.0000\r\n", ok("MG _TC"));
    }

    /**
     * COMALL MG: ":MG arr[0],arr[1],arr[2] ... 0.0000 1.0000 2.0000", ":MG 1+2 ... 3.0000"; GR's example
     * output for MG _RPA,_RPN: "-2000.0000 1000.0000"; TIME: an operand without underscore.
     */
    @Test
    void messagesPrintNumbersAsTheManualShowsThem() throws GalilException {
        ok("DM arr[3]");
        ok("arr[0]=0");
        ok("arr[1]=1");
        ok("arr[2]=2");
        assertEquals(" 0.0000 1.0000 2.0000\r\n", ok("MG arr[0],arr[1],arr[2]"));
        assertEquals(" 3.0000\r\n", ok("MG 1+2"));
        ok("ra=-2000");
        ok("rn=1000");
        assertEquals("-2000.0000 1000.0000\r\n", ok("MG ra,rn"));
        assertEquals(" 15.0000\r\n", ok("MG 10+5"));
        assertTrue(ok("MG TIME").matches(" \\d+\\.0000\r\n"), "TIME counts samples");
        // the manual has no example of a negative after another number (MG 5,-1): the table marks it silent
        assertEquals(" 5.0000-1.0000\r\n", ok("MG 5,-1"));
    }

    /** COMALL's @ function examples, each MG line as the reference prints it. */
    @Test
    void functionsAnswerTheReferenceExamples() throws GalilException {
        String[][] examples = {
            {"@ABS[-2147483647]", " 2147483647.0000"},
            {"@INT[1.2]", " 1.0000"}, {"@INT[-2.4]", "-2.0000"},
            {"@FRAC[1.2]", " 0.2000"}, {"@FRAC[-2.4]", "-0.4000"},
            {"@RND[1.2]", " 1.0000"}, {"@RND[1.6]", " 2.0000"}, {"@RND[-1.2]", "-1.0000"}, {"@RND[5.7]", " 6.0000"},
            {"@RND[-5.7]", "-6.0000"}, {"@RND[5.5]", " 6.0000"}, {"@RND[-5.5]", "-5.0000"},
            {"@SQR[2]", " 1.4142"}, {"@SQR[-2]", " 1.4142"},
            {"@SIN[0]", " 0.0000"}, {"@SIN[90]", " 1.0000"}, {"@SIN[180]", " 0.0000"}, {"@SIN[270]", "-1.0000"},
            {"@SIN[360]", " 0.0000"},
            {"@COS[0]", " 1.0000"}, {"@COS[90]", " 0.0000"}, {"@COS[180]", "-1.0000"}, {"@COS[270]", " 0.0000"},
            {"@COS[360]", " 1.0000"},
        };
        for (String[] e : examples) {
            assertEquals(e[1] + "\r\n", ok("MG " + e[0]), e[0]);
        }
    }

    /**
     * The commands COMALL marks "Not Valid in terminal" (EN, AI, MC, the trippoints) are refused from the
     * host with TC 2, and RS ("Not Valid in program") from a program with TC 3; CA takes S, not T here.
     */
    @Test
    void terminalAndProgramOnlyCommandsAreRefusedWhereTheReferenceSays() throws GalilException {
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("EN"));
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("RE"));
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("JP #A"));
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("AI 1"));
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("MC"));
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("WT 10"));
        c.download(String.join("\r", "#A", "RS", "EN"), false);
        ok("XQ #A");
        c.advance(0.01);
        assertEquals(" 3.0000 1.0000\r\n", ok("MG _TC,_ED"), "RS in a program: TC 3 at line 1");
        ok("CA S");
        assertEquals(Tc.S_OPERAND, rejected("CA T"), "gcnc uses S; T is not modelled");
        assertEquals(" 511.0000\r\n", ok("MG _LMS"));
        assertEquals("511\r\n", ok("LM ?"), "the free slots, as _LMS");
    }

    /**
     * The settings the virtual controller takes and does not model (OE, TL, AC, DC, SP in their axis
     * forms) are accepted, and the operands it answers for them read what a controller at rest reads.
     */
    @Test
    void acceptedSettingsAndTheOperandsOfARestingController() throws GalilException {
        ok("OE 1,1");
        ok("TL 5,5");
        ok("ACX=256000");
        ok("DCX=256000");
        ok("SPX=25000");
        ok("OF ,,2.5");
        ok("VS 3000");
        ok("VR 0.5");
        assertEquals(" 2.5000 3000.0000 0.5000 0.0000 0.0000\r\n", ok("MG _OFZ,_VSS,_VRS,_VPX,_RPX"));
        ok("DP 100,-20");
        assertEquals("100, -20, 0, 0\r\n", ok("RP"));
        assertEquals(" " + Model.ARRAYS + ".0000\r\n", ok("MG _DA"), "DA: \"_DA contains the total number of arrays available\"");
        // a new sequence after a stop: the manual does not say ST empties the buffer, the controller here does
        plane();
        ok("VP 100000,0");
        ok("VE");
        ok("BGS");
        c.advance(0.05);
        ok("ST S");
        c.settle(5);
        assertEquals(" 511.0000 4.0000\r\n", ok("MG _LMS,_SCS"), "stopped by ST (stop code 4), buffer empty");
    }
}
