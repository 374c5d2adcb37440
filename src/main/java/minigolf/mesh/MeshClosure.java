package minigolf.mesh;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * Whether a mesh is closed and wound alike: every edge between two corners (corners at the same
 * position are one, whatever their normals or uvs) is used once in each direction by its two
 * triangles. Only then can a renderer skip the faces turned away from the camera without opening a
 * hole: from outside, a face seen from behind always lies behind a face seen from the front.
 */
public final class MeshClosure {
    private MeshClosure() {
    }

    public static boolean closed(TriangleMesh mesh) {
        Set<Long> edges = directedEdges(mesh);
        if (edges == null) return false;
        for (long e : edges) {
            if (!edges.contains(key((int) e, (int) (e >>> 32)))) return false;
        }
        return true;
    }

    /**
     * Whether neighbouring triangles are wound alike (no edge is used twice in the same direction), closed or
     * not: a mesh standing open on the ground can be wound alike, and a closed one wound against itself is not.
     */
    public static boolean woundAlike(TriangleMesh mesh) {
        return directedEdges(mesh) != null;
    }

    /** The edges between welded corners as (from, to) keys; null when one is used twice in the same direction. */
    private static Set<Long> directedEdges(TriangleMesh mesh) {
        int[] corner = weld(mesh.positions());
        int[] idx = mesh.indices();
        Set<Long> edges = new HashSet<>();
        for (int t = 0; t + 2 < idx.length; t += 3) {
            for (int k = 0; k < 3; k++) {
                int a = corner[idx[t + k]], b = corner[idx[t + (k + 1) % 3]];
                if (a == b) continue; // a degenerate edge bounds nothing
                // The same directed edge twice: two triangles wound against each other (or more than two).
                if (!edges.add(key(a, b))) return null;
            }
        }
        return edges;
    }

    private static long key(int from, int to) {
        return ((long) from << 32) | (to & 0xffffffffL);
    }

    /** One id per distinct position (-0 and 0 the same). */
    private static int[] weld(float[] positions) {
        Map<String, Integer> ids = new HashMap<>();
        int[] corner = new int[positions.length / 3];
        for (int v = 0; v < corner.length; v++) {
            String k = (positions[3 * v] + 0f) + "," + (positions[3 * v + 1] + 0f) + "," + (positions[3 * v + 2] + 0f);
            corner[v] = ids.computeIfAbsent(k, x -> ids.size());
        }
        return corner;
    }
}
