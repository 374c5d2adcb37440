package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;

/**
 * The sky's ground cells that can show the seaside's shore (SkyPass, {@link ShoreCells}), each cut
 * into {@link #SUB} x {@link #SUB} smaller cells, so that a software rasteriser pays sky.frag's
 * per-pixel sea (SEA_PIXEL) only in the small cells the shore's band crosses; the others take their
 * colour from their own corners, as the plain cells do. At 1280x720 a sky cell is 80 x 72 pixels and
 * the band (grass to beach, the water's edge, the foam) crosses it in a strip some 20 to 60 pixels
 * tall, so most of a band cell's pixels lie off the band. Plain geometry, no GL.
 */
final class ShoreSubCells {
    /** Small cells per side of a sky cell (20 x 18 pixels at 1280x720). */
    static final int SUB = 4;
    private static final int CORNERS = (SUB + 1) * (SUB + 1);

    /** The small cells' corners, NDC x and y, {@link #SUB} + 1 squared per sky cell. */
    final float[] vertices;
    /** Their triangles, grouped as SkyPass's programs: 0 band, 2 band near the sun, 4 off the band, 6 off it near the sun. */
    final int[] indices;
    private final int[] group;
    private final float[] groundX = new float[CORNERS], groundY = new float[CORNERS];
    private final float[] qx = new float[4], qy = new float[4];
    private final int[] counts = new int[8];
    private int vertexCount;

    ShoreSubCells(int maxCells) {
        vertices = new float[maxCells * CORNERS * 2];
        indices = new int[maxCells * SUB * SUB * 6];
        group = new int[maxCells * SUB * SUB];
    }

    /** Vertices written by the last {@link #build}. */
    int vertexCount() {
        return vertexCount;
    }

    /**
     * Cuts the sky cells whose triangles are {@code order[from .. from + count)} (six indices a cell,
     * the first its lower-left corner, as SkyPass.sortCells writes them; {@code sun}: near the sun)
     * and the cells of a second such run, and returns the indices per group (see {@link #indices}).
     */
    int[] build(Matrix4f inverseViewProjection, SkyPass.Shore shore, int[] order, int from, int count,
                int sunFrom, int sunCount, Vector4f near, Vector4f far) {
        java.util.Arrays.fill(counts, 0);
        vertexCount = 0;
        int cells = 0;
        for (int run = 0; run < 2; run++) {
            int first = run == 0 ? from : sunFrom, n = run == 0 ? count : sunCount;
            for (int k = first; k < first + n; k += 6) {
                int a = order[k], i = a % (SkyPass.GRID_X + 1), j = a / (SkyPass.GRID_X + 1);
                cut(inverseViewProjection, shore, i, j, run == 1, cells++, near, far);
            }
        }
        int[] next = new int[counts.length];
        for (int g = 1; g < counts.length; g++) next[g] = next[g - 1] + counts[g - 1];
        for (int c = 0; c < cells; c++) {
            int base = c * CORNERS;
            for (int t = 0; t < SUB; t++) {
                for (int s = 0; s < SUB; s++) {
                    int g = group[c * SUB * SUB + t * SUB + s];
                    int a = base + t * (SUB + 1) + s, b = a + 1, cc = a + SUB + 1, d = cc + 1;
                    SkyPass.putCell(indices, next[g], a, b, cc, d);
                    next[g] += 6;
                }
            }
        }
        return counts.clone();
    }

    /** The small cells of sky cell (i, j): their corners into {@link #vertices}, their groups into {@link #group}. */
    private void cut(Matrix4f inverseViewProjection, SkyPass.Shore shore, int i, int j, boolean sun, int cell,
                     Vector4f near, Vector4f far) {
        float x0 = 2f * i / SkyPass.GRID_X - 1f, y0 = 2f * j / SkyPass.GRID_Y - 1f;
        float sx = 2f / SkyPass.GRID_X / SUB, sy = 2f / SkyPass.GRID_Y / SUB;
        for (int t = 0; t <= SUB; t++) {
            for (int s = 0; s <= SUB; s++) {
                // The outer corners exactly as the sky cell's, so the small cells meet the big ones without cracks.
                float x = s == SUB ? 2f * (i + 1) / SkyPass.GRID_X - 1f : x0 + s * sx;
                float y = t == SUB ? 2f * (j + 1) / SkyPass.GRID_Y - 1f : y0 + t * sy;
                int v = t * (SUB + 1) + s;
                vertices[vertexCount * 2] = x;
                vertices[vertexCount * 2 + 1] = y;
                vertexCount++;
                inverseViewProjection.transform(near.set(x, y, -1f, 1f));
                inverseViewProjection.transform(far.set(x, y, 1f, 1f));
                float nx = near.x / near.w, ny = near.y / near.w, nz = near.z / near.w;
                float dx = far.x / far.w - nx, dy = far.y / far.w - ny, dz = far.z / far.w - nz;
                boolean hits = dz < 0 && nz > shore.level();
                float u = hits ? (shore.level() - nz) / dz : Float.NaN;
                groundX[v] = nx + dx * u;
                groundY[v] = ny + dy * u;
            }
        }
        for (int t = 0; t < SUB; t++) {
            for (int s = 0; s < SUB; s++) {
                int a = t * (SUB + 1) + s;
                boolean plain = SkyPass.plainGround(shore, groundX, groundY, qx, qy, a, a + 1, a + SUB + 2, a + SUB + 1);
                int g = (plain ? 4 : 0) | (sun ? 2 : 0);
                group[cell * SUB * SUB + t * SUB + s] = g;
                counts[g] += 6;
            }
        }
    }
}
