package gcnc.post;

import java.util.Random;

/**
 * The part a generated program turns, in mm, work zero on the blank's face: a bar of diameter
 * {@code blank}, faced {@code face} deep, then a stepped shaft: a {@code chamfer} at the face's
 * outer corner, zone k running to Z -z[k] at diameter d[k] (d grows away from the face, so a
 * G71 type I contour describes it), each shoulder's outer corner rounded with {@code radius}.
 * Every cut the generator writes stays inside this description, which is what makes its
 * programs simulate clean from this blank.
 */
record PostPart(double blank, double face, double chamfer, double radius, double[] d, double[] z) {

    static PostPart random(Random rnd) {
        double blank = 30 + rnd.nextInt(31);
        double face = 0.3 + rnd.nextInt(8) / 10.0;
        double chamfer = 0.5 + rnd.nextInt(3) / 2.0;
        double radius = 0.5 + rnd.nextInt(2) / 2.0;
        // the largest zone leaves 1 to 4 mm a side to rough; each smaller one 4 to 10 mm less in
        // diameter, none under 14 mm (a zone that would be is left out)
        int wanted = 1 + rnd.nextInt(3);
        double[] from = new double[wanted];
        int zones = 0;
        for (double dia = blank - 2 - 2 * rnd.nextInt(4); zones < wanted && dia >= 14; zones++) {
            from[zones] = dia;
            dia -= 4 + 2 * rnd.nextInt(4);
        }
        double[] d = new double[zones];
        double[] z = new double[zones];
        for (int k = 0; k < zones; k++) {
            d[k] = from[zones - 1 - k];
        }
        // the first zone is long enough to thread (12 mm and more), every zone at least 10 mm
        double at = face + chamfer + 12 + rnd.nextInt(10);
        for (int k = 0; k < zones; k++) {
            z[k] = at;
            at += radius + 10 + rnd.nextInt(12);
        }
        return new PostPart(blank, face, chamfer, radius, d, z);
    }

    int last() {
        return d.length - 1;
    }

    /** Distance from work zero to the part's back end (where it is parted off). */
    double length() {
        return z[last()];
    }
}
