package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The profile keys of the machine around the motion: defaults, each form, each fault at its line (E430-E434). */
class MachineIoTest {
    private static final Tables TABLES = Tables.builtIn();

    private static String generic() throws Exception {
        return Files.readString(Path.of("tables/machines/generic.machine"));
    }

    private static MachineProfile load(String text) throws TableException {
        return ProfileLoader.read(ProfileFile.parse("t.machine", text), TABLES);
    }

    @Test
    void withoutTheKeysTheSpindleIsTheOfOfItsAxisWaitedForTwoSecondsAndHomeIsChecked() throws Exception {
        MachineIo io = MachineIo.of(load(generic()));
        assertEquals(new MachineIo.SpindleDrive.Offset('C'), io.drive());
        assertEquals(new MachineIo.AtSpeed.Dwell(2), io.atSpeed());
        assertEquals(Optional.empty(), io.turret());
        assertEquals(new MachineIo.Homing.Position(0.01), io.homing());
    }

    @Test
    void eachFormReadsAsWhatItSays() throws Exception {
        MachineIo io = MachineIo.of(load(generic().replace("DMC-4030", "DMC-4080") + "spindle.output = AO 3005\nspindle.at_speed = 1.5s\n"
                + "turret.station_outputs = 9, 10, 11, 12\nturret.strobe = 13\nturret.in_position = 4\n"
                + "homing.check = IN 6\n"));
        assertEquals(new MachineIo.SpindleDrive.Analog(3005), io.drive());
        assertEquals(new MachineIo.AtSpeed.Dwell(1.5), io.atSpeed());
        assertEquals(new MachineIo.Turret(List.of(9, 10, 11, 12), 13, 4, 10), io.turret().orElseThrow());
        assertEquals(new MachineIo.Homing.Input(6), io.homing());
        assertEquals(new MachineIo.SpindleDrive.Offset('C'), MachineIo.of(load(generic() + "spindle.output = OF C\n")).drive());
        assertEquals(new MachineIo.AtSpeed.Input(3, 4), MachineIo.of(load(generic()
                + "spindle.at_speed = IN3\nspindle.at_speed_timeout = 4\n")).atSpeed());
        assertEquals(new MachineIo.AtSpeed.None(), MachineIo.of(load(generic() + "spindle.at_speed = none\n")).atSpeed());
    }

    @Test
    void aBadValueIsAFaultAtItsLine() throws Exception {
        String g = generic();
        assertFault(g + "spindle.output = OF D\n", "spindle.output", Code.E430_SPINDLE_OUTPUT, "write OF");
        assertFault(g + "spindle.output = AO 9000\n", "spindle.output", Code.E437_ANALOG_OUTPUT_RANGE, "1000 to 8999");
        // AO takes a Modbus device's analog output only, n0 1,000 to 8,999 (command reference AO)
        assertFault(g + "spindle.output = AO 1\n", "spindle.output", Code.E437_ANALOG_OUTPUT_RANGE, "1000 to 8999");
        assertFault(g + "spindle.output = AO 999\n", "spindle.output", Code.E437_ANALOG_OUTPUT_RANGE, "1000 to 8999");
        // @IN reads 1-8 on a 4-axis model (9-16 on 5-8 axes), 81-96 and 1,000-8,999 (command reference @IN)
        assertFault(g + "spindle.at_speed = IN 200\n", "spindle.at_speed", Code.E436_INPUT_RANGE, "1 to 8 on the DMC-4030");
        assertFault(g + "homing.check = IN 9\n", "homing.check", Code.E436_INPUT_RANGE, "1 to 8 on the DMC-4030");
        assertFault(g + "turret.station_outputs = 5, 6, 7, 8\nturret.strobe = 4\nturret.in_position = 97\n",
                "turret.in_position", Code.E436_INPUT_RANGE, "81 to 96");
        assertFault(g + "turret.station_outputs = 5, 6, 7, 8\nturret.strobe = 9\nturret.in_position = 4\n",
                "turret.strobe", Code.E424_OUTPUT_BEYOND_MODEL, "output 9 is not one of the 8 digital outputs of the DMC-4030");
        assertFault(g + "spindle.at_speed = soon\n", "spindle.at_speed", Code.E431_SPINDLE_AT_SPEED, "IN n");
        assertFault(g + "turret.strobe = 13\n", "turret.strobe", Code.E432_TURRET_INCOMPLETE,
                "turret.station_outputs is missing");
        assertFault(g + "turret.station_outputs = 5, 6, 7\nturret.strobe = 8\nturret.in_position = 4\n",
                "turret.station_outputs", Code.E433_TURRET_STATIONS, "3 outputs code the stations 1 to 7 but tools.count is 12");
        assertFault(g + "homing.check = yes\n", "homing.check", Code.E434_HOMING_CHECK, "write position");
    }

    private static void assertFault(String text, String key, Code code, String message) {
        TableException e = assertThrows(TableException.class, () -> load(text));
        assertEquals(code, e.diagnostic().code(), e.getMessage());
        if (code == Code.E436_INPUT_RANGE || code == Code.E437_ANALOG_OUTPUT_RANGE) {
            assertTrue(e.getMessage().contains(message), e.getMessage());
        }
        assertEquals(text.substring(0, text.lastIndexOf(key + " =")).split("\n", -1).length, e.diagnostic().span().line());
        assertTrue(e.english().contains(message), e.english());
    }
}
