package gcnc.galil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The examples of thesis-reading §7.3, each one pinned by Table 5.2 or by Delphi's rules. */
class DelphiFormatTest {
    @Test
    void anglesKeepThreeSignificantDigitsPaddedToFourDecimals() {
        assertEquals("46.8000", DelphiFormat.fmt3x4(46.77));
        assertEquals("5.4300", DelphiFormat.fmt3x4(5.4321));
        assertEquals("0.0123", DelphiFormat.fmt3x4(0.012345));
        assertEquals("-53.1000", DelphiFormat.fmt3x4(-53.13));
        assertEquals("360.0000", DelphiFormat.fmt3x4(360));
    }

    @Test
    void countsRoundHalfAwayFromZero() {
        assertEquals("5381", DelphiFormat.fmt8(5380.5));
        assertEquals("-5381", DelphiFormat.fmt8(-5380.5));
        assertEquals("1010", DelphiFormat.fmt8(1009.5));
        assertEquals("1040", DelphiFormat.fmt8(1039.5));
        assertEquals("15149", DelphiFormat.fmt8(15149));
        assertEquals("5380", DelphiFormat.fmt8(5380.4999));
    }

    @Test
    void negativeZeroPrintsWithoutSign() {
        assertEquals("0", DelphiFormat.fmt8(-0.0));
        assertEquals("0.0000", DelphiFormat.fmt3x4(-0.0));
        assertEquals("0", DelphiFormat.fmt8(-0.2), "a negative that rounds to zero prints 0 (reading §7.3 [REC])");
    }

    @Test
    void moreIntegerDigitsThanPrecisionDoNotFit() {
        assertTrue(DelphiFormat.fits(99_999_999, 8));
        assertFalse(DelphiFormat.fits(100_000_000, 8));
    }

    @Test
    void galilAnglesDropTrailingZerosAndVoltsKeepFourDecimals() {
        assertEquals("180", GalilNumbers.angle(180));
        assertEquals("-8.2132", GalilNumbers.angle(-8.21319));
        assertEquals("53.13", GalilNumbers.angle(53.13));
        assertEquals("0.0001", GalilNumbers.angle(0.00005));
        assertEquals("3.0000", GalilNumbers.volts(3));
        assertEquals(-3, GalilNumbers.round(-2.5));
        assertEquals(3, GalilNumbers.round(2.5));
    }
}
