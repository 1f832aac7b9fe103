package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import org.junit.jupiter.api.Test;

/** The one map between machine counts and the Galil vector plane, read from the shipped profiles. */
class PlaneTest {
    private static Plane of(String profile) throws Exception {
        return Plane.of(ProfileLoader.load(profile, TableSource.builtIn(), Tables.builtIn()));
    }

    @Test
    void theThesisMachineHasXFirstAndBothSignsNegative() throws Exception {
        Plane p = of("thesis-2004");
        assertEquals(new Plane("XY", true, -1, -1), p);
        assertEquals(0, p.first());
        assertEquals(1, p.second());
        assertArrayEquals(new double[] {-300, -40}, p.galil(300, 40));
        assertArrayEquals(new double[] {300, 40}, p.machine(new double[] {-300, -40}));
        // (z, x) -> (-x, -z) is a reflection: a counter-clockwise arc in the drawing is clockwise in Galil's
        assertEquals(-1, p.handedness());
    }

    @Test
    void haasPutsZOnTheFirstChannel() throws Exception {
        Plane p = of("haas");
        assertEquals("XY", p.letters());
        assertFalse(p.xFirst());
        assertArrayEquals(new double[] {40, 300}, p.galil(300, 40));
        assertEquals(300, p.machineX(40, 300));
        assertEquals(40, p.machineZ(40, 300));
        assertEquals(1, p.handedness());
    }

    @Test
    void machineUndoesGalilWhicheverLatheAxisComesFirst() {
        for (Plane p : new Plane[] {new Plane("AC", true, 1, -1), new Plane("BD", false, -1, 1)}) {
            double[] g = p.galil(-123.5, 77.25);
            assertArrayEquals(new double[] {-123.5, 77.25}, p.machine(g), p.toString());
            assertEquals(g[0], p.galil1(-123.5, 77.25));
            assertEquals(g[1], p.galil2(-123.5, 77.25));
        }
    }

    @Test
    void sameChannelsTakesEitherOrderAndEitherAliasButOnlyUpperCase() {
        Plane p = new Plane("XY", true, 1, 1);
        assertTrue(p.sameChannels("XY"));
        assertTrue(p.sameChannels("BA"));
        assertFalse(p.sameChannels("xy"));
        assertFalse(p.sameChannels("XZ"));
        assertFalse(p.sameChannels("XYZ"));
        assertEquals(2, Plane.channel('C'));
        assertEquals(2, Plane.channel('Z'));
        assertEquals(7, Plane.channel('H'));
    }

    /** Galil's two names of a channel (A = X ... D = W, then E..H) are one index; anything else is none. */
    @Test
    void channelLettersAreOneIndexAndAnythingElseIsNone() {
        assertEquals(0, Plane.channel('A'));
        assertEquals(0, Plane.channel('X'));
        assertEquals(3, Plane.channel('W'));
        assertEquals(7, Plane.channel('H'));
        assertEquals(-1, Plane.channel('I'));
        assertEquals(-1, Plane.channel('x'), "upper case only, as the DMC names channels");
        assertEquals(-1, Plane.channel('1'));
        assertEquals('Z', Plane.letter(2));
        assertEquals('E', Plane.letter(4));
        assertTrue(Plane.sameChannel('B', 'Y'));
        assertFalse(Plane.sameChannel('I', 'I'), "no channel is not the same channel");
    }
}
