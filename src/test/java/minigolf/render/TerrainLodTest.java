package minigolf.render;

import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import java.util.HashMap;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/** CPU-only: the chunks' levels of detail are watertight, cover their chunk once, and get coarser with distance. */
class TerrainLodTest {
    private final TerrainMesh mesh = TerrainMesh.build(TestCourses.lake(), TestCourses.LAKE, TerrainMesh.ColorMode.GREEN, 0.1);
    private final TerrainLod lod = new TerrainLod(mesh.data().vertices(), TerrainMesh.STRIDE, mesh.columns(), mesh.rows(), mesh.cellStarts(), 0.1);
    private final int[] indices = lod.indices(mesh.data().indices());

    @Test
    void chunksTileTheGridAndHaveTheLevelsTheirSizeAllows() {
        // 100 quads a side: chunks of 32, 32, 32 and 4.
        assertEquals(16, lod.chunks().size());
        for (TerrainLod.Chunk c : lod.chunks()) {
            int w = c.i1 - c.i0, h = c.j1 - c.j0;
            assertEquals(w == 4 || h == 4 ? 2 : 3, c.maxLevel(), "chunk " + w + "x" + h);
        }
    }

    /**
     * At every level the triangles' open edges (used by one triangle only) are exactly the chunk's
     * full-resolution border, and they cover the chunk's area once, counter-clockwise: neighbours
     * at any two levels share the same edge (no cracks, no T-junctions), and no part is missing or doubled.
     */
    @Test
    void everyLevelKeepsTheFullResolutionBorderAndCoversTheChunkOnce() {
        float[] v = mesh.data().vertices();
        for (TerrainLod.Chunk c : lod.chunks()) {
            Map<Long, Integer> fine = openEdges(c, 0);
            for (int level = 0; level <= c.maxLevel(); level++) {
                assertEquals(fine, openEdges(c, level), "level " + level);
                double area = 0;
                for (int n = c.first[level]; n < c.first[level] + c.count[level]; n += 3) {
                    int a = indices[n] * TerrainMesh.STRIDE, b = indices[n + 1] * TerrainMesh.STRIDE, d = indices[n + 2] * TerrainMesh.STRIDE;
                    double cross = (v[b] - v[a]) * (v[d + 1] - v[a + 1]) - (v[b + 1] - v[a + 1]) * (v[d] - v[a]);
                    assertTrue(cross > 0, "a counter-clockwise, non-degenerate triangle");
                    area += cross / 2;
                }
                assertEquals((c.i1 - c.i0) * 0.1 * (c.j1 - c.j0) * 0.1, area, 1e-4, "level " + level);
            }
            // The fine border has 4 x 32 edges on a whole chunk, far more than a coarse outline would.
            if (c.i1 - c.i0 == 32 && c.j1 - c.j0 == 32) assertEquals(128, fine.size());
        }
    }

    @Test
    void coarserLevelsDrawFarFewerTriangles() {
        TerrainLod.Chunk c = lod.chunks().get(0);
        assertEquals(32 * 32 * 6, c.indexCount(0));
        assertTrue(c.indexCount(1) < c.indexCount(0) / 2.5, "level 1: " + c.indexCount(1));
        assertTrue(c.indexCount(2) < c.indexCount(0) / 6, "level 2: " + c.indexCount(2));
        assertTrue(c.indexCount(3) < c.indexCount(2), "level 3: " + c.indexCount(3));
    }

    @Test
    void theLevelGrowsWithDistanceAndStopsAtTheChunksCoarsest() {
        TerrainLod.Chunk c = lod.chunks().get(0);
        double ppr = 700; // about 1280x720 with a 55 degree vertical field of view
        // A 10 cm quad is 8 px at 8.75 m: 20 cm quads from 17.5 m, 40 cm from 35 m, 80 cm from 70 m.
        assertEquals(0, lod.level(c, 0, ppr));
        assertEquals(0, lod.level(c, 17, ppr));
        assertEquals(1, lod.level(c, 18, ppr));
        assertEquals(2, lod.level(c, 40, ppr));
        assertEquals(3, lod.level(c, 1000, ppr));
        assertEquals(2, lod.level(lod.chunks().get(3), 1000, ppr), "a 4-quad chunk has no level 3");
        // The distance is to the chunk's box, zero inside it.
        assertEquals(0, TerrainLod.distance(c, new Vector3f(-4, -4, (c.min[2] + c.max[2]) / 2)), 1e-9);
        assertEquals(10, TerrainLod.distance(c, new Vector3f(-4, -4, 10 + c.max[2])), 1e-5);
    }

    /** Undirected edges (as vertex pairs) used by exactly one triangle of chunk c at a level. */
    private Map<Long, Integer> openEdges(TerrainLod.Chunk c, int level) {
        Map<Long, Integer> uses = new HashMap<>();
        for (int n = c.first[level]; n < c.first[level] + c.count[level]; n += 3) {
            for (int e = 0; e < 3; e++) {
                int a = indices[n + e], b = indices[n + (e + 1) % 3];
                long key = (long) Math.min(a, b) << 32 | Math.max(a, b);
                uses.merge(key, 1, Integer::sum);
            }
        }
        uses.values().removeIf(u -> u != 1);
        return uses;
    }
}
