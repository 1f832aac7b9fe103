package gcnc.sim;

import java.util.Locale;

/**
 * What part of the half-section a drawing shows, and machine mm to SVG pixels (z right, radius
 * up). The view fits what a setup person works from: the blank and where the tool cut it, the
 * chuck's face with its jaws, and the tailstock's centre when it stands near the part (a path
 * with no blank: the whole path; a tailstock further from the part than the view is long is named
 * under the drawing instead, {@link SvgTitle}). Its aspect ratio is capped (never taller than {@link #MAX_HEIGHT}
 * nor flatter than {@link #MIN_HEIGHT} at {@link SvgWriter#WIDTH} pixels wide): a short part of a
 * large diameter shows more of the bed beside it rather than becoming a 3000-pixel column.
 */
record SvgView(double zMin, double zMax, double rMin, double rMax, double scale) {
    static final double MAX_HEIGHT = 700;
    static final double MIN_HEIGHT = 260;

    double height() {
        return (rMax - rMin) * scale;
    }

    double x(double z) {
        return (z - zMin) * scale;
    }

    double y(double r) {
        return (rMax - r) * scale;
    }

    String pt(double z, double r) {
        return String.format(Locale.ROOT, "%.2f,%.2f ", x(z), y(r));
    }

    static SvgView of(Drawing d) {
        boolean stock = !Double.isNaN(d.stockRadius());
        double zLo = Double.MAX_VALUE;
        double zHi = -Double.MAX_VALUE;
        double rHi = stock ? d.stockRadius() : -Double.MAX_VALUE;
        for (Drawing.Move m : d.moves()) {
            if (stock && m.rapid()) {
                continue;
            }
            for (int i = 0; i < m.z().length; i++) {
                zLo = Math.min(zLo, m.z()[i]);
                zHi = Math.max(zHi, m.z()[i]);
                rHi = Math.max(rHi, stock ? Math.min(m.r()[i], 1.2 * d.stockRadius()) : m.r()[i]);
            }
        }
        for (Drawing.Mark m : d.marks()) {
            zLo = Math.min(zLo, m.z());
            zHi = Math.max(zHi, m.z());
            rHi = Math.max(rHi, m.r());
        }
        if (stock) {
            zLo = Math.max(Math.min(zLo, d.stockFace()), d.stockBack());
            zHi = Math.min(Math.max(zHi, d.stockFace()), d.stockFace() + 0.2 * (d.stockFace() - d.stockBack()));
        }
        if (zLo > zHi) {
            zLo = 0;
            zHi = 1;
            rHi = Math.max(rHi, 1);
        }
        double face = d.machine().chuckFace();
        if (!Double.isNaN(face) && !d.chuck().isEmpty() && (stock || face >= zLo - (zHi - zLo))) {
            // the jaws' face and the front of the jaws: where the part is held, what the tool must keep clear of
            Shape jaws = d.chuck().get(0);
            double jawLength = face - min(jaws.z());
            zLo = Math.min(zLo, face - 0.4 * jawLength);
            zHi = Math.max(zHi, face);
            rHi = Math.max(rHi, max(jaws.r()));
        }
        double tip = d.tailstockTip();
        if (!Double.isNaN(tip) && tip >= zHi && tip - zHi < zHi - zLo) {
            zHi = tip + 0.05 * (zHi - zLo); // the centre's cone and a little of the quill
        }
        double mz = Math.max(zHi - zLo, 1e-9) * 0.06;
        double mr = Math.max(rHi, 1e-9) * 0.12;
        double z0 = zLo - mz;
        double z1 = zHi + mz;
        double top = rHi + mr;
        // With a blank the part is mirrored below the centreline, so both halves show.
        double bottom = stock ? -top : -mr * 0.3;
        double ratio = (top - bottom) / (z1 - z0);
        if (ratio * SvgWriter.WIDTH > MAX_HEIGHT) {
            double wider = (top - bottom) * SvgWriter.WIDTH / MAX_HEIGHT - (z1 - z0);
            z0 -= wider / 2;
            z1 += wider / 2;
        } else if (ratio * SvgWriter.WIDTH < MIN_HEIGHT) {
            double taller = (z1 - z0) * MIN_HEIGHT / SvgWriter.WIDTH - (top - bottom);
            if (stock) {
                top += taller / 2;
                bottom -= taller / 2;
            } else {
                top += taller;
            }
        }
        return new SvgView(z0, z1, bottom, top, SvgWriter.WIDTH / (z1 - z0));
    }

    private static double min(double[] v) {
        double m = Double.MAX_VALUE;
        for (double x : v) {
            m = Math.min(m, x);
        }
        return m;
    }

    private static double max(double[] v) {
        double m = -Double.MAX_VALUE;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }
}
