package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Obstacle;
import minigolf.scenery.SceneryMesh;
import minigolf.scenery.SceneryPlan;
import minigolf.theme.Theme;

import java.util.ArrayList;
import java.util.List;

/**
 * What stands round the course, so it does not float in an empty sky: the world's ground at the foot
 * of the slab's side walls, decorative trees (the obstacles' trunk and crown meshes) beyond the bounds
 * ({@link TreePlacement}) and the world's other props ({@link SceneryPlan}: rocks, pines, cacti,
 * flowers, fences, lamp posts, huts, a lighthouse, a castle, buttes on the skyline). The meadow is a plane that the sky pass shades below the horizon
 * ({@link SkyPass#setGround}, per grid corner: a depth-tested disc cost llvmpipe 2 ms a frame for
 * its half of the screen); this pass draws the trees, lit and faded into the sky's colours per
 * vertex (surroundings.vert), after the course's opaque passes and before the sky. Decoration only:
 * physics, the camera's clearance, the shadow map and the minimap never see any of it.
 */
public final class SurroundingsPass implements RenderPass {
    /** Horizontal distances from the eye over which the meadow and the trees fade into the sky's haze. */
    public static final float FADE_START = 25f, FADE_END = 125f;
    /** The same for the skyline's props (buttes, the castle, the lighthouse): they must still show far away. */
    public static final float SKYLINE_FADE_START = 60f, SKYLINE_FADE_END = 420f;
    /** The share of a world's props drawn at software quality: llvmpipe pays per triangle (a tree is about 300). */
    static final double SOFTWARE_SHARE = 0.5;

    private final ShaderProgram shader;
    private final Mesh mesh;
    private final Layout layout;
    private final Bounds bounds;
    private final List<Obstacle.Tree> trees;
    private final double level;
    private final Mesh propMesh;
    private final SceneryMesh props;

    /** Round a course with these bounds, whose slab stands at height {@code level} (its skirts' base): Meadowbrook's trees. */
    public SurroundingsPass(Bounds bounds, double level, int treeCount) {
        this(bounds, level, treeCount, false, null);
    }

    /**
     * Round {@code course} in its world: the world's trees and props, {@code share} of each kind's
     * count (see {@link #shareFor}).
     */
    public SurroundingsPass(Course course, double level, Theme theme, double share) {
        this(course, level, theme, share, false);
    }

    /** As above; {@code light}: the props' smallest parts with fewer triangles (the software tier, see {@link SceneryMesh#build}). */
    public SurroundingsPass(Course course, double level, Theme theme, double share, boolean light) {
        this(course.bounds(), level, treeCount(theme, share), light, SceneryMesh.build(SceneryPlan.plan(theme.scenery(), course.bounds(),
                course.start().x(), course.start().y(), course.hole().position().x(), course.hole().position().y(), share), theme, level,
                light));
    }

    private SurroundingsPass(Bounds bounds, double level, int treeCount, boolean light, SceneryMesh props) {
        this.level = level;
        this.bounds = bounds;
        this.trees = TreePlacement.around(bounds, treeCount);
        this.props = props;
        layout = build(level, trees, light);
        ShaderProgram s = ShaderProgram.load("surroundings");
        Mesh m = null;
        try {
            m = layout == null ? null : new Mesh(layout.data());
            propMesh = props == null || props.triangleCount() == 0 ? null
                    : new Mesh(new MeshData(MeshData.PNC, props.vertices(), props.indices()));
        } catch (RuntimeException e) {
            if (m != null) m.close();
            s.close();
            throw e;
        }
        mesh = m;
        shader = s;
    }

    /** The share of each kind of prop drawn at a quality. */
    static double shareFor(RenderQuality quality) {
        return quality.vertexLit() ? SOFTWARE_SHARE : 1.0;
    }

    private static int treeCount(Theme theme, double share) {
        for (Theme.PropCount p : theme.scenery().props()) {
            if (p.prop() == Theme.Prop.TREE) return (int) Math.round(p.count() * share);
        }
        return 0;
    }

    /** The props other than trees, or null. */
    public SceneryMesh props() {
        return props;
    }

    /** The mesh, trunks then crowns; per tree its trunk's and its crown's index runs (with boxes), so a frame can skip trees. */
    record Layout(MeshData data, List<ObstacleMeshes.Piece> trunks, List<ObstacleMeshes.Piece> crowns) {
    }

    /** {@code light}: the crowns' lighter twin (the software tier, see {@link ObstacleMeshes.CrownStyle#light}). */
    static Layout build(double level, List<Obstacle.Tree> trees, boolean light) {
        if (trees.isEmpty()) return null;
        ObstacleMeshes.Built built = ObstacleMeshes.build(List.copyOf(trees), (x, y) -> level, m -> null,
                light ? ObstacleMeshes.CrownStyle.SURROUNDINGS.light() : ObstacleMeshes.CrownStyle.SURROUNDINGS);
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
        if (mesh == null && propMesh == null) return;
        shader.use();
        Lighting.apply(shader, frame);
        shader.set("uViewProjection", frame.viewProjection);
        shader.set("uClipPlane", frame.clipPlane);
        shader.set("uFade", FADE_START, FADE_END);
        if (mesh != null) {
            boolean[] drawn = drawnTrees(frame);
            drawRuns(layout.trunks(), drawn);
            drawRuns(layout.crowns(), drawn);
        }
        if (propMesh != null) {
            List<ObstacleMeshes.Piece> near = new ArrayList<>(), skyline = new ArrayList<>();
            int[] viewport = {0, 0, frame.viewportWidth, frame.viewportHeight};
            int[] courseRect = courseRect(frame);
            double edge = TreePlacement.distance(bounds, frame.eye.x, frame.eye.y);
            for (SceneryMesh.Piece p : props.pieces()) {
                if (!shown(frame, p.box(), viewport, courseRect, edge)) continue;
                (p.skyline() ? skyline : near).add(new ObstacleMeshes.Piece(p.first(), p.count(), p.box()));
            }
            ObstaclesPass.drawRuns(propMesh, near, p -> true);
            shader.set("uFade", SKYLINE_FADE_START, SKYLINE_FADE_END);
            ObstaclesPass.drawRuns(propMesh, skyline, p -> true);
        }
    }

    /**
     * The trees to draw: those on screen, except those that stand in front of the course (nearer the
     * eye than the course's nearest edge and over it on screen), which would hide the play.
     */
    boolean[] drawnTrees(FrameContext frame) {
        int[] viewport = {0, 0, frame.viewportWidth, frame.viewportHeight};
        int[] courseRect = courseRect(frame);
        double edge = TreePlacement.distance(bounds, frame.eye.x, frame.eye.y);
        boolean[] drawn = new boolean[layout.trunks().size()];
        for (int i = 0; i < drawn.length; i++) {
            float[] box = union(layout.trunks().get(i).box(), i < layout.crowns().size() ? layout.crowns().get(i).box() : null);
            drawn[i] = shown(frame, box, viewport, courseRect, edge);
        }
        return drawn;
    }

    /** The course's rectangle on screen (bounds from the ground up to a metre above it), or null. */
    private int[] courseRect(FrameContext frame) {
        ScreenBounds course = new ScreenBounds(frame.viewProjection, frame.viewportWidth, frame.viewportHeight);
        course.addBox(new float[]{(float) bounds.minX(), (float) bounds.minY(), (float) level,
                (float) bounds.maxX(), (float) bounds.maxY(), (float) level + 1f});
        return course.rect(0, 0);
    }

    /** Whether a prop in this box is drawn: on screen, and not in front of the course (see {@link #drawnTrees}). */
    private static boolean shown(FrameContext frame, float[] box, int[] viewport, int[] courseRect, double edge) {
        ScreenBounds prop = new ScreenBounds(frame.viewProjection, frame.viewportWidth, frame.viewportHeight);
        prop.addBox(box);
        if (!prop.meets(viewport)) return false;
        double x = 0.5 * (box[0] + box[3]), y = 0.5 * (box[1] + box[4]);
        boolean inFront = Math.hypot(x - frame.eye.x, y - frame.eye.y) < edge && courseRect != null && prop.meets(courseRect);
        return !inFront;
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
        if (propMesh != null) propMesh.close();
        shader.close();
    }
}
