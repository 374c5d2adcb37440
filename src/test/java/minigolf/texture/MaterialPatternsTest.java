package minigolf.texture;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/** The procedural material layers: seamless tiles, the same every time, and each its own pattern. */
class MaterialPatternsTest {
    static final int SIZE = 64;

    @Test
    void everyLayerTilesWithoutASeam() {
        for (MaterialPatterns.Layer l : MaterialPatterns.Layer.values()) {
            byte[] px = MaterialPatterns.layer(l, SIZE);
            // Across the seam (last column to first) the change is no bigger than between neighbours inside.
            double seam = 0, inside = 0;
            for (int j = 0; j < SIZE; j++) {
                seam += diff(px, SIZE - 1, j, 0, j) + diff(px, j, SIZE - 1, j, 0);
                inside += diff(px, SIZE / 2 - 1, j, SIZE / 2, j) + diff(px, j, SIZE / 2 - 1, j, SIZE / 2);
            }
            assertTrue(seam <= 2.5 * inside + 2 * SIZE, l + ": seam " + seam + " against " + inside + " inside");
        }
    }

    private static double diff(byte[] px, int i0, int j0, int i1, int j1) {
        double d = 0;
        for (int c = 0; c < 4; c++) d += Math.abs((px[4 * (j0 * SIZE + i0) + c] & 0xFF) - (px[4 * (j1 * SIZE + i1) + c] & 0xFF));
        return d;
    }

    @Test
    void layersAreDeterministicDistinctAndAroundTheMaterialsOwnColour() {
        byte[] a = MaterialPatterns.all(SIZE), b = MaterialPatterns.all(SIZE);
        assertArrayEquals(a, b);
        int n = MaterialPatterns.Layer.values().length;
        assertEquals(n * SIZE * SIZE * 4, a.length);
        for (int l = 0; l < n; l++) {
            double mean = 0;
            int min = 255, max = 0;
            for (int k = 0; k < SIZE * SIZE; k++) {
                int g = a[l * SIZE * SIZE * 4 + 4 * k + 1] & 0xFF;
                mean += g;
                min = Math.min(min, g);
                max = Math.max(max, g);
            }
            mean /= SIZE * SIZE;
            // 128 stands for the material's own colour: the mean factor stays within 0.7..1.2 of it.
            assertTrue(mean > 0.7 * 128 && mean < 1.2 * 128, MaterialPatterns.Layer.values()[l] + ": mean " + mean);
            assertTrue(max - min > 12, MaterialPatterns.Layer.values()[l] + " has detail: " + min + ".." + max);
            for (int m = 0; m < l; m++) {
                assertFalse(java.util.Arrays.equals(java.util.Arrays.copyOfRange(a, l * SIZE * SIZE * 4, (l + 1) * SIZE * SIZE * 4),
                        java.util.Arrays.copyOfRange(a, m * SIZE * SIZE * 4, (m + 1) * SIZE * SIZE * 4)), "layers " + l + " and " + m);
            }
        }
    }

    @Test
    void stoneHasLowMortarJointsBetweenHigherBlocks() {
        byte[] px = MaterialPatterns.layer(MaterialPatterns.Layer.STONE, SIZE);
        // Courses are a quarter of the tile high: the joint between the first two rows is at j = SIZE/4.
        int joint = px[4 * ((SIZE / 4) * SIZE + SIZE / 8) + 3] & 0xFF;
        int block = px[4 * ((SIZE / 8) * SIZE + SIZE / 8) + 3] & 0xFF;
        assertTrue(joint < block - 60, "joint height " + joint + ", block " + block);
    }

    @Test
    void aSizeThatIsNotAMultipleOf64IsRefused() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MaterialPatterns.layer(MaterialPatterns.Layer.SAND, 100));
        assertEquals("size must be a positive multiple of 64, got 100", e.getMessage());
    }

    @Test
    void valueNoiseRepeatsWithItsPeriodAndStaysInRange() {
        for (double x = -3; x < 3; x += 0.37) {
            for (double y = -2; y < 2; y += 0.41) {
                double v = Noise.value(x, y, 4);
                assertTrue(v >= 0 && v < 1);
                assertEquals(v, Noise.value(x + 4, y - 8, 4), 1e-12);
            }
        }
    }
}
