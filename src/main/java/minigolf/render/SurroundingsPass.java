package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Obstacle;

import java.util.ArrayList;
import java.util.List;

/**
 * What stands round the course, so it does not float in an empty sky: a meadow at the foot of the
 * slab's side walls, and decorative trees (the obstacles' trunk and crown meshes) beyond the bounds
 * ({@link TreePlacement}). The meadow is a plane that the sky pass shades below the horizon
 * ({@link SkyPass#setGround}, per grid corner: a depth-tested disc cost llvmpipe 2 ms a frame for
 * its half of the screen); this pass draws the trees, lit and faded into the sky's colours per
 * vertex (surroundings.vert), after the course's opaque passes and before the sky. Decoration only:
 * physics, the camera's clearance, the shadow map and the minimap never see any of it.
 */
public final class SurroundingsPass implements RenderPass {
    /** Duller and darker than the course's grass, and without its mowing stripes. */
    public static final float[] MEADOW_COLOR = {0.29f, 0.45f, 0.18f};
    /** Horizontal distances from the eye over which the meadow and the trees fade into the sky's haze. */
    public static final float FADE_START = 25f, FADE_END = 125f;
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
        layout = build(level, trees);
        ShaderProgram s = ShaderProgram.load("surroundings");
        try {
            mesh = layout == null ? null : new Mesh(layout.data());
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

    /** The mesh, trunks then crowns; per tree its trunk's and its crown's index runs (with boxes), so a frame can skip trees. */
    record Layout(MeshData data, List<ObstacleMeshes.Piece> trunks, List<ObstacleMeshes.Piece> crowns) {
    }

    static Layout build(double level, List<Obstacle.Tree> trees) {
        if (trees.isEmpty()) return null;
        ObstacleMeshes.Built built = ObstacleMeshes.build(List.copyOf(trees), (x, y) -> level, m -> null,
                ObstacleMeshes.CrownStyle.SURROUNDINGS);
        // The trunks reach 1 m into the ground, as the physics' cylinders do; the meadow is drawn by the
        // sky, behind everything, so they must stop at its level.
        float[] v = built.solid().vertices().clone();
        int stride = built.solid().stride();
        for (int i = 2; i < v.length; i += stride) v[i] = Math.max(v[i], (float) level);
        MeshData trunks = new MeshData(built.solid().layout(), v, built.solid().indices());
        int shift = trunks.indices().length;
        List<ObstacleMeshes.Piece> crowns = new ArrayList<>();
        for (ObstacleMeshes.Piece c : built.decorationPieces()) crowns.add(new ObstacleMeshes.Piece(shift + c.first(), c.count(), c.box()));
        return new Layout(MeshData.concat(trunks, built.decoration()), built.solidPieces(), List.copyOf(crowns));
    }

    public List<Obstacle.Tree> trees() {
        return trees;
    }

    /** The meadow's height, where the trees stand. */
    public double level() {
        return level;
    }

    @Override
    public void render(FrameContext frame) {
        if (mesh == null) return;
        shader.use();
        Lighting.apply(shader, frame);
        shader.set("uViewProjection", frame.viewProjection);
        shader.set("uClipPlane", frame.clipPlane);
        shader.set("uFade", FADE_START, FADE_END);
        boolean[] drawn = drawnTrees(frame);
        drawRuns(layout.trunks(), drawn);
        drawRuns(layout.crowns(), drawn);
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
        List<ObstacleMeshes.Piece> shown = new java.util.ArrayList<>();
        for (int i = 0; i < pieces.size(); i++) if (drawn[i]) shown.add(pieces.get(i));
        ObstaclesPass.drawRuns(mesh, shown, p -> true);
    }

    @Override
    public void close() {
        if (mesh != null) mesh.close();
        shader.close();
    }
}
