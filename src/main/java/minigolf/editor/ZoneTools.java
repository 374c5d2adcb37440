package minigolf.editor;

import java.util.Locale;
import minigolf.course.Shape;
import minigolf.course.Zone;

/** Short descriptions of friction zones for the editor's list. */
public final class ZoneTools {
    private ZoneTools() {
    }

    /** "circle (1.00, 2.00) r 0.50, mu_k 0.45 mu_s 0.60". */
    public static String describe(Zone z) {
        String shape;
        if (z.shape() instanceof Shape.Rect r) {
            shape = String.format(Locale.ROOT, "rect (%.2f, %.2f)-(%.2f, %.2f)", r.min().x(), r.min().y(), r.max().x(), r.max().y());
        } else if (z.shape() instanceof Shape.Circle c) {
            shape = String.format(Locale.ROOT, "circle (%.2f, %.2f) r %.2f", c.center().x(), c.center().y(), c.radius());
        } else if (z.shape() instanceof Shape.Cells c) {
            shape = String.format(Locale.ROOT, "cells (%d spans of %.3f m cells)", c.spanCount(), c.size());
        } else {
            shape = "polygon of " + ((Shape.Polygon) z.shape()).points().size() + " points";
        }
        String hazard = z.hazard() == null ? "" : ", " + z.hazard().kind().jsonName() + " (on " + z.hazard().when().jsonName() + ")";
        return String.format(Locale.ROOT, "%s, mu_k %.2f mu_s %.2f%s", shape, z.kineticFriction(), z.staticFriction(), hazard);
    }
}
