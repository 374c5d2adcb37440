package minigolf.ui;

/** The players' ball colours, by seat: white, orange, sky blue, pink (distinct on green grass). */
public final class PlayerColors {
    private static final float[][] COLORS = {{1f, 1f, 1f}, {1f, 0.55f, 0.1f}, {0.35f, 0.75f, 1f}, {1f, 0.4f, 0.75f}};

    private PlayerColors() {
    }

    public static float[] of(int seat) {
        return COLORS[Math.floorMod(seat, COLORS.length)].clone();
    }
}
