package minigolf.ui;

import java.util.List;
import java.util.function.Function;

/**
 * Draws the route a thinking bot intends (its plan) over the course: a line through the points
 * projected to the screen, a dot at each end. The game and the editor share it.
 */
public final class PlanOverlay {
    /** ABGR: a light orange that shows on grass, sand and water alike. */
    private static final int COLOUR = 0xE040B0FF;
    private static final int SHADOW = 0x90000000;

    private PlanOverlay() {
    }

    /**
     * @param plan     course points (x, y), ball first
     * @param toScreen a course point to interface pixels, or null when it is behind the camera
     */
    public static void draw(GuiDrawList dl, List<double[]> plan, Function<double[], float[]> toScreen) {
        float[] previous = null;
        float[] first = null;
        for (double[] p : plan) {
            float[] s = toScreen.apply(p);
            if (s != null && previous != null) {
                dl.addLine(previous[0], previous[1], s[0], s[1], SHADOW, 5f);
                dl.addLine(previous[0], previous[1], s[0], s[1], COLOUR, 3f);
            }
            if (first == null) first = s;
            previous = s;
        }
        if (first != null) dl.addCircleFilled(first[0], first[1], 5f, COLOUR);
        if (previous != null && previous != first) dl.addCircle(previous[0], previous[1], 9f, COLOUR, 20, 3f);
    }
}
