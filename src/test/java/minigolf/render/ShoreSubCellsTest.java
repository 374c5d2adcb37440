package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The sky's band cells by the sea cut smaller (plain geometry, no GL). */
class ShoreSubCellsTest {
    private static final float LEVEL = -0.6f, SHORE = 14;

    /**
     * From a player's view over a seaside course: the band cells are cut into SUB x SUB small cells
     * that tile them exactly (their outer corners are the big cell's), no small cell drawn from its
     * corners shows the band (sampled 8 x 8 per small cell and followed down to the ground), and the
     * per-pixel area left is well under the band cells' whole area.
     */
    @Test
    void theCutCellsTileTheBandCellsAndOnlyTheBandStaysPerPixel() {
        int views = 0;
        int[] area = new int[2];
        for (float pitch : new float[]{-35, -20, -8}) {
            for (float heading : new float[]{0, 35, 90}) {
                if (checkView(pitch, heading, area)) views++;
            }
        }
        assertTrue(views >= 6, "band cells in " + views + " of 9 views");
        assertTrue(area[1] < 0.6 * area[0], "of the band cells' " + area[0] + " small cells " + area[1] + " stay per pixel");
    }

    /** Checks one view; adds the band cells' small cells and those per pixel to {@code area}; false: no band cell. */
    private static boolean checkView(float pitchDegrees, float headingDegrees, int[] area) {
        String view = "pitch " + pitchDegrees + ", heading " + headingDegrees;
        double p = Math.toRadians(pitchDegrees), h = Math.toRadians(headingDegrees);
        Vector3f eye = new Vector3f(-5, -3, 3);
        Matrix4f inverse = new Matrix4f().perspective((float) Math.toRadians(45), 16f / 9, 0.05f, 500f)
                .lookAt(eye.x, eye.y, eye.z, eye.x + (float) (Math.cos(p) * Math.cos(h)), eye.y + (float) (Math.cos(p) * Math.sin(h)),
                        eye.z + (float) Math.sin(p), 0, 0, 1).invert(new Matrix4f());
        int corners = (SkyPass.GRID_X + 1) * (SkyPass.GRID_Y + 1);
        int[] order = new int[SkyPass.GRID_X * SkyPass.GRID_Y * 6];
        SkyPass.Shore shore = new SkyPass.Shore(LEVEL, ShoreCellsTest.RECT, SHORE - SkyPass.BEACH_WIDTH, SHORE + SkyPass.FOAM_REACH);
        Vector4f near = new Vector4f(), far = new Vector4f();
        int[] counts = SkyPass.sortCells(inverse, new Vector3f(0.3f, 0.4f, 0.8f), new float[corners], new float[corners], order,
                near, far, shore, new float[corners], new float[corners]);
        int bandCells = (counts[0] + counts[2]) / 6;
        if (bandCells == 0) return false;
        ShoreSubCells sub = new ShoreSubCells(SkyPass.GRID_X * SkyPass.GRID_Y);
        int[] subCounts = sub.build(inverse, shore, order, 0, counts[0], counts[0] + counts[1], counts[2], near, far);
        int n = ShoreSubCells.SUB;
        assertEquals(bandCells * n * n * 6, java.util.Arrays.stream(subCounts).sum(), "16 small cells a band cell (" + view + ")");
        assertEquals(0, subCounts[1] + subCounts[3] + subCounts[5] + subCounts[7], "no small cell above the horizon");
        assertEquals(bandCells * (n + 1) * (n + 1), sub.vertexCount());
        // Each band cell's small-cell corners: the first and last of its (n + 1)^2 are the big cell's own corners.
        for (int c = 0; c < bandCells; c++) {
            int k = c < counts[0] / 6 ? c * 6 : (counts[1] / 6 + c) * 6;
            int a = order[k], i = a % (SkyPass.GRID_X + 1), j = a / (SkyPass.GRID_X + 1);
            int first = c * (n + 1) * (n + 1), last = first + (n + 1) * (n + 1) - 1;
            assertEquals(2f * i / SkyPass.GRID_X - 1, sub.vertices[first * 2], 0f);
            assertEquals(2f * j / SkyPass.GRID_Y - 1, sub.vertices[first * 2 + 1], 0f);
            assertEquals(2f * (i + 1) / SkyPass.GRID_X - 1, sub.vertices[last * 2], 0f);
            assertEquals(2f * (j + 1) / SkyPass.GRID_Y - 1, sub.vertices[last * 2 + 1], 0f);
        }
        int perPixel = subCounts[0] + subCounts[2], plain = subCounts[4] + subCounts[6];
        assertTrue(plain > 0, "some of the band cells' area is off the band (" + view + ")");
        area[0] += (plain + perPixel) / 6;
        area[1] += perPixel / 6;
        System.out.println(view + ": " + bandCells + " band cells, " + perPixel / 6 + " of " + (plain + perPixel) / 6 + " small cells per pixel");
        int start = subCounts[0] + subCounts[2];
        for (int k = start; k < start + plain; k += 6) {
            // A small cell's triangles a, b, d: a and d are opposite corners.
            int a = sub.indices[k], d = sub.indices[k + 2];
            float x0 = sub.vertices[a * 2], y0 = sub.vertices[a * 2 + 1], x1 = sub.vertices[d * 2], y1 = sub.vertices[d * 2 + 1];
            for (int s = 0; s <= 8; s++) {
                for (int t = 0; t <= 8; t++) {
                    ShoreCellsTest.assertOffTheBand(inverse, x0 + (x1 - x0) * s / 8, y0 + (y1 - y0) * t / 8, shore,
                            "a plain small cell", view);
                }
            }
        }
        return true;
    }
}
