package gcnc.check.geom;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.Feed;
import gcnc.ir.Letter;
import gcnc.machine.MachineProfile;

/**
 * F to a path speed in counts per second: G94/G98 units per minute, G95/G99 units per
 * revolution at the spindle speed of the move; a profile may calibrate F directly ({@code feed.per_f}). A feed above the profile's maximum is an error
 * (E103), not a silent clamp: the part would be cut slower than programmed. Per revolution
 * without any spindle speed is E104. A feed the controller cannot give at all (under one count
 * per second, VS 2 is Galil's slowest) is E207 here already, so check and compile give one verdict.
 */
public final class Feeds {
    private final MachineProfile p;
    /** The last feed made: most cutting blocks keep the feed of the one before, and it is a value. */
    private Feed last;

    public Feeds(MachineProfile p) {
        this.p = p;
    }

    /** The feed of a cutting move at {@code rpm}, or null after reporting. */
    public Feed feed(BlockDraft d, double rpm, Diagnostics out) {
        double f = d.next.feed;
        // counts/s for one unit/min of F: the machine's own calibration, else its encoder scale
        double perUnitPerMin = p.feedPerF() > 0 ? p.feedPerF() : p.z().countsPer(d.units) / 60;
        Span at = d.has(Letter.F) ? d.word(Letter.F).span() : d.blame();
        double cps;
        if (d.next.feedPerRev) {
            if (!(rpm > 0)) {
                d.fail(out, Code.E104_FEED_PER_REV_NO_SPEED, at);
                return null;
            }
            cps = f * rpm * perUnitPerMin;
        } else {
            cps = f * perUnitPerMin;
        }
        if (Math.round(cps) < 2) {
            // the slowest vector speed the controller has (VS 2): the same verdict as compile's backend
            d.fail(out, Code.E207_FEED_TOO_SLOW, at, Arcs.text(cps));
            return null;
        }
        if (cps > p.maxFeed()) {
            d.fail(out, Code.E103_FEED_ABOVE_MAXIMUM, at, programTerms(d, f, rpm, cps, p.maxFeed(), perUnitPerMin));
            return null;
        }
        if (last == null || Double.compare(last.programmed(), f) != 0
                || Double.compare(last.countsPerSecond(), cps) != 0 || last.perRevolution() != d.next.feedPerRev) {
            last = new Feed(f, cps, d.next.feedPerRev);
        }
        return last;
    }

    /**
     * A feed finding's arguments in the program's terms first, the controller's counts second
     * (E103; E207 stays in counts, as the galil backend reports it too: 1 count/s is its limit): the F as written and its mode ({@code mm/rev × 800 rpm}, {@code in/min}), the
     * speed along the path it gives and the limit, both per minute in the program's units, then
     * the counts per second and the limit in counts.
     */
    private static Object[] programTerms(BlockDraft d, double f, double rpm, double cps, double limitCps,
                                         double perUnitPerMin) {
        String unit = d.units == gcnc.machine.Units.INCH ? "in" : "mm";
        String mode = d.next.feedPerRev ? unit + "/rev × " + Arcs.text(rpm) + " rpm" : unit + "/min";
        String written = d.has(Letter.F) ? d.word(Letter.F).number() : Arcs.text(f);
        return new Object[] {written, mode, Arcs.text(cps / perUnitPerMin), unit + "/min",
            Arcs.text(limitCps / perUnitPerMin), Arcs.text(cps), Arcs.text(limitCps)};
    }
}
