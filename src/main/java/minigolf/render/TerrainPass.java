package minigolf.render;

import minigolf.course.Course;
import minigolf.terrain.Terrain;

/** The course surface and its side walls, lit by the sun. */
public final class TerrainPass implements RenderPass {
    private Course course;
    private Terrain terrain;
    private final ShaderProgram shader;
    private TerrainMesh.ColorMode mode;
    private Mesh mesh;
    private double minHeight, maxHeight;
    private int vertexCount;
    private final double minSpacing;

    public TerrainPass(Course course, Terrain terrain, TerrainMesh.ColorMode mode) {
        this(course, terrain, mode, false, TerrainMesh.MIN_SPACING);
    }

    /**
     * As above; {@code vertexLit} picks the software rasterisers' shader (lighting and haze per vertex,
     * shadows per pixel: terrain-vertexlit.*), which costs less per pixel on llvmpipe; {@code minSpacing}
     * the mesh's finest sample spacing in metres (llvmpipe pays per triangle too).
     */
    public TerrainPass(Course course, Terrain terrain, TerrainMesh.ColorMode mode, boolean vertexLit, double minSpacing) {
        this.minSpacing = minSpacing;
        this.shader = ShaderProgram.load(vertexLit ? "terrain-vertexlit" : "terrain");
        this.course = course;
        this.terrain = terrain;
        setColorMode(mode);
    }

    public TerrainMesh.ColorMode colorMode() {
        return mode;
    }

    /** Rebuilds the mesh with the other colouring (a few milliseconds for 256x256 quads). */
    public void setColorMode(TerrainMesh.ColorMode newMode) {
        if (newMode == mode && mesh != null) return;
        TerrainMesh built = TerrainMesh.build(course, terrain, newMode, minSpacing);
        Mesh uploaded = new Mesh(built.data());
        if (mesh != null) mesh.close();
        mesh = uploaded;
        vertexCount = built.data().vertices().length / built.data().stride();
        minHeight = built.minHeight();
        maxHeight = built.maxHeight();
        mode = newMode;
    }

    /**
     * Live edit: the terrain changed inside [minX, maxX] x [minY, maxY]; the mesh rows there are
     * re-sampled and uploaded in place with glBufferSubData (the rest of the mesh is untouched).
     * Returns the number of floats uploaded.
     */
    public int updateRegion(Course newCourse, Terrain newTerrain, double minX, double minY, double maxX, double maxY) {
        course = newCourse;
        terrain = newTerrain;
        TerrainMesh.Patch patch = TerrainMesh.surfacePatch(course, terrain, mode, minHeight, maxHeight, minX, minY, maxX, maxY, minSpacing);
        return applyPatch(patch);
    }

    /** The mesh's finest sample spacing (metres): patches for {@link #applyPatch} must be made with it. */
    public double minSpacing() {
        return minSpacing;
    }

    /** Uploads re-sampled surface rows (see {@link TerrainMesh#surfacePatch}, made with {@link #minSpacing()}); returns the floats uploaded. */
    public int applyPatch(TerrainMesh.Patch patch) {
        if (patch == null) return 0;
        mesh.updateVertices(patch.firstFloat(), patch.vertices());
        return patch.vertices().length;
    }

    /** Rebuilds the whole mesh from a changed course (skirts, triangulation, deleted cells, colour range). */
    public void rebuild(Course newCourse, Terrain newTerrain) {
        course = newCourse;
        terrain = newTerrain;
        TerrainMesh.ColorMode m = mode;
        mode = null;
        setColorMode(m);
    }

    /** Vertices in the drawn mesh (surface and skirts). */
    public int vertexCount() {
        return vertexCount;
    }

    /** The lowest and highest surface heights sampled for the mesh. */
    public double minHeight() {
        return minHeight;
    }

    public double maxHeight() {
        return maxHeight;
    }

    /** Draws the surface into the shadow map with the depth-only shader. */
    void drawDepth(ShaderProgram depthShader) {
        depthShader.set("uModel", new org.joml.Matrix4f());
        mesh.draw();
    }

    @Override
    public void render(FrameContext frame) {
        shader.use();
        shader.set("uViewProjection", frame.viewProjection);
        shader.set("uClipPlane", frame.clipPlane);
        Lighting.apply(shader, frame);
        shader.set("uShininess", 24f);
        shader.set("uSpecularStrength", mode == TerrainMesh.ColorMode.GREEN ? 0.10f : 0.05f);
        mesh.draw();
    }

    @Override
    public void close() {
        if (mesh != null) mesh.close();
        shader.close();
    }
}
