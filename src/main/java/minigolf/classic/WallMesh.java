package minigolf.classic;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A solid region of the pixel map as one triangle mesh, the way the course's model obstacles are
 * collided with and drawn: vertical sides along the region's simplified outline (within half a
 * pixel of the pixels, so diagonal and round walls are smooth) from just below the ground to the
 * wall's top, and a flat top made of the region's pixel rows merged into rectangles.
 * Touching pixels of one kind become one mesh, however many tiles they span.
 */
public final class WallMesh {
    private final List<double[]> vertices = new ArrayList<>();
    private final List<int[]> faces = new ArrayList<>();
    private final Map<String, Integer> index = new HashMap<>();

    /**
     * @param mask     the region's pixels
     * @param pixel    metres per pixel
     * @param bottom   z of the sides' lower edge (m, below the ground)
     * @param top      z of the top (m)
     */
    public static WallMesh of(PixelRegions.Mask mask, double pixel, double bottom, double top) {
        WallMesh m = new WallMesh();
        int h = mask.height();
        for (double[] ring : PixelRegions.outline(mask)) {
            double[] r = PixelRegions.simplify(ring, PixelRegions.TOLERANCE);
            int n = r.length / 2;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ax = r[2 * i] * pixel, ay = (h - r[2 * i + 1]) * pixel;
                double bx = r[2 * j] * pixel, by = (h - r[2 * j + 1]) * pixel;
                // Interior on the left in world coordinates: (a, b, b', a') faces outwards.
                m.quad(ax, ay, bottom, bx, by, bottom, bx, by, top, ax, ay, top);
            }
        }
        for (int[] rect : rectangles(mask)) {
            double x0 = rect[0] * pixel, x1 = rect[2] * pixel;
            double y0 = (h - rect[3]) * pixel, y1 = (h - rect[1]) * pixel;
            m.quad(x0, y0, top, x1, y0, top, x1, y1, top, x0, y1, top);
        }
        return m;
    }

    /**
     * The mask's pixels as rectangles {x0, y0, x1, y1} (pixel corners, y down): each row's runs,
     * a run merged with the identical run of the rows below.
     */
    static List<int[]> rectangles(PixelRegions.Mask mask) {
        List<int[]> done = new ArrayList<>();
        List<int[]> open = new ArrayList<>(); // rectangles still growing downwards
        for (int y = 0; y <= mask.height(); y++) {
            List<int[]> runs = new ArrayList<>();
            if (y < mask.height()) {
                for (int x = 0; x < mask.width(); ) {
                    if (!mask.at(x, y)) {
                        x++;
                        continue;
                    }
                    int s = x;
                    while (x < mask.width() && mask.at(x, y)) x++;
                    runs.add(new int[]{s, x});
                }
            }
            List<int[]> next = new ArrayList<>();
            for (int[] run : runs) {
                int[] grown = null;
                for (int[] r : open) {
                    if (r[0] == run[0] && r[2] == run[1]) {
                        grown = r;
                        break;
                    }
                }
                if (grown != null) {
                    open.remove(grown);
                    grown[3] = y + 1;
                    next.add(grown);
                } else {
                    next.add(new int[]{run[0], y, run[1], y + 1});
                }
            }
            done.addAll(open);
            open = next;
        }
        done.addAll(open);
        return done;
    }

    private void quad(double ax, double ay, double az, double bx, double by, double bz,
                      double cx, double cy, double cz, double dx, double dy, double dz) {
        int a = vertex(ax, ay, az), b = vertex(bx, by, bz), c = vertex(cx, cy, cz), d = vertex(dx, dy, dz);
        faces.add(new int[]{a, b, c});
        faces.add(new int[]{a, c, d});
    }

    private int vertex(double x, double y, double z) {
        String key = String.format(Locale.ROOT, "%.6f %.6f %.6f", x, y, z);
        Integer i = index.get(key);
        if (i != null) return i;
        vertices.add(new double[]{x, y, z});
        index.put(key, vertices.size()); // OBJ indices start at 1
        return vertices.size();
    }

    public int triangleCount() {
        return faces.size();
    }

    public int vertexCount() {
        return vertices.size();
    }

    /**
     * The region as one mesh, or, where that would pass a model's limits, as several: the region
     * cut into horizontal bands (the cut faces lie inside the wall, where no ball reaches).
     */
    public static List<WallMesh> split(PixelRegions.Mask mask, double pixel, double bottom, double top,
                                       int maxTriangles, int maxVertices) {
        for (int bands = 1; bands <= mask.height(); bands *= 2) {
            List<WallMesh> parts = new ArrayList<>();
            boolean fits = true;
            for (int b = 0; b < bands && fits; b++) {
                int y0 = mask.height() * b / bands, y1 = mask.height() * (b + 1) / bands;
                boolean[] set = new boolean[mask.set().length];
                boolean any = false;
                for (int y = y0; y < y1; y++) {
                    for (int x = 0; x < mask.width(); x++) {
                        boolean v = mask.at(x, y);
                        set[x + mask.width() * y] = v;
                        any |= v;
                    }
                }
                if (!any) continue;
                WallMesh m = of(new PixelRegions.Mask(mask.width(), mask.height(), set), pixel, bottom, top);
                fits = m.triangleCount() <= maxTriangles && m.vertexCount() <= maxVertices;
                parts.add(m);
            }
            if (fits) return parts;
        }
        throw new IllegalStateException("a wall region too large for the model limits even in one-pixel bands");
    }

    /** The mesh as Wavefront .obj text, using material {@code material} of {@code mtllib}. */
    public String obj(String mtllib, String material) {
        StringBuilder sb = new StringBuilder(64 * (vertices.size() + faces.size()) + 128);
        sb.append("# made by minigolf import-tracks from a classic track's pixel map\n");
        if (mtllib != null) sb.append("mtllib ").append(mtllib).append('\n');
        for (double[] v : vertices) {
            sb.append(String.format(Locale.ROOT, "v %.6f %.6f %.6f%n", v[0], v[1], v[2]));
        }
        if (material != null) sb.append("usemtl ").append(material).append('\n');
        for (int[] f : faces) sb.append("f ").append(f[0]).append(' ').append(f[1]).append(' ').append(f[2]).append('\n');
        return sb.toString();
    }
}
