package minigolf.app;

import java.util.ArrayList;
import java.util.List;

/**
 * Where the name tags over the balls stand so that none covers another: balls side by side at the
 * tee are a few pixels apart, their tags wider than that. The current player's tag keeps its place
 * over its ball; each other tag, in seat order, stays over its ball's x and rises above any tag it
 * would overlap.
 */
final class NameTagLayout {
    /** The gap kept between two plates, pixels. */
    static final float GAP = 2;

    private NameTagLayout() {
    }

    /**
     * The bottom y of each tag. {@code x[i]}, {@code y[i]}: where tag i's plate would stand (bottom
     * centre); {@code w[i]}, {@code h[i]}: its plate's size; {@code first}: the tag placed first
     * (the current player's; -1 for none).
     */
    static float[] place(float[] x, float[] y, float[] w, float[] h, int first) {
        int n = x.length;
        float[] out = y.clone();
        List<Integer> order = new ArrayList<>();
        if (first >= 0 && first < n) order.add(first);
        for (int i = 0; i < n; i++) if (i != first) order.add(i);
        List<Integer> placed = new ArrayList<>();
        for (int i : order) {
            boolean moved = true;
            while (moved) { // each move is upwards, above a placed plate: at most one move per placed tag
                moved = false;
                for (int j : placed) {
                    boolean acrossX = Math.abs(x[i] - x[j]) < (w[i] + w[j]) / 2 + GAP;
                    boolean acrossY = out[i] > out[j] - h[j] - GAP && out[i] - h[i] < out[j] + GAP;
                    if (acrossX && acrossY) {
                        out[i] = out[j] - h[j] - GAP;
                        moved = true;
                    }
                }
            }
            placed.add(i);
        }
        return out;
    }

    /** Whether two plates (bottom centre x, y; size w, h) overlap. */
    static boolean overlap(float x1, float y1, float w1, float h1, float x2, float y2, float w2, float h2) {
        return Math.abs(x1 - x2) < (w1 + w2) / 2 && y1 > y2 - h2 && y1 - h1 < y2;
    }
}
