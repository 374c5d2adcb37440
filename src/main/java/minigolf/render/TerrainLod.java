package minigolf.render;

import org.joml.FrustumIntersection;
import org.joml.Matrix4f;
import org.joml.Vector3f;

import java.util.ArrayList;
import java.util.List;

/**
 * Level of detail for the terrain's grid mesh (CPU only; {@link TerrainPass} draws it). The grid's
 * quads are split into square chunks of {@link #CHUNK} quads; each chunk has index lists at levels
 * 0..{@link #LEVELS}-1, level L sampling every 2^L-th grid vertex, all into the same vertex buffer
 * (so live patches of the vertices update every level at once).
 *
 * <p>No cracks: at every level a chunk keeps <em>all</em> the full-resolution vertices along its own
 * border; only its inside is coarser. The coarse cells that touch the border are fans from their
 * centre (a grid vertex, since 2^L is even) to the full-resolution border points and the coarse
 * corners, so two neighbouring chunks always share the same edge whatever their levels, and the
 * skirts (full resolution) meet every chunk exactly. A chunk that changes level changes only inside.
 *
 * <p>Choice per frame ({@link #select}): the coarsest level whose quads still project to at most
 * {@link #TARGET_PIXELS} pixels at the chunk's nearest point to the eye; chunks outside the view
 * frustum are not drawn. A chunk with a deleted cell, or whose size is not a multiple of 2^L, stays
 * at the finer levels it can have.
 */
public final class TerrainLod {
    /** Quads along a chunk's side. */
    public static final int CHUNK = 32;
    /** Levels 0 (every vertex) to 3 (every 8th). */
    public static final int LEVELS = 4;
    /** The largest projected quad side, in pixels, that a coarser level may have. */
    public static final double TARGET_PIXELS = 8;

    /** One chunk: its quads [i0, i1) x [j0, j1), its box in world space, and where its levels' indices lie. */
    public static final class Chunk {
        public final int i0, j0, i1, j1;
        final float[] min = new float[3], max = new float[3];
        /** Per level: first index (into the appended list) and count; count 0 where the level is unavailable. */
        final int[] first = new int[LEVELS], count = new int[LEVELS];
        /** No cell of the chunk can be in the shadow map's shadow (set by TerrainPass.setShadowedCells): drawn without the tap. */
        boolean allSunlit;
        /**
         * Of the level-0 indices, how many come first and need the shadow tap (TerrainPass.setShadowedCells
         * sorts the chunk's cells, those the map can darken first); the rest are drawn without it.
         */
        int shadowedAtLevel0 = -1;

        Chunk(int i0, int j0, int i1, int j1) {
            this.i0 = i0;
            this.j0 = j0;
            this.i1 = i1;
            this.j1 = j1;
        }

        /** The coarsest level this chunk has. */
        public int maxLevel() {
            int l = 0;
            while (l + 1 < LEVELS && count[l + 1] > 0) l++;
            return l;
        }

        public int indexCount(int level) {
            return count[level];
        }
    }

    private final List<Chunk> chunks = new ArrayList<>();
    private final int[] indices;
    private final double spacing;

    /**
     * Builds the chunks' index lists for a grid of {@code columns} x {@code rows} vertices (row-major,
     * vertex (i, j) at j*columns + i, {@code stride} floats a vertex with x, y, z first) whose quads
     * are {@code spacing} metres apart; {@code cellStarts} as {@link TerrainMesh#cellStarts()} (a cell
     * with no indices is deleted). Index values refer to the same vertices.
     */
    public TerrainLod(float[] vertices, int stride, int columns, int rows, int[] cellStarts, double spacing) {
        this.spacing = spacing;
        int nx = columns - 1, ny = rows - 1;
        IntList out = new IntList();
        for (int j0 = 0; j0 < ny; j0 += CHUNK) {
            for (int i0 = 0; i0 < nx; i0 += CHUNK) {
                Chunk c = new Chunk(i0, j0, Math.min(nx, i0 + CHUNK), Math.min(ny, j0 + CHUNK));
                boolean deleted = false;
                float zMin = Float.POSITIVE_INFINITY, zMax = Float.NEGATIVE_INFINITY;
                for (int j = c.j0; j <= c.j1; j++) {
                    for (int i = c.i0; i <= c.i1; i++) {
                        float z = vertices[(j * columns + i) * stride + 2];
                        zMin = Math.min(zMin, z);
                        zMax = Math.max(zMax, z);
                        if (i < c.i1 && j < c.j1 && cellStarts[j * nx + i + 1] == cellStarts[j * nx + i]) deleted = true;
                    }
                }
                int a = c.j0 * columns + c.i0, b = c.j1 * columns + c.i1;
                c.min[0] = vertices[a * stride];
                c.min[1] = vertices[a * stride + 1];
                c.min[2] = zMin;
                c.max[0] = vertices[b * stride];
                c.max[1] = vertices[b * stride + 1];
                c.max[2] = zMax;
                // Level 0: the mesh's own triangles, row by row.
                c.first[0] = out.size;
                for (int j = c.j0; j < c.j1; j++) {
                    for (int i = c.i0; i < c.i1; i++) {
                        int cell = j * nx + i;
                        for (int q = cellStarts[cell]; q < cellStarts[cell + 1]; q++) out.add(-1 - q); // resolved below
                    }
                }
                c.count[0] = out.size - c.first[0];
                for (int level = 1; level < LEVELS && !deleted; level++) {
                    int k = 1 << level;
                    if ((c.i1 - c.i0) % k != 0 || (c.j1 - c.j0) % k != 0) break;
                    c.first[level] = out.size;
                    coarse(out, vertices, stride, columns, c, k);
                    c.count[level] = out.size - c.first[level];
                }
                chunks.add(c);
            }
        }
        indices = out.toArray();
    }

    /** The level-0 entries hold -1 - (position in the mesh's own index list); this swaps in the indices themselves. */
    int[] indices(int[] meshIndices) {
        int[] r = indices.clone();
        for (int n = 0; n < r.length; n++) if (r[n] < 0) r[n] = meshIndices[-1 - r[n]];
        return r;
    }

    public List<Chunk> chunks() {
        return chunks;
    }

    /** Triangles of chunk c at step k: coarse quads inside, fans to the full-resolution border along the chunk's edge. */
    private static void coarse(IntList out, float[] v, int stride, int cols, Chunk c, int k) {
        int[] ring = new int[4 * k + 1];
        for (int j = c.j0; j < c.j1; j += k) {
            for (int i = c.i0; i < c.i1; i += k) {
                boolean south = j == c.j0, east = i + k == c.i1, north = j + k == c.j1, west = i == c.i0;
                int a = j * cols + i, b = a + k, d = a + k * cols, e = d + k;
                if (!(south || east || north || west)) {
                    float za = v[a * stride + 2], zb = v[b * stride + 2], zd = v[d * stride + 2], ze = v[e * stride + 2];
                    if (Math.abs(za - ze) <= Math.abs(zb - zd)) {
                        out.add(a, b, e);
                        out.add(a, e, d);
                    } else {
                        out.add(a, b, d);
                        out.add(b, e, d);
                    }
                    continue;
                }
                // The cell's outline, counter-clockwise from its south-west corner.
                int n = 0;
                int step = south ? 1 : k;
                for (int t = 0; t < k; t += step) ring[n++] = a + t;
                step = east ? 1 : k;
                for (int t = 0; t < k; t += step) ring[n++] = b + t * cols;
                step = north ? 1 : k;
                for (int t = 0; t < k; t += step) ring[n++] = e - t;
                step = west ? 1 : k;
                for (int t = 0; t < k; t += step) ring[n++] = d - t * cols;
                int centre = a + (k / 2) * cols + k / 2;
                for (int t = 0; t < n; t++) out.add(centre, ring[t], ring[(t + 1) % n]);
            }
        }
    }

    /**
     * Each chunk's level for a view (-1: outside the frustum), into {@code levels} (one per chunk).
     * {@code pixelsPerRadian}: the viewport's height over the vertical field of view's extent
     * (projection m11 x height / 2).
     */
    public void select(Matrix4f viewProjection, Vector3f eye, double pixelsPerRadian, int[] levels) {
        FrustumIntersection frustum = new FrustumIntersection(viewProjection, false);
        for (int n = 0; n < chunks.size(); n++) {
            Chunk c = chunks.get(n);
            if (!frustum.testAab(c.min[0], c.min[1], c.min[2], c.max[0], c.max[1], c.max[2])) {
                levels[n] = -1;
                continue;
            }
            levels[n] = level(c, distance(c, eye), pixelsPerRadian);
        }
    }

    /** The coarsest level of c whose quads are at most TARGET_PIXELS wide at {@code distance} metres. */
    int level(Chunk c, double distance, double pixelsPerRadian) {
        int max = c.maxLevel(), level = 0;
        while (level < max && spacing * (1 << (level + 1)) * pixelsPerRadian <= TARGET_PIXELS * Math.max(distance, 1e-6)) level++;
        return level;
    }

    static double distance(Chunk c, Vector3f eye) {
        double dx = Math.max(0, Math.max(c.min[0] - eye.x, eye.x - c.max[0]));
        double dy = Math.max(0, Math.max(c.min[1] - eye.y, eye.y - c.max[1]));
        double dz = Math.max(0, Math.max(c.min[2] - eye.z, eye.z - c.max[2]));
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Widens the z range of chunks (after a live edit changed heights) from the current vertices. */
    void refreshBoxes(float[] vertices, int stride, int columns) {
        for (Chunk c : chunks) {
            float zMin = Float.POSITIVE_INFINITY, zMax = Float.NEGATIVE_INFINITY;
            for (int j = c.j0; j <= c.j1; j++) {
                for (int i = c.i0; i <= c.i1; i++) {
                    float z = vertices[(j * columns + i) * stride + 2];
                    zMin = Math.min(zMin, z);
                    zMax = Math.max(zMax, z);
                }
            }
            c.min[2] = zMin;
            c.max[2] = zMax;
        }
    }

    private static final class IntList {
        int[] a = new int[1024];
        int size;

        void add(int x) {
            if (size == a.length) a = java.util.Arrays.copyOf(a, a.length * 2);
            a[size++] = x;
        }

        void add(int x, int y, int z) {
            add(x);
            add(y);
            add(z);
        }

        int[] toArray() {
            return java.util.Arrays.copyOf(a, size);
        }
    }
}
