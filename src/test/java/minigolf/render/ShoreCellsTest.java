package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** Which sky cells by the sea can skip the per-pixel shore (plain geometry, no GL). */
class ShoreCellsTest {
    static final float[] RECT = {-3.8f, -1.8f, 3.8f, 1.8f};

    @Test
    void distanceBetweenAQuadAndTheRectangle() {
        float[] rect = {0, 0, 2, 1};
        // A unit square 2 m to the right: 2 m; one off the corner (2, 1) diagonally: sqrt 2.
        assertEquals(2.0, ShoreCells.distanceQuadToRect(new float[]{4, 5, 5, 4}, new float[]{0, 0, 1, 1}, rect), 1e-6);
        assertEquals(Math.sqrt(2), ShoreCells.distanceQuadToRect(new float[]{3, 4, 4, 3}, new float[]{2, 2, 3, 3}, rect), 1e-6);
        // Overlapping, and the rectangle wholly inside the quad: 0.
        assertEquals(0.0, ShoreCells.distanceQuadToRect(new float[]{1, 3, 3, 1}, new float[]{0.5f, 0.5f, 2, 2}, rect));
        assertEquals(0.0, ShoreCells.distanceQuadToRect(new float[]{-5, 5, 5, -5}, new float[]{-5, -5, 5, 5}, rect));
    }

    @Test
    void aLongCellWhoseCornersAreAllFarCanStillCrossTheBand() {
        // Corners 50 m out on both sides, but the edge y = 10 passes 8.2 m from the rectangle:
        // inside the band 11.3 .. 15.2 by its corners alone it would look like open sea.
        float[] xs = {-50, 50, 50, -50}, ys = {10, 10, 12, 12};
        assertFalse(ShoreCells.outsideBand(xs, ys, RECT, 11.3f, 15.2f));
        assertTrue(ShoreCells.outsideBand(xs, ys, RECT, 2f, 5f), "wholly beyond 5 m");
        // Near the course, wholly inside the inner distance: grass.
        assertTrue(ShoreCells.outsideBand(new float[]{4, 6, 6, 4}, new float[]{0, 0, 1, 1}, RECT, 11.3f, 15.2f));
        // Straddling the inner distance.
        assertFalse(ShoreCells.outsideBand(new float[]{10, 20, 20, 10}, new float[]{0, 0, 1, 1}, RECT, 11.3f, 15.2f));
    }

    /**
     * From a player's view over a seaside course, some cells skip the per-pixel shore, and no point of
     * a skipped cell (sampled on the screen, followed down to the ground) lies in the shore's band.
     */
    @Test
    void skippedCellsNeverShowTheShore() {
        for (float pitch : new float[]{-35, -20, -8}) {
            for (float heading : new float[]{0, 35, 90}) {
                checkView(pitch, heading);
            }
        }
    }

    private static void checkView(float pitchDegrees, float headingDegrees) {
        double p = Math.toRadians(pitchDegrees), h = Math.toRadians(headingDegrees);
        Vector3f eye = new Vector3f(-5, -3, 3);
        Matrix4f vp = new Matrix4f().perspective((float) Math.toRadians(45), 16f / 9, 0.05f, 500f)
                .lookAt(eye.x, eye.y, eye.z, eye.x + (float) (Math.cos(p) * Math.cos(h)), eye.y + (float) (Math.cos(p) * Math.sin(h)),
                        eye.z + (float) Math.sin(p), 0, 0, 1);
        Matrix4f inverse = vp.invert(new Matrix4f());
        int corners = (SkyPass.GRID_X + 1) * (SkyPass.GRID_Y + 1);
        int[] order = new int[SkyPass.GRID_X * SkyPass.GRID_Y * 6];
        float shoreDistance = 14, level = -0.6f;
        SkyPass.Shore shore = new SkyPass.Shore(level, RECT, shoreDistance - SkyPass.BEACH_WIDTH, shoreDistance + SkyPass.FOAM_REACH);
        int[] counts = SkyPass.sortCells(inverse, new Vector3f(0.3f, 0.4f, 0.8f), new float[corners], new float[corners], order,
                new Vector4f(), new Vector4f(), shore, new float[corners], new float[corners]);
        int total = 0;
        for (int c : counts) total += c;
        assertEquals(order.length, total);
        int skipped = counts[4] + counts[5] + counts[6] + counts[7];
        assertEquals(0, counts[5] + counts[7], "a skipped cell above the horizon");
        String view = "pitch " + pitchDegrees + ", heading " + headingDegrees;
        assertTrue(skipped > 0, "no cell skipped at " + view);
        int first = counts[0] + counts[1] + counts[2] + counts[3];
        Vector4f near = new Vector4f(), far = new Vector4f();
        for (int k = first; k < first + skipped; k += 6) {
            // The cell's corners a, b, d: its lower-left corner index gives its column and row.
            int a = order[k], i = a % (SkyPass.GRID_X + 1), j = a / (SkyPass.GRID_X + 1);
            for (int s = 0; s <= 8; s++) {
                for (int t = 0; t <= 8; t++) {
                    float x = 2f * (i + s / 8f) / SkyPass.GRID_X - 1, y = 2f * (j + t / 8f) / SkyPass.GRID_Y - 1;
                    inverse.transform(near.set(x, y, -1, 1));
                    inverse.transform(far.set(x, y, 1, 1));
                    float nx = near.x / near.w, ny = near.y / near.w, nz = near.z / near.w;
                    float dx = far.x / far.w - nx, dy = far.y / far.w - ny, dz = far.z / far.w - nz;
                    assertTrue(dz < 0, "a skipped cell's point above the horizon at " + view);
                    float u = (level - nz) / dz;
                    float d = ShoreCells.distanceToRect(nx + dx * u, ny + dy * u, RECT);
                    assertFalse(d >= shore.inner() && d <= shore.outer(),
                            "a skipped cell shows the shore at distance " + d + " (" + view + ")");
                }
            }
        }
    }
}
