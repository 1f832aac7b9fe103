package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import gcnc.machine.ControllerLimits.Rounded;
import gcnc.machine.ControllerLimits.Violation;
import gcnc.machine.GalilModel.Limit;
import gcnc.tables.ErrorMessages;
import gcnc.tables.Tables;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.DoubleFunction;
import org.junit.jupiter.api.Test;

/**
 * Each limit of a DMC-4040 (tables/galil_models.csv) at its bound, just inside and just outside,
 * through the check the backend calls; the rounding of VA/VD, speeds and dwells; and every E22x
 * code as the report helper emits it.
 */
class ControllerLimitsTest {
    private static final GalilModels MODELS = GalilModels.builtIn();
    private static final ControllerLimits DMC4040 = new ControllerLimits(MODELS.find("DMC-4040").orElseThrow());

    /** The check each limit has, taking the value as the backend would hand it. */
    private static Map<Limit, DoubleFunction<Optional<Violation>>> checks(ControllerLimits c) {
        Map<Limit, DoubleFunction<Optional<Violation>>> m = new EnumMap<>(Limit.class);
        m.put(Limit.VECTOR_SPEED, v -> c.vectorSpeed((long) v));
        m.put(Limit.SEGMENT_SPEED, v -> c.cornerSpeed((long) v));
        m.put(Limit.ACCELERATION, v -> c.acceleration((long) v));
        m.put(Limit.SEGMENT_LENGTH, v -> c.segment((long) v, 0));
        m.put(Limit.ARC_RADIUS, v -> c.arcRadius((long) v));
        m.put(Limit.ARC_LENGTH, v -> c.arc(1000, v / 1000));
        m.put(Limit.DWELL, v -> c.dwell((long) v));
        m.put(Limit.LINE_LENGTH, v -> c.check(Limit.LINE_LENGTH, v));
        m.put(Limit.PROGRAM_LINES, v -> c.check(Limit.PROGRAM_LINES, v));
        m.put(Limit.LABELS, v -> c.check(Limit.LABELS, v));
        m.put(Limit.LABEL_LENGTH, v -> c.check(Limit.LABEL_LENGTH, v));
        m.put(Limit.VARIABLES, v -> c.check(Limit.VARIABLES, v));
        m.put(Limit.ARRAY_ELEMENTS, v -> c.check(Limit.ARRAY_ELEMENTS, v));
        m.put(Limit.SEQUENCE_LENGTH, v -> c.check(Limit.SEQUENCE_LENGTH, v));
        m.put(Limit.BUFFER_SEGMENTS, v -> c.check(Limit.BUFFER_SEGMENTS, v));
        return m;
    }

    /** The reference's bounds, written out here so that a wrong row in the table fails this test. */
    private static final Map<Limit, long[]> REFERENCE = Map.ofEntries(
            Map.entry(Limit.VECTOR_SPEED, new long[] {2, 15_000_000}),
            Map.entry(Limit.SEGMENT_SPEED, new long[] {2, 15_000_000}),
            Map.entry(Limit.ACCELERATION, new long[] {1024, 1_073_740_800}),
            Map.entry(Limit.SEGMENT_LENGTH, new long[] {0, 8_388_607}),
            Map.entry(Limit.ARC_RADIUS, new long[] {10, 6_000_000}),
            Map.entry(Limit.ARC_LENGTH, new long[] {0, 450_000_000}),
            Map.entry(Limit.DWELL, new long[] {2, 2_147_483_646}),
            Map.entry(Limit.LINE_LENGTH, new long[] {0, 80}),
            Map.entry(Limit.PROGRAM_LINES, new long[] {0, 2000}),
            Map.entry(Limit.LABELS, new long[] {0, 510}),
            Map.entry(Limit.LABEL_LENGTH, new long[] {0, 7}),
            Map.entry(Limit.VARIABLES, new long[] {0, 254}),
            Map.entry(Limit.ARRAY_ELEMENTS, new long[] {0, 16_000}),
            Map.entry(Limit.SEQUENCE_LENGTH, new long[] {0, 1L << 30}),
            Map.entry(Limit.BUFFER_SEGMENTS, new long[] {0, 511}));

    @Test
    void eachLimitAtJustInsideAndJustOutsideItsBounds() {
        Map<Limit, DoubleFunction<Optional<Violation>>> checks = checks(DMC4040);
        assertEquals(Limit.values().length, checks.size(), "every limit has its check");
        for (Limit l : Limit.values()) {
            long min = REFERENCE.get(l)[0];
            long max = REFERENCE.get(l)[1];
            DoubleFunction<Optional<Violation>> check = checks.get(l);
            // the top: the reference's "less than" limits refuse the bound itself
            assertEquals(l.below(), check.apply(max).isPresent(), l + " at its maximum " + max);
            assertTrue(check.apply(max - 1).isEmpty(), l + " just inside its maximum");
            Violation over = check.apply(max + 1).orElseThrow(() -> new AssertionError(l + " just past " + max));
            assertEquals(l, over.limit());
            assertEquals(l.code(), over.diagnostic(Span.of(1, 1)).code());
            // the bottom: counts start at 0; ranges that start higher refuse the value just under
            assertTrue(check.apply(min).isEmpty(), l + " at its minimum " + min);
            assertTrue(check.apply(min + 1).isEmpty(), l + " just inside its minimum");
            if (min > 0) {
                assertTrue(check.apply(min - 1).isPresent(), l + " just under its minimum " + min);
            }
        }
    }

    @Test
    void theThingsIssue19FoundPassingSilentlyAreNowCaught() {
        // G04 P1 became WT 1; the hires profile wrote VS 20000000 and VP -18500000,-10500000; CR 3 on thesis-2004
        assertEquals(Code.E226_DWELL_RANGE, DMC4040.dwell(1).orElseThrow().limit().code());
        assertEquals(Code.E220_VECTOR_SPEED_RANGE, DMC4040.vectorSpeed(20_000_000).orElseThrow().limit().code());
        assertTrue(DMC4040.segment(-18_500_000, -10_500_000).isPresent());
        assertEquals(Code.E224_ARC_RADIUS_RANGE, DMC4040.arc(3, 90).orElseThrow().limit().code());
    }

    @Test
    void aSegmentIsMeasuredAlongItsLengthNotPerAxis() {
        // 6,000,000 on each axis is within an axis's 8,388,607 but the segment is 8,485,281 long
        assertTrue(DMC4040.segment(8_388_607, 0).isEmpty());
        assertTrue(DMC4040.segment(0, -8_388_607).isEmpty());
        Violation v = DMC4040.segment(6_000_000, -6_000_000).orElseThrow();
        assertEquals(8_485_281, Math.floor(v.value()));
        assertTrue(DMC4040.segment(5_000_000, 5_000_000).isEmpty());
    }

    @Test
    void anArcIsRefusedByItsRadiusTimesItsDegreesEitherWay() {
        assertTrue(DMC4040.arc(1_250_000, 359.9).isEmpty());
        assertTrue(DMC4040.arc(1_250_000, 360).isPresent(), "1,250,000 x 360 = 450,000,000 is not below it");
        assertTrue(DMC4040.arc(1_250_000, -360).isPresent(), "a clockwise sweep counts its size");
        assertEquals(Limit.ARC_RADIUS, DMC4040.arc(6_000_001, 1).orElseThrow().limit(), "the radius first");
    }

    @Test
    void vaAndVdAreRoundedDownToAMultipleOf1024WithAWarning() {
        Rounded r = DMC4040.roundAcceleration(1_000_000); // the generic profile's VA
        assertTrue(r.changed());
        assertEquals(999_424, r.taken(), "976 x 1024: what the controller itself would take");
        Rounded exact = DMC4040.roundAcceleration(1_024_000);
        assertFalse(exact.changed());
        assertTrue(exact.diagnostic(Span.of(1, 1)).isEmpty(), "an exact value has no warning");
        assertEquals(19_456, DMC4040.roundAcceleration(20_000).taken(), "the reference's own example: VA 20000 reads 19456");
        assertEquals(1000, DMC4040.roundAcceleration(1000).taken(), "below one step: left for the range check");
        assertTrue(DMC4040.acceleration(DMC4040.roundAcceleration(1000).taken()).isPresent());
    }

    @Test
    void speedsRoundDownToEvenAndDwellsUp() {
        Rounded vs = DMC4040.roundSpeed(1667); // F100 at 1000 counts/mm
        assertEquals(1666, vs.taken());
        assertFalse(DMC4040.roundSpeed(1666).changed());
        Rounded wt = DMC4040.roundDwell(333); // G04 P333
        assertEquals(334, wt.taken(), "never a shorter dwell than programmed");
        assertFalse(DMC4040.roundDwell(334).changed());
        assertEquals(2, DMC4040.roundDwell(1).taken(), "G04 P1 rounds up to WT 2, the shortest the controller takes");
    }

    @Test
    void everyCodeIsEmittedThroughTheReportHelpers() {
        Diagnostics out = new Diagnostics();
        Span at = Span.of(7, 1);
        Map<Limit, DoubleFunction<Optional<Violation>>> checks = checks(DMC4040);
        for (Limit l : Limit.values()) {
            ControllerLimits.report(checks.get(l).apply(REFERENCE.get(l)[1] + 1), at, out);
        }
        ControllerLimits.report(DMC4040.roundAcceleration(1_000_000), at, out);
        ControllerLimits.report(DMC4040.roundSpeed(1667), at, out);
        ControllerLimits.report(DMC4040.roundDwell(333), at, out);
        ControllerLimits.report(DMC4040.vectorSpeed(5000), at, out); // inside: nothing
        ControllerLimits.report(DMC4040.roundSpeed(5000), at, out); // exact: nothing
        List<Diagnostic> all = out.sorted();
        for (int n = 220; n <= 237; n++) {
            Code c = Code.byNumber(n);
            Diagnostic d = all.stream().filter(x -> x.code() == c).findFirst()
                    .orElseThrow(() -> new AssertionError(c + " was not emitted"));
            assertEquals(n <= 234 ? Severity.ERROR : Severity.WARNING, d.severity(), c.toString());
            assertEquals(7, d.span().line());
        }
        assertEquals(18, all.size(), "nothing for a value inside its range or already on its step");
    }

    @Test
    void theMessagesNameTheValueTheRangeAndTheModelInBothLanguages() {
        ErrorMessages m = Tables.builtIn().messages();
        Diagnostic vs = DMC4040.vectorSpeed(20_000_000).orElseThrow().diagnostic(Span.of(12, 1));
        assertEquals("VS 20000000 is outside the DMC-4040's vector speed range 2 to 15000000 counts/s: the controller refuses it",
                m.render(vs.code(), vs.args(), ErrorMessages.Lang.EN));
        assertEquals("VS 20000000 está fuera del rango de velocidad vectorial de DMC-4040: de 2 a 15000000 cuentas/s;"
                + " el controlador lo rechaza", m.render(vs.code(), vs.args(), ErrorMessages.Lang.ES));
        Diagnostic va = DMC4040.roundAcceleration(1_000_000).diagnostic(Span.of(3, 1)).orElseThrow();
        assertEquals("acceleration 1000000 counts/s^2 is not a multiple of 1024: the DMC-4040 would take 999424 and gcnc"
                + " writes 999424", m.render(va.code(), va.args(), ErrorMessages.Lang.EN));
        assertEquals("VS 20000000 not in 2..15000000 (DMC-4040, galil_models.csv:" + DMC4040.model().row() + ")",
                DMC4040.vectorSpeed(20_000_000).orElseThrow().render());
    }

    @Test
    void firmware12aDoublesTheProgramLinesWhereTheReferenceSaysSo() {
        GalilModel old = MODELS.find("DMC-4040").orElseThrow();
        ControllerLimits newer = new ControllerLimits(old.withFirmware12a());
        assertTrue(DMC4040.check(Limit.PROGRAM_LINES, 2001).isPresent());
        assertTrue(newer.check(Limit.PROGRAM_LINES, 4000).isEmpty());
        assertTrue(newer.check(Limit.PROGRAM_LINES, 4001).isPresent());
        assertTrue(newer.check(Limit.ARRAY_ELEMENTS, 24_000).isEmpty());
        assertTrue(newer.check(Limit.ARRAY_ELEMENTS, 24_001).isPresent());
        // a model whose firmware numbering is not verified keeps the smaller memory
        ControllerLimits dmc2143 = new ControllerLimits(MODELS.find("DMC-2143").orElseThrow().withFirmware12a());
        assertTrue(dmc2143.check(Limit.PROGRAM_LINES, 2001).isPresent());
    }
}
