package minigolf.render;

import minigolf.course.HeightProbe;
import minigolf.course.ModelTwins;
import minigolf.course.Obstacle;
import org.joml.Matrix3f;
import org.joml.Matrix4f;

import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import static org.lwjgl.opengl.GL11.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11.glDisable;
import static org.lwjgl.opengl.GL11.glEnable;
import static org.lwjgl.opengl.GL11.glIsEnabled;

/**
 * The course's obstacles (walls, boxes, trunks, models) and the trees' decorative crowns, each
 * group one static mesh in world coordinates (one draw call for 200 obstacles). Rebuilt by
 * {@link #setObstacles} when the course changes (the editor places, moves and deletes them live).
 */
public final class ObstaclesPass implements RenderPass {
    private final HeightProbe ground;
    private final LitShader shader;
    private ShaderProgram program;
    private final Matrix4f identity = new Matrix4f();
    private final Matrix3f normalMatrix = new Matrix3f();
    private final Map<String, MaterialLibrary> materials = new HashMap<>();
    private Path courseFolder;
    private List<Obstacle> obstacles = List.of();
    private Mesh solid;
    private Mesh decoration;
    private double top = Double.NEGATIVE_INFINITY;
    private int solidTriangles, decorationTriangles;
    private List<ObstacleMeshes.Piece> solidPieces = List.of(), decorationPieces = List.of();
    private MeshData solidData, decorationData;
    /** Whether some solid piece is a model that is not closed (drawn with every face even where faces are culled). */
    private boolean anyOpen;
    private final ObstacleMeshes.Style style;
    /** Nothing is drawn below this height (the plinth's foot): the rails' footings reach 1 m into the ground. */
    private final double floor;
    /** Whether models are drawn from their lighter twins where they have one (software tier, see {@link ModelTwins}). */
    private final boolean lowModels;
    /** The twins found so far, for the course folder's models. */
    private ModelTwins.Cache twins = new ModelTwins.Cache(null);
    /**
     * The software tier's meshes reordered by {@link BacklitSplit} for this sun (null: not yet): the
     * backlit parts are drawn without the shadow tap.
     */
    private org.joml.Vector3f splitFor;
    private BacklitSplit.Result solidSplit, decorationSplit;
    private boolean splitBacklit = true;

    public ObstaclesPass(List<Obstacle> obstacles, HeightProbe ground) {
        this(obstacles, ground, false);
    }

    /** As above; {@code vertexLit} picks the software rasterisers' shader (object-vertexlit: lighting per vertex). */
    public ObstaclesPass(List<Obstacle> obstacles, HeightProbe ground, boolean vertexLit) {
        this(obstacles, ground, vertexLit, ObstacleMeshes.Style.CLASSIC);
    }

    /** As above, walls and boxes in a world's style (colours, materials, rounded rails). */
    public ObstaclesPass(List<Obstacle> obstacles, HeightProbe ground, boolean vertexLit, ObstacleMeshes.Style style) {
        this(obstacles, ground, vertexLit, style, Double.NEGATIVE_INFINITY);
    }

    /**
     * As above, drawn down to {@code floor} only: the course's plinth stands on the ground there, and
     * the footings below it (collision only) would show under the plinth from a high view. With
     * {@code vertexLit} (the software tier) models are drawn from their lighter twins where they have
     * one: llvmpipe pays per triangle, and the windmill's 10,560 cost more than a hole's whole terrain.
     */
    public ObstaclesPass(List<Obstacle> obstacles, HeightProbe ground, boolean vertexLit, ObstacleMeshes.Style style, double floor) {
        this.shader = new LitShader(vertexLit ? "object-vertexlit" : "object");
        this.ground = ground;
        this.style = style;
        this.floor = floor;
        this.lowModels = vertexLit;
        try {
            setObstacles(obstacles);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    /** Replaces the drawn obstacles (null or empty: none). */
    public void setObstacles(List<Obstacle> list) {
        obstacles = list == null ? List.of() : List.copyOf(list);
        ObstacleMeshes.Built built = ObstacleMeshes.build(lowModels ? twins.drawn(obstacles) : obstacles, ground, this::materialsOf,
                lowModels ? ObstacleMeshes.CrownStyle.COURSE.light() : ObstacleMeshes.CrownStyle.COURSE, style);
        if (floor > Double.NEGATIVE_INFINITY) {
            float[] v = built.solid().vertices();
            for (int i = 2; i < v.length; i += built.solid().stride()) v[i] = (float) Math.max(v[i], floor);
        }
        freeMeshes();
        solidTriangles = built.solid().triangleCount();
        decorationTriangles = built.decoration().triangleCount();
        solid = solidTriangles > 0 ? new Mesh(built.solid()) : null;
        decoration = decorationTriangles > 0 ? new Mesh(built.decoration()) : null;
        top = Math.max(highest(built.solid()), highest(built.decoration()));
        solidPieces = built.solidPieces();
        anyOpen = solidPieces.stream().anyMatch(ObstacleMeshes.Piece::open);
        decorationPieces = built.decorationPieces();
        solidData = built.solid();
        decorationData = built.decoration();
        splitFor = null;
        solidSplit = decorationSplit = null;
    }

    /**
     * Reorders the meshes' indices for {@code toSun} if they are not yet (software tier): each piece's
     * triangles the sun may light, then those it cannot ({@link BacklitSplit}).
     */
    private void splitFor(org.joml.Vector3f toSun) {
        if (toSun.equals(splitFor)) return;
        if (solid != null) {
            solidSplit = BacklitSplit.split(solidData, solidPieces, toSun);
            solid.updateIndices(0, solidSplit.indices());
        }
        if (decoration != null) {
            decorationSplit = BacklitSplit.split(decorationData, decorationPieces, toSun);
            decoration.updateIndices(0, decorationSplit.indices());
        }
        splitFor = new org.joml.Vector3f(toSun);
    }

    /** Off: the meshes in their built order, every piece with the frame's shadow variant, as before the split (tests compare the pictures). */
    void splitBacklit(boolean on) {
        if (on == splitBacklit) return;
        splitBacklit = on;
        if (solid != null) solid.updateIndices(0, solidData.indices());
        if (decoration != null) decoration.updateIndices(0, decorationData.indices());
        splitFor = null;
        solidSplit = decorationSplit = null;
    }

    /** Triangles in the backlit parts (0 before the first software frame; tests). */
    int backlitTriangles() {
        int n = 0;
        if (solidSplit != null) for (ObstacleMeshes.Piece p : solidSplit.backlit()) n += p.count() / 3;
        if (decorationSplit != null) for (ObstacleMeshes.Piece p : decorationSplit.backlit()) n += p.count() / 3;
        return n;
    }

    /** Where model obstacles' .mtl files are looked for before the classpath (the course file's folder); rebuilds. */
    public void setCourseFolder(Path folder) {
        courseFolder = folder;
        materials.clear();
        twins = new ModelTwins.Cache(folder);
        setObstacles(obstacles);
    }

    public List<Obstacle> obstacles() {
        return obstacles;
    }

    /** Triangles drawn for the solid obstacles and for the crowns. */
    public int solidTriangles() {
        return solidTriangles;
    }

    public int decorationTriangles() {
        return decorationTriangles;
    }

    /** The highest point of anything drawn here, or -infinity when there is nothing. */
    public double top() {
        return top;
    }

    private MaterialLibrary materialsOf(Obstacle.Model m) {
        return materials.computeIfAbsent(m.file(), f -> MaterialLibrary.forModel(f, m.mesh(), courseFolder));
    }

    private static double highest(MeshData d) {
        double max = Double.NEGATIVE_INFINITY;
        float[] v = d.vertices();
        for (int i = 2; i < v.length; i += d.stride()) max = Math.max(max, v[i]);
        return max;
    }

    @Override
    public void render(FrameContext frame) {
        renderWhere(frame, p -> true);
    }

    /**
     * Only the obstacles whose boxes, seen through the frame's camera, reach into {@code rect} ({x, y,
     * width, height} in the frame's viewport pixels from the bottom left): the viewport itself for the
     * scene (obstacles behind the eye or beside the view are skipped), the water's rectangle for its
     * reflection.
     */
    void renderInRect(FrameContext frame, int[] rect) {
        renderWhere(frame, p -> onScreen(p.box(), frame, rect));
    }

    /**
     * Only the obstacles whose boxes meet {@code box} (min x, y, z, max x, y, z): the second draw round
     * the balls' shadows (see {@link SceneRenderer}) and the refraction need not push the whole course
     * through again.
     */
    void renderWithin(FrameContext frame, float[] box) {
        renderWhere(frame, p -> p.overlaps(box));
    }

    /** Whether a box (min x, y, z, max x, y, z) may show inside rect: its corners' screen box meets it; true if one is behind the eye. */
    static boolean onScreen(float[] box, FrameContext frame, int[] rect) {
        ScreenBounds screen = new ScreenBounds(frame.viewProjection, frame.viewportWidth, frame.viewportHeight);
        screen.addBox(box);
        return screen.meets(rect);
    }

    /** The solid obstacles and the crowns whose pieces pass {@code drawn}; neighbouring ones as one run. */
    private void renderWhere(FrameContext frame, java.util.function.Predicate<ObstacleMeshes.Piece> drawn) {
        if (solid == null && decoration == null) return;
        LitShader.Variant variant = LitShader.Variant.of(frame);
        if (!lowModels || !splitBacklit) {
            drawParts(frame, drawn, variant, solidPieces, decorationPieces);
            return;
        }
        // Software tier: the parts the sun may light with the frame's shadows, the backlit parts without the tap.
        splitFor(frame.sun.direction());
        List<ObstacleMeshes.Piece> none = List.of();
        drawParts(frame, drawn, variant, solidSplit == null ? none : solidSplit.lit(), decorationSplit == null ? none : decorationSplit.lit());
        drawParts(frame, drawn, LitShader.Variant.UNSHADOWED, solidSplit == null ? none : solidSplit.backlit(),
                decorationSplit == null ? none : decorationSplit.backlit());
    }

    private void drawParts(FrameContext frame, java.util.function.Predicate<ObstacleMeshes.Piece> drawn, LitShader.Variant variant,
                           List<ObstacleMeshes.Piece> solidParts, List<ObstacleMeshes.Piece> decorationParts) {
        if (solidParts.isEmpty() && decorationParts.isEmpty()) return;
        begin(frame, variant);
        if (solid != null && !solidParts.isEmpty()) {
            program.set("uSpecularStrength", 0.12f);
            program.set("uShininess", 16f);
            // Where the faces turned away are culled (software tier), models that are not closed keep them.
            boolean cull = anyOpen && glIsEnabled(GL_CULL_FACE);
            drawRuns(solid, solidParts, cull ? drawn.and(p -> !p.open()) : drawn);
            if (cull) {
                glDisable(GL_CULL_FACE);
                drawRuns(solid, solidParts, drawn.and(ObstacleMeshes.Piece::open));
                glEnable(GL_CULL_FACE);
            }
        }
        if (decoration != null && !decorationParts.isEmpty()) {
            program.set("uSpecularStrength", 0.05f);
            program.set("uShininess", 8f);
            drawRuns(decoration, decorationParts, drawn);
        }
    }

    /** The pieces are consecutive index runs covering the mesh: all drawn is one draw call. */
    static void drawRuns(Mesh mesh, List<ObstacleMeshes.Piece> pieces, java.util.function.Predicate<ObstacleMeshes.Piece> drawn) {
        int runFirst = -1, runEnd = -1;
        for (ObstacleMeshes.Piece p : pieces) {
            if (!drawn.test(p)) continue;
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

    /** The minimap shows only what the ball can hit (no crowns, which would hide the trunks). */
    void renderMinimap(FrameContext frame) {
        if (solid == null) return;
        begin(frame);
        program.set("uSpecularStrength", 0f);
        program.set("uShininess", 8f);
        solid.draw();
    }

    /** Draws everything here into the shadow map (the depth shader is in use). */
    void drawDepth(ShaderProgram depthShader) {
        depthShader.set("uModel", identity);
        if (solid != null) solid.draw();
        if (decoration != null) decoration.draw();
    }

    private void begin(FrameContext frame) {
        begin(frame, LitShader.Variant.of(frame));
    }

    private void begin(FrameContext frame, LitShader.Variant variant) {
        program = shader.use(frame, variant);
        program.set("uViewProjection", frame.viewProjection);
        program.set("uClipPlane", frame.clipPlane);
        program.set("uModel", identity);
        program.set("uNormalMatrix", identity.normal(normalMatrix));
        program.set("uTint", 1f, 1f, 1f);
    }

    private void freeMeshes() {
        if (solid != null) solid.close();
        if (decoration != null) decoration.close();
        solid = null;
        decoration = null;
    }

    @Override
    public void close() {
        freeMeshes();
        shader.close();
    }
}
