package gcnc.ir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class ArcGeometryTest {
    // Quarter circles of radius 10 about (x=0, z=0), drawn with Z right and X up.
    // start(x,z), end(x,z), G02?, R, expected centre (x,z), expected sweep.
    @ParameterizedTest
    @CsvSource({
        "10,0,  0,10, true,  10,  0,0, -90",   // top -> right, clockwise
        "0,10,  10,0, false, 10,  0,0,  90",   // right -> top, counter-clockwise
        "0,10, -10,0, true,  10,  0,0, -90",   // right -> bottom, clockwise
        "-10,0, 0,-10, true, 10,  0,0, -90",   // bottom -> left, clockwise
        "0,-10, 10,0, true,  10,  0,0, -90",   // left -> top, clockwise
        "10,0,  0,10, false, -10, 0,0,  270",  // top -> right the long way round, counter-clockwise
        "10,0,  0,10, true,  -10, 10,10, -270" // R<0 clockwise: centre on the other side
    })
    void centreAndSweepInEveryQuadrant(double ax, double az, double bx, double bz, boolean cw, double r,
                                       double cx, double cz, double sweep) {
        Point a = new Point(ax, az);
        Point b = new Point(bx, bz);
        Point c = ArcGeometry.centreFromRadius(a, b, r, cw, 1e-9).orElseThrow();
        assertEquals(cx, c.x(), 1e-9);
        assertEquals(cz, c.z(), 1e-9);
        assertEquals(sweep, ArcGeometry.sweepDegrees(a, b, c, cw), 1e-9);
    }

    @Test
    void aRadiusTooSmallForTheChordHasNoCentre() {
        assertTrue(ArcGeometry.centreFromRadius(new Point(0, 0), new Point(0, 30), 10, true, 0.5).isEmpty());
    }

    @Test
    void aHalfCircleHasItsCentreOnTheChord() {
        Point c = ArcGeometry.centreFromRadius(new Point(0, 0), new Point(0, 20), 10, true, 1e-9).orElseThrow();
        assertEquals(0, c.x(), 1e-9);
        assertEquals(10, c.z(), 1e-9);
    }

    @Test
    void endPointErrorMeasuresDistanceFromTheCircle() {
        assertEquals(1, ArcGeometry.endPointError(new Point(10, 0), new Point(0, 11), Point.ORIGIN), 1e-12);
    }
}
