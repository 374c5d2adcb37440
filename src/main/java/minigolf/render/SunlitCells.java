package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;

/**
 * Which terrain cells the sun's shadow map can darken, from the map's depths: the rest of the
 * course is in full sun and is drawn without the per-pixel shadow tap (llvmpipe pays for that tap on
 * every pixel, about 3 ms a frame on the lake, though shadows cover a few percent of the ground).
 * Plain geometry, no GL: the map is read back once after it is drawn.
 *
 * <p>A cell is shadowed when some texel under it (its corners' light-space box, widened by the
 * filter's reach) holds a depth nearer the sun than the cell's own surface there (the plane through
 * three of its corners in light space), by more than the bias and the fourth corner's distance from
 * that plane: so something stands between the cell and the sun. A cell seen edge-on by the sun is
 * marked. Every shadowed cell is marked (a lit one now and then, which only costs a little speed), and
 * the mask is widened by one cell all round so the soft edges of the filter stay inside it.
 */
final class SunlitCells {
    /** Texels beyond a cell's corners still read by the receivers' filter (bilinear taps, normal offset). */
    static final int FILTER_REACH = 3;

    private SunlitCells() {
    }

    /**
     * The mask over the grid's quads (index j * (columns - 1) + i), true where shadows may fall.
     * {@code vertices} are the terrain mesh's (stride floats each, position first), its grid vertex
     * (i, j) at index j * columns + i; {@code depth} the map's size x size depths, rows from the bottom.
     */
    static boolean[] shadowed(float[] depth, int size, Matrix4f lightViewProjection, float bias,
                              float[] vertices, int stride, int columns, int rows) {
        int nx = columns - 1, ny = rows - 1;
        // Each grid vertex in the map: texel coordinates and depth.
        float[] u = new float[columns * rows], v = new float[columns * rows], d = new float[columns * rows];
        Vector4f p = new Vector4f();
        for (int k = 0; k < columns * rows; k++) {
            lightViewProjection.transform(p.set(vertices[k * stride], vertices[k * stride + 1], vertices[k * stride + 2], 1f));
            u[k] = (p.x / p.w * 0.5f + 0.5f) * size;
            v[k] = (p.y / p.w * 0.5f + 0.5f) * size;
            d[k] = p.z / p.w * 0.5f + 0.5f;
        }
        boolean[] marked = new boolean[nx * ny];
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                int a = j * columns + i, b = a + 1, c = a + columns, e = c + 1;
                float minU = Math.min(Math.min(u[a], u[b]), Math.min(u[c], u[e]));
                float maxU = Math.max(Math.max(u[a], u[b]), Math.max(u[c], u[e]));
                float minV = Math.min(Math.min(v[a], v[b]), Math.min(v[c], v[e]));
                float maxV = Math.max(Math.max(v[a], v[b]), Math.max(v[c], v[e]));
                // The cell's surface in light space: depth = d[a] + gu (x - u[a]) + gv (y - v[a]).
                float bu = u[b] - u[a], bv = v[b] - v[a], cu = u[c] - u[a], cv = v[c] - v[a];
                float det = bu * cv - bv * cu;
                if (Math.abs(det) < 1e-6f) {
                    marked[j * nx + i] = true;
                    continue;
                }
                float gu = ((d[b] - d[a]) * cv - (d[c] - d[a]) * bv) / det;
                float gv = ((d[c] - d[a]) * bu - (d[b] - d[a]) * cu) / det;
                float bent = Math.abs(d[e] - (d[a] + gu * (u[e] - u[a]) + gv * (v[e] - v[a])));
                float slack = 3.5f * bias + bent;
                int x0 = Math.max(0, (int) Math.floor(minU) - FILTER_REACH), x1 = Math.min(size - 1, (int) Math.ceil(maxU) + FILTER_REACH);
                int y0 = Math.max(0, (int) Math.floor(minV) - FILTER_REACH), y1 = Math.min(size - 1, (int) Math.ceil(maxV) + FILTER_REACH);
                search:
                for (int y = y0; y <= y1; y++) {
                    for (int x = x0; x <= x1; x++) {
                        float surface = d[a] + gu * (x + 0.5f - u[a]) + gv * (y + 0.5f - v[a]);
                        if (depth[y * size + x] < surface - slack) {
                            marked[j * nx + i] = true;
                            break search;
                        }
                    }
                }
            }
        }
        boolean[] widened = new boolean[nx * ny];
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                if (!marked[j * nx + i]) continue;
                for (int dj = -1; dj <= 1; dj++) {
                    for (int di = -1; di <= 1; di++) {
                        int ii = i + di, jj = j + dj;
                        if (ii >= 0 && ii < nx && jj >= 0 && jj < ny) widened[jj * nx + ii] = true;
                    }
                }
            }
        }
        return widened;
    }

    /**
     * The mask as runs of cells in row-major order, alternating shadowed and sunlit, starting with
     * shadowed (possibly empty): run k spans cells [bounds[k], bounds[k + 1]). Sunlit gaps shorter than
     * {@code minSunlit} cells are folded into the shadowed runs around them (fewer draw calls).
     */
    static int[] runs(boolean[] shadowed, int minSunlit) {
        int n = shadowed.length;
        boolean[] merged = shadowed.clone();
        int i = 0;
        while (i < n) {
            if (merged[i]) {
                i++;
                continue;
            }
            int start = i;
            while (i < n && !merged[i]) i++;
            boolean inner = start > 0 && i < n;
            if (inner && i - start < minSunlit) java.util.Arrays.fill(merged, start, i, true);
        }
        int[] bounds = new int[n + 2];
        int count = 0;
        bounds[count++] = 0;
        boolean state = true;
        for (int k = 0; k < n; k++) {
            if (merged[k] != state) {
                bounds[count++] = k;
                state = merged[k];
            }
        }
        bounds[count++] = n;
        return java.util.Arrays.copyOf(bounds, count);
    }
}
