package minigolf.scenery;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A unit icosahedron subdivided once (42 points, 80 faces, counter-clockwise from outside): the props' lumps;
 * and the icosahedron itself (its 12 points are the first 12, 20 faces) for the smallest ones on the software tier.
 */
final class Icosphere {
    private static final double[][] POINTS;
    private static final int[][] FACES;
    private static final int[][] PLAIN_FACES;

    static {
        double t = (1 + Math.sqrt(5)) / 2;
        List<double[]> p = new ArrayList<>();
        double[][] base = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (double[] b : base) p.add(unit(b));
        int[][] f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6},
                {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        Map<Long, Integer> mid = new HashMap<>();
        List<int[]> faces = new ArrayList<>();
        for (int[] tri : f) {
            int a = midpoint(p, mid, tri[0], tri[1]), b = midpoint(p, mid, tri[1], tri[2]), c = midpoint(p, mid, tri[2], tri[0]);
            faces.add(new int[]{tri[0], a, c});
            faces.add(new int[]{tri[1], b, a});
            faces.add(new int[]{tri[2], c, b});
            faces.add(new int[]{a, b, c});
        }
        // The base icosahedron lies on an edge; turn it so that a vertex points straight up (z).
        double angle = Math.atan2(1, t);
        for (double[] q : p) {
            double y = q[1] * Math.cos(angle) - q[0] * Math.sin(angle), x = q[1] * Math.sin(angle) + q[0] * Math.cos(angle);
            double z = q[2];
            q[0] = x;
            q[1] = z;
            q[2] = y;
        }
        POINTS = p.toArray(new double[0][]);
        FACES = faces.toArray(new int[0][]);
        PLAIN_FACES = new int[f.length][];
        for (int k = 0; k < f.length; k++) PLAIN_FACES[k] = f[k].clone();
        // The swap of y and z above mirrors the shape: restore counter-clockwise faces.
        for (int[][] all : new int[][][]{FACES, PLAIN_FACES}) {
            for (int[] face : all) {
                int s = face[1];
                face[1] = face[2];
                face[2] = s;
            }
        }
    }

    private Icosphere() {
    }

    static double[][] points() {
        return POINTS;
    }

    static int[][] faces() {
        return FACES;
    }

    /** The plain icosahedron's 20 faces, over the first 12 of {@link #points()}. */
    static int[][] plainFaces() {
        return PLAIN_FACES;
    }

    private static int midpoint(List<double[]> p, Map<Long, Integer> cache, int a, int b) {
        long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
        Integer hit = cache.get(key);
        if (hit != null) return hit;
        double[] pa = p.get(a), pb = p.get(b);
        p.add(unit(new double[]{(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2}));
        cache.put(key, p.size() - 1);
        return p.size() - 1;
    }

    private static double[] unit(double[] q) {
        double l = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        return new double[]{q[0] / l, q[1] / l, q[2] / l};
    }
}
