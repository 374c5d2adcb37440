package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Obstacle;

import java.util.ArrayList;
import java.util.List;

/**
 * What stands round the course, so it does not float in an empty sky: a meadow disc at the foot of
 * the slab's side walls and decorative trees (the obstacles' trunk and crown meshes) beyond the
 * bounds, fading with distance into the sky's haze below the horizon (surroundings.frag matches
 * sky.vert's colours, so the disc's edge never shows). One static mesh, one draw call; drawn after
 * the course's opaque passes (early depth test skips what the course covers) and before the sky.
 * Decoration only: physics, the camera's clearance, the shadow map and the minimap never see it.
 */
public final class SurroundingsPass implements RenderPass {
    /** The meadow's radius round the course's centre (metres); it is wholly faded well before its edge. */
    static final double MEADOW_RADIUS = 200;
    /** The meadow's rings (metres from the centre), the last at its edge, and the segments round each. */
    static final double[] MEADOW_RINGS = {6, 10, 15, 21, 28, 36, 45, 55, 67, 81, 97, 115, 140, 170, MEADOW_RADIUS};
    static final int MEADOW_SEGMENTS = 64;
    /** Duller and darker than the course's grass, and without its mowing stripes. */
    static final float[] MEADOW_COLOR = {0.29f, 0.45f, 0.18f};
    /** Horizontal distances from the eye over which the meadow and the trees fade into the sky's haze. */
    static final float FADE_START = 25f, FADE_END = 125f;
    /** Trees per quality: llvmpipe pays per triangle (a tree is about 300). */
    static final int TREES_HIGH = 48, TREES_SOFTWARE = 24;

    private final ShaderProgram shader;
    private final Mesh mesh;
    private final Layout layout;
    private final Bounds bounds;
    private final List<Obstacle.Tree> trees;
    private final double level;

    /** Round a course with these bounds, whose slab stands at height {@code level} (its skirts' base). */
    public SurroundingsPass(Bounds bounds, double level, int treeCount) {
        this.level = level;
        this.bounds = bounds;
        this.trees = TreePlacement.around(bounds, treeCount);
        layout = build(bounds, level, trees);
        ShaderProgram s = ShaderProgram.load("surroundings");
        try {
            mesh = new Mesh(layout.data());
        } catch (RuntimeException e) {
            s.close();
            throw e;
        }
        shader = s;
    }

    /** The trees' count for a quality. */
    static int treesFor(RenderQuality quality) {
        return quality.vertexLit() ? TREES_SOFTWARE : TREES_HIGH;
    }

    /**
     * The mesh: trunks, crowns, then the meadow (the meadow behind the trees then fails the depth
     * test); per tree its trunk's and its crown's index runs and its box, so a frame can skip trees.
     */
    record Layout(MeshData data, List<ObstacleMeshes.Piece> trunks, List<ObstacleMeshes.Piece> crowns, int meadowFirst) {
    }

    static Layout build(Bounds b, double level, List<Obstacle.Tree> trees) {
        MeshData meadow = meadow((b.minX() + b.maxX()) / 2, (b.minY() + b.maxY()) / 2, level);
        if (trees.isEmpty()) return new Layout(meadow, List.of(), List.of(), 0);
        ObstacleMeshes.Built built = ObstacleMeshes.build(List.copyOf(trees), (x, y) -> level, m -> null);
        int shift = built.solid().indices().length;
        List<ObstacleMeshes.Piece> crowns = new ArrayList<>();
        for (ObstacleMeshes.Piece c : built.decorationPieces()) crowns.add(new ObstacleMeshes.Piece(shift + c.first(), c.count(), c.box()));
        MeshData wood = MeshData.concat(built.solid(), built.decoration());
        return new Layout(MeshData.concat(wood, meadow), built.solidPieces(), List.copyOf(crowns), wood.indices().length);
    }

    /**
     * A flat disc facing up: a fan round the centre, then rings further apart outwards (the fade is
     * computed per vertex, so it needs vertices where it changes).
     */
    static MeshData meadow(double cx, double cy, double z) {
        int rings = MEADOW_RINGS.length, n = MEADOW_SEGMENTS;
        float[] v = new float[(1 + rings * n) * 9];
        int[] idx = new int[3 * n + 6 * n * (rings - 1)];
        float[] c = MEADOW_COLOR;
        int p = Shapes.putPnc(v, 0, cx, cy, z, 0, 0, 1, c[0], c[1], c[2]);
        for (double r : MEADOW_RINGS) {
            for (int k = 0; k < n; k++) {
                double a = 2 * Math.PI * k / n;
                p = Shapes.putPnc(v, p, cx + r * Math.cos(a), cy + r * Math.sin(a), z, 0, 0, 1, c[0], c[1], c[2]);
            }
        }
        int q = 0;
        for (int k = 0; k < n; k++) {
            idx[q++] = 0;
            idx[q++] = 1 + k;
            idx[q++] = 1 + (k + 1) % n;
        }
        for (int ring = 0; ring + 1 < rings; ring++) {
            int inner = 1 + ring * n, outer = inner + n;
            for (int k = 0; k < n; k++) {
                int k1 = (k + 1) % n;
                idx[q++] = inner + k;
                idx[q++] = outer + k;
                idx[q++] = outer + k1;
                idx[q++] = inner + k;
                idx[q++] = outer + k1;
                idx[q++] = inner + k1;
            }
        }
        return new MeshData(MeshData.PNC, v, idx);
    }

    public List<Obstacle.Tree> trees() {
        return trees;
    }

    /** The meadow's height. */
    public double level() {
        return level;
    }

    @Override
    public void render(FrameContext frame) {
        shader.use();
        Lighting.apply(shader, frame);
        shader.set("uViewProjection", frame.viewProjection);
        shader.set("uClipPlane", frame.clipPlane);
        shader.set("uFade", FADE_START, FADE_END);
        boolean[] drawn = drawnTrees(frame);
        drawRuns(layout.trunks(), drawn);
        drawRuns(layout.crowns(), drawn);
        mesh.drawRange(layout.meadowFirst(), layout.data().indices().length - layout.meadowFirst());
    }

    /**
     * The trees to draw: those on screen, except those that stand in front of the course (nearer the
     * eye than the course's nearest edge and over it on screen), which would hide the play.
     */
    boolean[] drawnTrees(FrameContext frame) {
        int w = frame.viewportWidth, h = frame.viewportHeight;
        int[] viewport = {0, 0, w, h};
        ScreenBounds course = new ScreenBounds(frame.viewProjection, w, h);
        course.addBox(new float[]{(float) bounds.minX(), (float) bounds.minY(), (float) level,
                (float) bounds.maxX(), (float) bounds.maxY(), (float) level + 1f});
        int[] courseRect = course.rect(0, 0);
        double edge = TreePlacement.distance(bounds, frame.eye.x, frame.eye.y);
        boolean[] drawn = new boolean[layout.trunks().size()];
        for (int i = 0; i < drawn.length; i++) {
            float[] box = union(layout.trunks().get(i).box(), i < layout.crowns().size() ? layout.crowns().get(i).box() : null);
            ScreenBounds tree = new ScreenBounds(frame.viewProjection, w, h);
            tree.addBox(box);
            if (!tree.meets(viewport)) continue;
            double x = 0.5 * (box[0] + box[3]), y = 0.5 * (box[1] + box[4]);
            boolean inFront = Math.hypot(x - frame.eye.x, y - frame.eye.y) < edge && courseRect != null && tree.meets(courseRect);
            drawn[i] = !inFront;
        }
        return drawn;
    }

    private static float[] union(float[] a, float[] b) {
        if (b == null) return a;
        return new float[]{Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.min(a[2], b[2]),
                Math.max(a[3], b[3]), Math.max(a[4], b[4]), Math.max(a[5], b[5])};
    }

    /** The drawn trees' pieces (consecutive index runs), neighbouring ones as one draw. */
    private void drawRuns(List<ObstacleMeshes.Piece> pieces, boolean[] drawn) {
        int runFirst = -1, runEnd = -1;
        for (int i = 0; i < pieces.size(); i++) {
            ObstacleMeshes.Piece p = pieces.get(i);
            if (!drawn[i]) continue;
            if (p.first() == runEnd) {
                runEnd += p.count();
                continue;
            }
            if (runFirst >= 0) mesh.drawRange(runFirst, runEnd - runFirst);
            runFirst = p.first();
            runEnd = p.first() + p.count();
        }
        if (runFirst >= 0) mesh.drawRange(runFirst, runEnd - runFirst);
    }

    @Override
    public void close() {
        mesh.close();
        shader.close();
    }
}
