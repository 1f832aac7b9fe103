package gcnc.post;

import gcnc.post.PostStyleGenerator.Post;
import java.util.Random;

/**
 * The operations of a generated program, each written as the posts' onSection, cycle and
 * onSectionEnd functions write one: retract, tool call, spindle and coolant, the cut, the speed
 * mode put back to r/min. All positions are in mm from work zero on the blank's face; the cuts
 * stay inside the {@link PostPart} (so they simulate clean): facing {@code face} deep, roughing
 * with G71 down to the contour plus an allowance, finishing the contour, a groove in the last
 * zone, a thread on the first zone clear of its shoulder, a hole on the centreline, a part-off
 * behind the last zone.
 */
final class Sections {
    /** Clearance in front of the face and outside the blank (mm). */
    private static final double CLEAR = 2;
    /** The initial level of a drilling or tapping cycle (the posts' cycle.clearance), above the R point at CLEAR. */
    private static final double DRILL_CLEARANCE = 5;

    private final PostStyleGenerator g;
    private final Post post;
    private final Random rnd;
    private final PostPart p;
    private final Blocks out;

    Sections(PostStyleGenerator g) {
        this.g = g;
        this.post = g.post();
        this.rnd = g.rnd();
        this.p = g.part();
        this.out = g.out();
    }

    /** The tool word as the post writes it: haas "T101" (no zero padding), fanuc "T0101" (width 4). */
    private String tool(int n) {
        return post.haas() ? "T" + (n * 100 + n) : String.format("T%02d%02d", n, n);
    }

    private double outside() {
        return p.blank() + 2 * CLEAR;
    }

    private static int pickInt(Random rnd, int from, int to) {
        return from + rnd.nextInt(to - from + 1);
    }

    /** r/min of surface speed {@code v} (m/min on the fanuc, ft/min on the haas) at diameter {@code dMm}, under the clamp. */
    private int rpm(int v, double dMm) {
        double r = post.haas() ? v * 12 / (Math.PI * dMm / 25.4) : v * 1000 / (Math.PI * dMm);
        return (int) Math.min(g.maxRpm(), Math.round(r));
    }

    /** onSection: retract, comment, optional stop, tool call, spindle, feed mode, work offset, coolant, first position, then G96 when {@code css}. */
    private void start(String comment, int tool, boolean css, int speed, double x, double z) {
        boolean first = g.nextToolCall() == 0;
        if (!first) {
            out.block("M9");
        }
        g.retract();
        out.line("");
        out.line("(" + comment + ")");
        if (!first && g.wants(Construct.OPTIONAL_STOP)) {
            out.block("M1");
        }
        out.block(tool(tool));
        g.toolUsed(tool(tool), comment);
        int r0 = css ? rpm(speed, x) : speed;
        if (post.haas()) {
            if (g.wants(Construct.TAILSTOCK_M22)) {
                out.block("M22");
            }
            out.block("G97", "S" + r0, "M3");
        }
        out.block(g.feedMode(true), "G18");
        out.block(g.workOffset());
        out.block("M8");
        if (!post.haas()) {
            out.block("G97", "S" + r0, "M3");
        }
        out.block(post == Post.FANUC_B ? "G90 G0" : "G0", out.x(x), out.z(z));
        if (css) {
            out.block(g.clamp(), "S" + g.maxRpm());
            out.block("G96", "S" + speed, "M3");
        }
    }

    /** onSectionEnd: a G96 section goes back to r/min (the speed at its last position) so the next tool call starts safely. */
    private void end(boolean css, int speed) {
        if (css) {
            out.block("G97", "S" + rpm(speed, outside()), "M3");
        }
        out.optional = false;
    }

    private int css(int fanucFrom, int fanucTo) {
        return post.haas() ? pickInt(rnd, fanucFrom * 3, fanucTo * 3) : pickInt(rnd, fanucFrom, fanucTo);
    }

    /** Facing {@code face} deep, then G71 (haas one block with D; fanuc G71 U R and G71 P Q U W F) over the contour. */
    void faceAndRough(Construct underComp) {
        int v = css(150, 250);
        start("FACE AND ROUGH", 1, true, v, outside(), CLEAR);
        boolean parametric = g.wants(Construct.PARAMETRIC_FEED);
        out.block("G0", out.z(-p.face()));
        out.block("G1", out.x(-1.6), g.feed(pickInt(rnd, 15, 25) / 100.0, parametric, "FACING"));
        if (g.wants(Construct.HIGH_FEED_G1)) {
            // onRapid: X and Z both change, the axes are not synchronized: a G1 at the high feed
            out.block("G1", out.x(outside()), out.z(CLEAR), "F" + out.num(0.75));
        } else {
            out.block("G0", out.z(CLEAR));
            out.block("G0", out.x(outside()));
        }
        if (underComp != null) {
            out.block("G0", "G42", out.x(outside()), out.z(CLEAR));
        }
        double depth = pickInt(rnd, 10, 20) / 10.0;
        double u = pickInt(rnd, 2, 5) / 10.0;
        double w = pickInt(rnd, 5, 10) / 100.0;
        String f = g.feed(pickInt(rnd, 20, 35) / 100.0, parametric, "ROUGHING");
        // the contour's sequence numbers follow the G71 block(s), as the posts number them
        int first = out.numberAfter(post.haas() ? 1 : 2);
        int last = first + 5 * contourBlocks();
        g.contourAt(first, last);
        if (post.haas()) {
            out.block("G71", "P" + first, "Q" + last, "U" + out.num(u), "W" + out.num(w), "D" + out.num(depth), f);
        } else {
            out.block("G71", "U" + out.num(depth), "R" + out.num(0.5));
            out.block("G71", "P" + first, "Q" + last, "U" + out.num(u), "W" + out.num(w), f);
        }
        contour(first, last);
        if (underComp != null) {
            out.block("G0", "G40", out.x(outside()));
        }
        end(true, v);
    }

    /** How many blocks follow the contour's first one (its last is N first + 5 x this). */
    private int contourBlocks() {
        return 3 + 3 * p.last() + 1;
    }

    /**
     * The G71/G70 contour, type I: X only in its first block, X growing and Z falling after. The
     * posts number its first and last blocks (G71 P and Q) even when the others carry no number.
     */
    private void contour(int first, int last) {
        int[] n = {first};
        out.numberedBlock(first, "G0", out.x(p.d()[0] - 2 * p.chamfer()));
        path(n, "G1", out.z(-p.face()));
        path(n, out.x(p.d()[0]), out.z(-p.face() - p.chamfer()));
        path(n, out.z(-p.z()[0]));
        for (int k = 1; k <= p.last(); k++) {
            path(n, out.x(p.d()[k] - 2 * p.radius()));
            path(n, "G3", out.x(p.d()[k]), out.z(-p.z()[k - 1] - p.radius()), "R" + out.num(p.radius()));
            path(n, "G1", out.z(-p.z()[k]));
        }
        out.numberedBlock(n[0] += 5, out.x(p.blank() + CLEAR));
        if (n[0] != last) {
            throw new IllegalStateException("contour numbered " + first + ".." + n[0] + ", not " + last);
        }
        out.skipNumbers(last);
    }

    private void path(int[] n, String... words) {
        n[0] += 5;
        if (out.numbered) {
            out.numberedBlock(n[0], words);
        } else {
            out.block(words);
        }
    }

    /** Finishing: G70 P Q under G42, or the profile as the posts write a finishing pass (optionally with ,C/,R corners). */
    void finish(Construct how) {
        int v = css(200, 300);
        start("FINISH", post.haas() ? 2 : 3, true, v, outside(), CLEAR);
        if (how == Construct.FINISH_G70) {
            out.block("G0", "G42", out.x(p.blank() + CLEAR), out.z(CLEAR));
            out.block("G70", "P" + g.contourFirst(), "Q" + g.contourLast());
            out.block("G0", "G40", out.x(outside()));
        } else {
            boolean corners = how == Construct.CORNER_CHAMFER_RADIUS;
            double startX = p.d()[0] - 2 * p.chamfer() - (corners ? 2 : 0);
            out.block("G0", out.x(startX - 2), out.z(CLEAR));
            out.block("G18");
            out.block("G1", "G42", out.x(startX), out.z(0.5), "F" + out.num(pickInt(rnd, 8, 15) / 100.0));
            out.block(out.z(-p.face()));
            if (corners) {
                // Haas ,C is unsigned; a Fanuc C or R takes the sign of the next move (here -Z)
                out.block(out.x(p.d()[0]), (post.haas() ? ",C" : "C-") + out.num(p.chamfer()));
            } else {
                out.block(out.x(p.d()[0]), out.z(-p.face() - p.chamfer()));
            }
            out.block(out.z(-p.z()[0]));
            for (int k = 1; k <= p.last(); k++) {
                if (corners) {
                    out.block(out.x(p.d()[k]), (post.haas() ? ",R" : "R-") + out.num(p.radius()));
                } else {
                    out.block(out.x(p.d()[k] - 2 * p.radius()));
                    out.block("G3", out.x(p.d()[k]), out.z(-p.z()[k - 1] - p.radius()), "R" + out.num(p.radius()));
                    out.block("G1", out.z(-p.z()[k]));
                    continue;
                }
                out.block(out.z(-p.z()[k]));
            }
            out.block(out.x(p.blank() + CLEAR));
            out.block("G0", "G40", out.x(outside()));
            out.block(out.z(CLEAR));
        }
        end(true, v);
    }

    /** G75 in the middle of the last zone with a 3 mm blade whose programmed point is its chuck-side corner. */
    void groove() {
        out.optional = g.wants(Construct.OPTIONAL_SECTION);
        int k = p.last();
        double from = k == 0 ? p.face() + p.chamfer() : p.z()[k - 1] + p.radius();
        double to = p.z()[k];
        double mid = (from + to) / 2;
        double width = 3 + (rnd.nextBoolean() ? 0 : pickInt(rnd, 1, 3));
        double a = mid - width / 2;
        double bottom = p.d()[k] - 2 * pickInt(rnd, 5, 15) / 10.0;
        int v = css(100, 150);
        start("GROOVE", post.haas() ? 9 : 5, true, v, outside(), CLEAR);
        out.block("G0", out.z(-(a + 3)));
        out.block("G0", out.x(p.blank() + CLEAR));
        String f = "F" + out.num(pickInt(rnd, 4, 8) / 100.0);
        boolean wide = width > 3;
        if (post.haas()) {
            out.block("G75", out.x(bottom), wide ? out.z(-(a + width)) : "", "I" + out.num(0.5),
                    wide ? "K" + out.num(2) : "", f);
        } else {
            out.block("G75", "R" + out.num(0.5));
            out.block("G75", out.x(bottom), wide ? out.z(-(a + width)) : "", "P" + Blocks.micro(0.5),
                    wide ? "Q" + Blocks.micro(2) : "", f);
        }
        if (g.wants(Construct.DWELL)) {
            out.block("G4", "P" + pickInt(rnd, 2, 10) * 100);
        }
        out.block("G0", out.x(outside()));
        out.block("G0", out.z(CLEAR));
        end(true, v);
    }

    /** A thread on the first zone, ending two leads and 2 mm before its shoulder, started 3 leads in front of the face. */
    void thread(Construct how) {
        out.optional = g.wants(Construct.OPTIONAL_SECTION);
        double lead = post.haas() ? 25.4 / new int[] {20, 16, 13, 12, 10}[rnd.nextInt(5)]
                : new double[] {1.0, 1.25, 1.5, 1.75, 2.0}[rnd.nextInt(5)];
        double h = Math.round(0.6134 * lead / post.unit * 10000) / 10000.0 * post.unit;
        double major = p.d()[0];
        double zEnd = -(p.z()[0] - 2 * lead - 2);
        double zStart = 3 * lead + CLEAR;
        double xStart = major + 2 * CLEAR;
        int rpm = post.haas() ? pickInt(rnd, 4, 8) * 100 : pickInt(rnd, 5, 9) * 100;
        start("THREAD", post.haas() ? 3 : 7, false, rpm, xStart, zStart);
        boolean m24 = how != Construct.THREAD_G32 && g.wants(Construct.THREAD_M24);
        if (m24) {
            out.block("M24");
        }
        String f = "F" + out.num(lead);
        // a two-start thread (start angle Q, haas and fanuc G92): the cycle twice, the second start 180 degrees on
        boolean twoStarts = how != Construct.THREAD_G32 && !(how == Construct.THREAD_G76 && !post.haas())
                && g.wants(Construct.THREAD_START_ANGLE);
        for (String q : twoStarts ? new String[] {"Q0", "Q180000"} : new String[] {""}) {
            threadCycle(how, lead, h, major, zEnd, xStart, zStart, f, q);
        }
        out.block("G0", out.x(xStart), out.z(zStart));
        if (m24) {
            out.block("M23");
        }
        end(false, rpm);
    }

    /** One thread cycle: G76 (haas one block; fanuc two), G92/G78 one block per pass, or G32/G33 passes between rapids. */
    private void threadCycle(Construct how, double lead, double h, double major, double zEnd, double xStart,
                             double zStart, String f, String q) {
        double minor = major - 2 * h;
        switch (how) {
            case THREAD_G76 -> {
                if (post.haas()) {
                    String angle = g.wants(Construct.THREAD_ANGLE_WITH_POINT) ? "A60." : rnd.nextBoolean() ? "A60" : "A59";
                    out.block("G76", out.x(minor), out.z(zEnd), "K" + out.num(h), "D" + out.num(h / 4), angle,
                            "P" + (g.wants(Construct.THREAD_ALTERNATE_FLANKS) ? 2 : rnd.nextBoolean() ? 1 : 3), q, f);
                } else {
                    // P mm rr aa: finishing passes, chamfer in tenths of a lead (the post always writes 10), angle
                    String rr = g.always(Construct.FANUC_THREAD_CHAMFER) ? "10" : "00";
                    out.block("G76", String.format("P%02d%s%02d", pickInt(rnd, 1, 2), rr, 60), "Q" + Blocks.micro(0.05), "R0");
                    out.block("G76", out.x(minor), out.z(zEnd), "P" + Blocks.micro(h), "Q" + Blocks.micro(h / 4), f);
                }
            }
            case THREAD_G92 -> {
                int passes = pickInt(rnd, 4, 8);
                String code = post == Post.FANUC_B ? "G78" : "G92";
                for (int i = 1; i <= passes; i++) {
                    double x = major - 2 * h * Math.sqrt((double) i / passes);
                    if (i == 1) {
                        out.block(code, out.x(x), out.z(zEnd), q, f);
                    } else {
                        out.block(out.x(x));
                    }
                }
                if (rnd.nextBoolean()) {
                    out.block(out.x(minor), out.z(zEnd)); // the spring pass: the last pass again
                }
            }
            default -> {
                int passes = pickInt(rnd, 3, 6);
                String code = post == Post.FANUC_B ? "G33" : "G32";
                for (int i = 1; i <= passes; i++) {
                    out.block("G0", out.x(major - 2 * h * Math.sqrt((double) i / passes)));
                    out.block(code, out.z(zEnd), f);
                    out.block("G0", out.x(xStart));
                    out.block(out.z(zStart));
                }
            }
        }
    }

    /** A hole on the centreline: G74 (haas Z K; fanuc G74 R / G74 Z Q), haas G83, fanuc G83, or G84 tapping. */
    void drill(Construct how) {
        out.optional = g.wants(Construct.OPTIONAL_SECTION);
        double depth = p.face() + pickInt(rnd, 5, 15);
        double peck = pickInt(rnd, 2, 4);
        int rpm = pickInt(rnd, 8, 12) * 100;
        // the cycle starts at the clearance height (the initial level) and feeds from the R point
        // (the posts' cycle.clearance and cycle.retract)
        start(how == Construct.TAP_G84 ? "TAP" : "DRILL", post.haas() ? 5 : 2, false, rpm, 0, DRILL_CLEARANCE);
        String r = "R" + rPoint();
        String f = "F" + out.num(pickInt(rnd, 8, 15) / 100.0);
        switch (how) {
            case DRILL_G74 -> {
                if (post.haas()) {
                    out.block("G74", out.z(-depth), "K" + out.num(peck), f);
                } else {
                    out.block("G74", "R" + out.num(0.5));
                    out.block("G74", out.z(-depth), "Q" + Blocks.micro(peck), f);
                }
            }
            case DRILL_G83_HAAS, DRILL_G83_FANUC -> {
                out.block(post == Post.FANUC_B ? "G90 G98 G83" : "G83", out.x(0), out.z(-depth), r,
                        "Q" + out.num(peck), f);
                out.block("G80");
            }
            default -> {
                double pitch = post.haas() ? 25.4 / 20 : 1.25;
                if (!post.haas()) {
                    out.block("M29", "S" + rpm);
                }
                out.block(post == Post.FANUC_B ? "G90 G98 G84" : "G84", out.x(0), out.z(-depth), r, "P0",
                        "F" + out.num(pitch));
                out.block("G80");
            }
        }
        out.block("G0", out.z(CLEAR));
        end(false, rpm);
    }

    /**
     * The R word's value: the R point's Z as the posts write it (getCommonCycle: cycle.retract) on
     * haas and fanuc-b (parameter RAB, cycle.drill_r = absolute); on fanuc-a the distance from the
     * initial level to it, as the 0i-TF manual says R is read (docs/language.md: the post writes
     * the Z there too).
     */
    private String rPoint() {
        return out.num(post == Post.FANUC_A ? CLEAR - DRILL_CLEARANCE : CLEAR);
    }

    /** Part-off 1 mm behind the last zone: the blade's programmed point is its chuck-side corner, so it stands 4 mm behind. */
    void partOff() {
        int v = css(80, 120);
        start("PART OFF", post.haas() ? 12 : 5, true, v, outside(), CLEAR);
        out.block("G0", out.z(-(p.length() + 4)));
        out.block("G1", out.x(-1), "F" + out.num(pickInt(rnd, 4, 6) / 100.0));
        out.block("G0", out.x(outside()));
        out.block("G0", out.z(CLEAR));
        end(true, v);
    }
}
