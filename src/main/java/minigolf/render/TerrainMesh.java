package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.TerrainSpec;
import minigolf.course.Zone;
import minigolf.physics.FrictionField;
import minigolf.terrain.Terrain;
import minigolf.theme.Rgb;
import minigolf.theme.Theme;
import minigolf.theme.Themes;

import java.util.List;

/**
 * The course surface as a triangle grid over the bounds (world z up: course x, y horizontal, height
 * h up), plus earth-coloured side walls ("skirts") so the course reads as a solid slab. Normals come
 * from the analytic gradient, n = normalize(-dh/dx, -dh/dy, 1). Built on the CPU; see {@link Mesh}.
 */
public final class TerrainMesh {
    /** The finest sample spacing used, in metres (200 quads across a 10 m course). */
    public static final double MIN_SPACING = 0.05;
    /** The most quads along either axis. */
    public static final int MAX_QUADS = 256;
    /** Zones at least this rough are drawn as sand. */
    public static final double SAND_FRICTION = 0.2;
    /** Kinetic friction up to this is drawn as plain grass. */
    public static final double GRASS_FRICTION = 0.12;
    /** Zones at most this slick are drawn as ice (blended in up to {@link #GRASS_ICE_FRICTION}). */
    public static final double ICE_FRICTION = 0.03;
    public static final double GRASS_ICE_FRICTION = 0.06;
    /** From this kinetic friction on the ground is drawn as mud (the classic tracks' mud is 1.27, their sand 0.51). */
    public static final double MUD_FRICTION = 1.0;
    /**
     * Vertex layout: position, normal, colour and the mowing stripes' weight (1 on grass, 0 on sand,
     * mud, skirts and the height map). The stripes are drawn per pixel by the terrain shaders
     * ({@code stripes.glsl}), filtered to the pixel's footprint: as vertex colours they aliased
     * once the level of detail ({@link TerrainLod}) spaced vertices wider than a stripe.
     */
    public static final int[] LAYOUT = {3, 3, 4};
    /** The fourth colour component of the course's edge (its side walls): materials.glsl draws them in the world's rock or stone. */
    public static final float EDGE_CODE = 2;
    /** Floats a vertex. */
    public static final int STRIDE = 10;
    /** The mowing stripes' width (m) along x, from the course's minimum x; odd stripes are {@link #STRIPE_SHADE} as bright. */
    public static final double STRIPE_WIDTH = 0.5;
    public static final double STRIPE_SHADE = 0.92;

    /** How the surface is coloured. */
    public enum ColorMode {
        /** A putting green: darker low, lighter high, mowing stripes, sand and a muddy lake bed. */
        GREEN,
        /** A height map by altitude: blue (under water), green, yellow, brown, white. */
        HEIGHT_MAP;

        public ColorMode next() {
            return values()[(ordinal() + 1) % values().length];
        }
    }

    private final MeshData data;
    private final int columns;
    private final int rows;
    private final double minHeight;
    private final double maxHeight;
    private final int[] cellStarts;

    private TerrainMesh(MeshData data, int columns, int rows, double minHeight, double maxHeight, int[] cellStarts) {
        this.data = data;
        this.cellStarts = cellStarts;
        this.columns = columns;
        this.rows = rows;
        this.minHeight = minHeight;
        this.maxHeight = maxHeight;
    }

    /** The sample spacing for these bounds: {@link #MIN_SPACING}, coarser where needed to stay within {@link #MAX_QUADS}. */
    public static double sampleSpacing(Bounds b) {
        return sampleSpacing(b, MIN_SPACING);
    }

    /** As above with a coarser finest spacing (software rasterisers pay per triangle; see RenderQuality). */
    public static double sampleSpacing(Bounds b, double minSpacing) {
        return Math.max(Math.max(MIN_SPACING, minSpacing), Math.max(b.width(), b.depth()) / MAX_QUADS);
    }

    static int quads(double extent, double spacing) {
        return Math.max(1, Math.min(MAX_QUADS, (int) Math.ceil(extent / spacing - 1e-9)));
    }

    public static TerrainMesh build(Course course, Terrain terrain, ColorMode mode) {
        return build(course, terrain, mode, MIN_SPACING);
    }

    /** As above with samples at least {@code minSpacing} metres apart (the same surface, fewer triangles). */
    public static TerrainMesh build(Course course, Terrain terrain, ColorMode mode, double minSpacing) {
        Bounds b = course.bounds();
        double spacing = sampleSpacing(b, minSpacing);
        int nx = quads(b.width(), spacing), ny = quads(b.depth(), spacing);
        int cols = nx + 1, rows = ny + 1;
        double dx = b.width() / nx, dy = b.depth() / ny;
        double[] h = new double[cols * rows], gx = new double[cols * rows], gy = new double[cols * rows];
        double[] s = new double[3];
        double minH = Double.POSITIVE_INFINITY, maxH = Double.NEGATIVE_INFINITY;
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) {
                terrain.sample(b.minX() + i * dx, b.minY() + j * dy, s);
                int k = j * cols + i;
                h[k] = s[0];
                gx[k] = s[1];
                gy[k] = s[2];
                minH = Math.min(minH, s[0]);
                maxH = Math.max(maxH, s[0]);
            }
        }
        double base = skirtBase(minH, b);
        int skirtVertices = 2 * 2 * (cols + rows);
        float[] v = new float[(cols * rows + skirtVertices) * STRIDE];
        int[] idx = new int[nx * ny * 6 + 2 * 6 * (nx + ny)];
        float[] rgb = new float[3];
        Theme.Materials palette = Themes.of(course.world()).materials();
        // Friction as physics sees it: zones, else the grid's per-node values, else the course's.
        FrictionField friction = new FrictionField(course.physics(), course.zones(), course.terrain());
        double slick = slickness(course);
        int p = 0;
        for (int j = 0; j < rows; j++) {
            for (int i = 0; i < cols; i++) {
                int k = j * cols + i;
                double x = b.minX() + i * dx, y = b.minY() + j * dy;
                double len = Math.sqrt(gx[k] * gx[k] + gy[k] * gy[k] + 1);
                double stripes = unstripedColor(mode, palette, friction.kinetic(x, y) / slick, friction.hazardAt(x, y), x, y, h[k], minH, maxH, rgb);
                p = put(v, p, x, y, h[k], -gx[k] / len, -gy[k] / len, 1 / len, rgb, stripes);
            }
        }
        int q = 0;
        // Deleted grid cells are holes in the course: their quads are left out.
        TerrainSpec.HeightGrid mask = course.terrain() instanceof TerrainSpec.HeightGrid g && g.deletedCount() > 0 ? g : null;
        int[] cellStarts = new int[nx * ny + 1];
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                cellStarts[j * nx + i] = q;
                if (mask != null && mask.isDeletedAt(b.minX() + (i + 0.5) * dx, b.minY() + (j + 0.5) * dy)) continue;
                int a = j * cols + i, c = a + cols;
                // Split each quad along the diagonal that better follows the surface.
                if (Math.abs(h[a] - h[c + 1]) <= Math.abs(h[a + 1] - h[c])) {
                    q = tri(idx, q, a, a + 1, c + 1);
                    q = tri(idx, q, a, c + 1, c);
                } else {
                    q = tri(idx, q, a, a + 1, c);
                    q = tri(idx, q, a + 1, c + 1, c);
                }
            }
        }
        cellStarts[nx * ny] = q;
        // Skirts: for each edge, a strip from the surface down to the base, facing outwards.
        int vertex = cols * rows;
        int[][] edges = {
                {0, 0, 1, 0, cols, 0, -1},          // y = minY, running +x, normal -y
                {cols - 1, 0, 0, 1, rows, 1, 0},    // x = maxX, running +y, normal +x
                {cols - 1, rows - 1, -1, 0, cols, 0, 1}, // y = maxY, running -x, normal +y
                {0, rows - 1, 0, -1, rows, -1, 0}}; // x = minX, running -y, normal -x
        for (int[] e : edges) {
            int start = vertex;
            for (int t = 0; t < e[4]; t++) {
                int i = e[0] + t * e[2], j = e[1] + t * e[3];
                double x = b.minX() + i * dx, y = b.minY() + j * dy, top = h[j * cols + i];
                edge(palette, top, top, rgb);
                p = put(v, p, x, y, top, e[5], e[6], 0, rgb, EDGE_CODE);
                edge(palette, top, base, rgb);
                p = put(v, p, x, y, base, e[5], e[6], 0, rgb, EDGE_CODE);
                vertex += 2;
            }
            for (int t = 0; t + 1 < e[4]; t++) {
                int top0 = start + 2 * t, bot0 = top0 + 1, top1 = top0 + 2, bot1 = top0 + 3;
                q = tri(idx, q, top0, bot0, bot1);
                q = tri(idx, q, top0, bot1, top1);
            }
        }
        if (q < idx.length) idx = java.util.Arrays.copyOf(idx, q);
        return new TerrainMesh(new MeshData(LAYOUT, v, idx), cols, rows, minH, maxH, cellStarts);
    }

    /** Surface vertices of whole mesh rows, to overwrite a built mesh's vertex buffer from {@code firstFloat}. */
    public record Patch(int firstFloat, float[] vertices) {
    }

    /**
     * The surface vertices (positions, normals, colours as {@link #build} makes them) of the mesh
     * rows that cover [minX, maxX] x [minY, maxY], for a live update after the terrain changed
     * there. Colours use the given height range (the built mesh's), so the patch matches its
     * surroundings; the skirts and the triangulation are left as they are. Null if the region
     * misses the course.
     */
    public static Patch surfacePatch(Course course, Terrain terrain, ColorMode mode, double minH, double maxH,
                                     double minX, double minY, double maxX, double maxY) {
        return surfacePatch(course, terrain, mode, minH, maxH, minX, minY, maxX, maxY, MIN_SPACING);
    }

    /** As above for a mesh built with {@code minSpacing} (see {@link #build(Course, Terrain, ColorMode, double)}). */
    public static Patch surfacePatch(Course course, Terrain terrain, ColorMode mode, double minH, double maxH,
                                     double minX, double minY, double maxX, double maxY, double minSpacing) {
        Bounds b = course.bounds();
        double spacing = sampleSpacing(b, minSpacing);
        int nx = quads(b.width(), spacing), ny = quads(b.depth(), spacing);
        int cols = nx + 1, rows = ny + 1;
        double dx = b.width() / nx, dy = b.depth() / ny;
        int j0 = Math.max(0, (int) Math.floor((minY - b.minY()) / dy));
        int j1 = Math.min(rows - 1, (int) Math.ceil((maxY - b.minY()) / dy));
        if (j0 > j1 || maxX < b.minX() || minX > b.maxX()) return null;
        FrictionField friction = new FrictionField(course.physics(), course.zones(), course.terrain());
        double slick = slickness(course);
        Theme.Materials palette = Themes.of(course.world()).materials();
        float[] v = new float[(j1 - j0 + 1) * cols * STRIDE];
        double[] s = new double[3];
        float[] rgb = new float[3];
        int p = 0;
        for (int j = j0; j <= j1; j++) {
            for (int i = 0; i < cols; i++) {
                double x = b.minX() + i * dx, y = b.minY() + j * dy;
                terrain.sample(x, y, s);
                double len = Math.sqrt(s[1] * s[1] + s[2] * s[2] + 1);
                double stripes = unstripedColor(mode, palette, friction.kinetic(x, y) / slick, friction.hazardAt(x, y), x, y, s[0], minH, maxH, rgb);
                p = put(v, p, x, y, s[0], -s[1] / len, -s[2] / len, 1 / len, rgb, stripes);
            }
        }
        return new Patch(j0 * cols * STRIDE, v);
    }

    private static int put(float[] v, int p, double x, double y, double z, double nx, double ny, double nz, float[] c,
                           double stripes) {
        p = Shapes.putPnc(v, p, x, y, z, nx, ny, nz, c[0], c[1], c[2]);
        v[p++] = (float) stripes;
        return p;
    }

    private static int tri(int[] idx, int q, int a, int b, int c) {
        idx[q++] = a;
        idx[q++] = b;
        idx[q++] = c;
        return q;
    }

    /** The course's edge (the plinth's side) at height z below its top: the world's edge colour, darker lower down. */
    private static void edge(Theme.Materials palette, double top, double z, float[] out) {
        double t = Math.min(1, Math.max(0, (top - z) / 0.6));
        double k = lerp(1.0, 0.58, t);
        Rgb c = palette.edgeColor();
        set(out, c.r() * k, c.g() * k, c.b() * k);
    }

    /**
     * What the frictions are divided by before they choose a colour: 1, or for a course whose own
     * friction is below {@link #GRASS_ICE_FRICTION} (the classic tracks' grass is 0.041) that
     * friction's share of it, so that its own grass is drawn as grass and only what is slicker
     * than it as ice.
     */
    static double slickness(minigolf.course.Course course) {
        double own = course.physics().kineticFriction();
        return own > 0 && own < GRASS_ICE_FRICTION ? own / GRASS_ICE_FRICTION : 1;
    }

    /** The colour of the surface at (x, y) with height h, for a terrain spanning [minH, maxH]. */
    public static void surfaceColor(ColorMode mode, List<Zone> zones, double x, double y, double h,
                                    double minH, double maxH, Bounds b, float[] out) {
        Zone zone = null;
        for (Zone z : zones) {
            if (z.shape().contains(x, y)) zone = z; // later zones win
        }
        // Outside every zone: plain grass.
        double weight = unstripedColor(mode, Themes.MEADOWBROOK.materials(), zone != null ? zone.kineticFriction() : GRASS_FRICTION,
                zone != null ? zone.hazard() : null, x, y, h, minH, maxH, out);
        stripe(weight, x, b, out);
    }

    /**
     * The colour at (x, y) where the kinetic friction is {@code kineticFriction}: grass up to
     * {@link #GRASS_FRICTION}, sand from {@link #SAND_FRICTION}, blended in between (so a grid's
     * bilinear friction patch shows as sand with a soft edge).
     */
    public static void surfaceColor(ColorMode mode, double kineticFriction, double x, double y, double h,
                                    double minH, double maxH, Bounds b, float[] out) {
        stripe(unstripedColor(mode, Themes.MEADOWBROOK.materials(), kineticFriction, null, x, y, h, minH, maxH, out), x, b, out);
    }

    /** Mowing stripes across x, as on a real green (the terrain shaders draw the same per pixel), with this weight. */
    private static void stripe(double weight, double x, Bounds b, float[] out) {
        double stripe = Math.floorMod((long) Math.floor((x - b.minX()) / STRIPE_WIDTH), 2) == 0 ? 1.0 : STRIPE_SHADE;
        double f = lerp(1, stripe, weight);
        set(out, out[0] * f, out[1] * f, out[2] * f);
    }

    /**
     * The colour without the mowing stripes, into {@code out}; returns the stripes' weight there
     * (1 - the sand's share on grass, 0 under water, in hazard zones, on ice and mud and on the
     * height map).
     *
     * @param hazard the hazard of the zone there, or null: water and acid zones (the classic
     *               tracks' pools) are drawn flat blue and green, shallow ones lighter
     */
    static double unstripedColor(ColorMode mode, Theme.Materials palette, double kineticFriction, Zone.Hazard hazard,
                                 double x, double y, double h, double minH, double maxH, float[] out) {
        if (mode == ColorMode.HEIGHT_MAP) {
            heightMapColor(h, minH, maxH, out);
            return 0;
        }
        if (h < 0) {
            // Lake bed: wet mud, darker with depth.
            double t = Math.min(1, -h / 0.3);
            Rgb bed = palette.lakeBed();
            double k = lerp(1.0, 0.55, t);
            set(out, bed.r() * k, bed.g() * k, bed.b() * k);
            return 0;
        }
        double ripple = 0.96 + 0.04 * Math.sin(x * 23.0 + y * 7.0);
        if (hazard != null) {
            boolean shallow = hazard.when() == Zone.Hazard.When.REST;
            if (hazard.kind() == Zone.Hazard.Kind.ACID) {
                set(out, (shallow ? 0.62 : 0.46) * ripple, (shallow ? 0.86 : 0.74) * ripple, (shallow ? 0.30 : 0.10) * ripple);
            } else {
                set(out, (shallow ? 0.36 : 0.14) * ripple, (shallow ? 0.62 : 0.40) * ripple, (shallow ? 0.86 : 0.76) * ripple);
            }
            return 0;
        }
        if (kineticFriction >= MUD_FRICTION) {
            set(out, 0.42 * ripple, 0.30 * ripple, 0.17 * ripple);
            return 0;
        }
        double sand = Math.min(1, Math.max(0, (kineticFriction - GRASS_FRICTION) / (SAND_FRICTION - GRASS_FRICTION)));
        double ice = Math.min(1, Math.max(0, (GRASS_ICE_FRICTION - kineticFriction) / (GRASS_ICE_FRICTION - ICE_FRICTION)));
        double grain = 0.97 + 0.03 * Math.sin(x * 41.0) * Math.sin(y * 37.0);
        Rgb s = palette.sand();
        if (sand >= 1) {
            set(out, s.r() * grain, s.g() * grain, s.b() * grain);
            return 0;
        }
        double range = maxH - Math.max(minH, 0);
        double t = range > 1e-6 ? (h - Math.max(minH, 0)) / range : 0.5;
        t = Math.min(1, Math.max(0, t));
        Rgb grass = palette.grassLow().mix(palette.grassHigh(), t);
        // Ice: the grass seen through a pale blue glaze.
        grass = grass.mix(grass.mix(ICE, 0.75), ice);
        set(out, lerp(grass.r(), s.r() * grain, sand), lerp(grass.g(), s.g() * grain, sand), lerp(grass.b(), s.b() * grain, sand));
        return (1 - sand) * (1 - ice);
    }

    /** The colour of ice over grass. */
    private static final Rgb ICE = Rgb.of(0.78, 0.90, 0.97);

    private static final float[][] HEIGHT_STOPS = {
            {0.16f, 0.62f, 0.22f}, // green
            {0.93f, 0.86f, 0.32f}, // yellow
            {0.55f, 0.36f, 0.18f}, // brown
            {0.97f, 0.97f, 0.97f}, // white
    };

    /** Course-map colouring: blue under water (darker when deeper), then green, yellow, brown, white up to maxH. */
    public static void heightMapColor(double h, double minH, double maxH, float[] out) {
        if (h < 0) {
            double t = minH < 0 ? Math.min(1, h / minH) : 0;
            set(out, lerp(0.35, 0.08, t), lerp(0.60, 0.22, t), lerp(0.95, 0.62, t));
            return;
        }
        double t = maxH > 1e-6 ? Math.min(1, h / maxH) : 0;
        double f = t * (HEIGHT_STOPS.length - 1);
        int i = Math.min(HEIGHT_STOPS.length - 2, (int) f);
        double u = f - i;
        float[] a = HEIGHT_STOPS[i], c = HEIGHT_STOPS[i + 1];
        set(out, lerp(a[0], c[0], u), lerp(a[1], c[1], u), lerp(a[2], c[2], u));
    }

    private static double lerp(double a, double b, double t) {
        return a + (b - a) * t;
    }

    private static void set(float[] out, double r, double g, double b) {
        out[0] = (float) r;
        out[1] = (float) g;
        out[2] = (float) b;
    }

    public MeshData data() {
        return data;
    }

    /** Grid vertices along x (quads + 1); vertex (i, j) of the surface is vertex j*columns + i. */
    public int columns() {
        return columns;
    }

    public int rows() {
        return rows;
    }

    /**
     * Where each row of quads starts in the index list: the surface's triangles between grid rows j
     * and j + 1 are indices {@code rowStarts[j]} to {@code rowStarts[j + 1]}; from {@code rowStarts[rows - 1]}
     * on come the skirts. A copy.
     */
    public int[] rowStarts() {
        int nx = columns - 1, ny = rows - 1;
        int[] starts = new int[ny + 1];
        for (int j = 0; j <= ny; j++) starts[j] = cellStarts[j * nx];
        return starts;
    }

    /**
     * Where each quad's triangles start in the index list, row-major (quad (i, j) is entry
     * j * (columns - 1) + i; a deleted quad has none), and one entry more where the skirts start. A copy.
     */
    public int[] cellStarts() {
        return cellStarts.clone();
    }

    /** One side of the skirts: its index range and its outward normal (every vertex of a side has it). */
    public record SkirtSide(int first, int count, int normalX, int normalY) {
    }

    /** The skirts' four sides in drawing order (y = min, x = max, y = max, x = min), as {@link #build} makes them. */
    public List<SkirtSide> skirtSides() {
        int first = cellStarts[cellStarts.length - 1], along = 6 * (columns - 1), across = 6 * (rows - 1);
        return List.of(new SkirtSide(first, along, 0, -1), new SkirtSide(first + along, across, 1, 0),
                new SkirtSide(first + along + across, along, 0, 1), new SkirtSide(first + 2 * along + across, across, -1, 0));
    }

    /** The height the skirts reach down to, for terrain whose lowest sample is {@code minHeight}: where the slab stands. */
    public static double skirtBase(double minHeight, Bounds b) {
        return Math.min(minHeight, 0) - Math.max(0.25, 0.015 * Math.max(b.width(), b.depth()));
    }

    public double minHeight() {
        return minHeight;
    }

    public double maxHeight() {
        return maxHeight;
    }
}
