package minigolf.editor;

/**
 * Terrain brushes. Every node within the radius r of the brush centre is changed by the weight
 * w(d) = (1 - (d/r)^2)^2, which is 1 at the centre and falls smoothly to 0 at the rim:
 * <ul>
 * <li>RAISE / LOWER: h += / -= strength * w (strength in metres per dab);</li>
 * <li>SMOOTH: h += min(1, strength) * w * (mean of the 3x3 neighbourhood - h);</li>
 * <li>FLATTEN: h += min(1, strength) * w * (target - h), target the height under the brush centre
 * when the stroke began.</li>
 * </ul>
 */
public enum Brush {
    RAISE("raise"), LOWER("lower"), SMOOTH("smooth"), FLATTEN("flatten");

    private final String label;

    Brush(String label) {
        this.label = label;
    }

    public String label() {
        return label;
    }

    /** The falloff weight at distance d from the centre of a brush of radius r. */
    public static double weight(double d, double r) {
        if (d >= r) return 0;
        double q = 1 - (d * d) / (r * r);
        return q * q;
    }

    /** Applies one dab at (x, y) to the recorder's course. */
    void dab(EditableCourse c, NodeEdit.Recorder rec, double x, double y, double radius, double strength,
             double target) {
        int i0 = Math.max(0, (int) Math.floor((x - radius - c.originX) / c.spacing));
        int i1 = Math.min(c.columns - 1, (int) Math.ceil((x + radius - c.originX) / c.spacing));
        int j0 = Math.max(0, (int) Math.floor((y - radius - c.originY) / c.spacing));
        int j1 = Math.min(c.rows - 1, (int) Math.ceil((y + radius - c.originY) / c.spacing));
        if (i0 > i1 || j0 > j1) return;
        double k = Math.min(1, Math.max(0, strength));
        // Smoothing reads the heights before this dab, so that the result does not depend on the visiting order.
        double[] before = this == SMOOTH ? snapshot(c, i0 - 1, j0 - 1, i1 + 1, j1 + 1) : null;
        int w = i1 - i0 + 3;
        for (int j = j0; j <= j1; j++) {
            for (int i = i0; i <= i1; i++) {
                double wt = weight(Math.hypot(c.nodeX(i) - x, c.nodeY(j) - y), radius);
                if (wt <= 0) continue;
                double h = c.height(i, j);
                double nh = switch (this) {
                    case RAISE -> h + strength * wt;
                    case LOWER -> h - strength * wt;
                    case FLATTEN -> h + k * wt * (target - h);
                    case SMOOTH -> h + k * wt * (mean(before, w, i - i0 + 1, j - j0 + 1) - h);
                };
                if (nh != h) rec.setHeight(i, j, nh);
            }
        }
    }

    /** Heights of nodes (i0..i1, j0..j1), edge nodes repeated outside the grid. */
    private static double[] snapshot(EditableCourse c, int i0, int j0, int i1, int j1) {
        int w = i1 - i0 + 1;
        double[] out = new double[w * (j1 - j0 + 1)];
        for (int j = j0; j <= j1; j++) {
            int jj = Math.max(0, Math.min(c.rows - 1, j));
            for (int i = i0; i <= i1; i++) {
                int ii = Math.max(0, Math.min(c.columns - 1, i));
                out[(j - j0) * w + (i - i0)] = c.height(ii, jj);
            }
        }
        return out;
    }

    private static double mean(double[] a, int w, int i, int j) {
        double sum = 0;
        for (int dj = -1; dj <= 1; dj++) {
            for (int di = -1; di <= 1; di++) sum += a[(j + dj) * w + i + di];
        }
        return sum / 9;
    }
}
