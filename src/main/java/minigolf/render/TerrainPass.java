package minigolf.render;

import minigolf.course.Course;
import minigolf.terrain.Terrain;

/** The course surface and its side walls, lit by the sun. */
public final class TerrainPass implements RenderPass {
    private Course course;
    private Terrain terrain;
    private final LitShader shader;
    private TerrainMesh.ColorMode mode;
    private Mesh mesh;
    private double minHeight, maxHeight;
    private int vertexCount;
    private int[] rowStarts;
    private int[] cellStarts;
    private int indexCount;
    private int columns, rows;
    /** The main mesh's vertices as uploaded (patches included): what the sunlit cells are found from. */
    private float[] vertices;
    /** Runs of cells (see SunlitCells.runs) as index ranges {first, count}: shadowed and sunlit; null: all shadowed. */
    private int[][] shadowedRanges, sunlitRanges;
    private final double minSpacing;
    /** The water reflection's coarser mesh (software quality: a small mirrored image needs few triangles), or null: {@link #mesh}. */
    private Mesh targetMesh;
    private final double targetSpacing;
    private boolean targetMeshStale;
    private int targetVertexCount;

    public TerrainPass(Course course, Terrain terrain, TerrainMesh.ColorMode mode) {
        this(course, terrain, mode, false, TerrainMesh.MIN_SPACING, TerrainMesh.MIN_SPACING);
    }

    /**
     * As above; {@code vertexLit} picks the software rasterisers' shader (lighting and haze per vertex,
     * shadows per pixel: terrain-vertexlit.*), which costs less per pixel on llvmpipe; {@code minSpacing}
     * the mesh's finest sample spacing in metres (llvmpipe pays per triangle too); {@code targetSpacing}
     * that of the mesh drawn into the water's reflection image (a second, coarser mesh
     * when larger than {@code minSpacing}).
     */
    public TerrainPass(Course course, Terrain terrain, TerrainMesh.ColorMode mode, boolean vertexLit, double minSpacing,
                       double targetSpacing) {
        this.minSpacing = minSpacing;
        this.targetSpacing = Math.max(minSpacing, targetSpacing);
        this.shader = new LitShader(vertexLit ? "terrain-vertexlit" : "terrain");
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
        rowStarts = built.rowStarts();
        cellStarts = built.cellStarts();
        indexCount = built.data().indices().length;
        columns = built.columns();
        rows = built.rows();
        vertices = built.data().vertices();
        shadowedRanges = sunlitRanges = null;
        minHeight = built.minHeight();
        maxHeight = built.maxHeight();
        mode = newMode;
        rebuildTargetMesh();
    }

    private void rebuildTargetMesh() {
        targetMeshStale = false;
        if (targetSpacing <= minSpacing) return;
        MeshData data = TerrainMesh.build(course, terrain, mode, targetSpacing).data();
        Mesh uploaded = new Mesh(data);
        if (targetMesh != null) targetMesh.close();
        targetMesh = uploaded;
        targetVertexCount = data.vertices().length / data.stride();
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
        int floats = applyPatch(patch);
        if (targetMesh != null && patch != null) {
            TerrainMesh.Patch coarse = TerrainMesh.surfacePatch(course, terrain, mode, minHeight, maxHeight,
                    minX, minY, maxX, maxY, targetSpacing);
            if (coarse != null) targetMesh.updateVertices(coarse.firstFloat(), coarse.vertices());
            targetMeshStale = false;
        }
        return floats;
    }

    /** The mesh's finest sample spacing (metres): patches for {@link #applyPatch} must be made with it. */
    public double minSpacing() {
        return minSpacing;
    }

    /** Uploads re-sampled surface rows (see {@link TerrainMesh#surfacePatch}, made with {@link #minSpacing()}); returns the floats uploaded. */
    public int applyPatch(TerrainMesh.Patch patch) {
        if (patch == null) return 0;
        mesh.updateVertices(patch.firstFloat(), patch.vertices());
        System.arraycopy(patch.vertices(), 0, vertices, patch.firstFloat(), patch.vertices().length);
        // The water targets' coarse mesh is rebuilt before it is next drawn (updateRegion patches it at once).
        if (targetMesh != null) targetMeshStale = true;
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

    /** The terrain the mesh was last built or patched from. */
    public Terrain terrain() {
        return terrain;
    }

    /**
     * Which cells the sun's shadow map can darken ({@link SunlitCells}), from its depths: the others
     * are drawn without the shadow tap. Null (also after any rebuild) draws every cell with it.
     */
    public void setShadowedCells(ShadowMap map) {
        if (map == null) {
            shadowedRanges = sunlitRanges = null;
            return;
        }
        boolean[] mask = SunlitCells.shadowed(map.readDepth(), map.size(), map.lightViewProjection(), map.bias(),
                vertices, 9, columns, rows); // PNC: 9 floats a vertex
        int[] runs = SunlitCells.runs(mask, 8);
        java.util.List<int[]> shadowed = new java.util.ArrayList<>(), sunlit = new java.util.ArrayList<>();
        for (int k = 0; k + 1 < runs.length; k++) {
            int first = cellStarts[runs[k]], end = cellStarts[runs[k + 1]];
            if (end > first) (k % 2 == 0 ? shadowed : sunlit).add(new int[]{first, end - first});
        }
        shadowedRanges = shadowed.toArray(new int[0][]);
        sunlitRanges = sunlit.toArray(new int[0][]);
    }

    /** Indices in the main mesh (surface and skirts). */
    public int indexCount() {
        return indexCount;
    }

    /** Cells drawn without the shadow tap, or -1 when none is known to be sunlit. */
    public int sunlitIndexCount() {
        if (sunlitRanges == null) return -1;
        int n = 0;
        for (int[] r : sunlitRanges) n += r[1];
        return n;
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
        if (shadowedRanges == null || LitShader.Variant.of(frame) == LitShader.Variant.UNSHADOWED) {
            draw(frame, mesh);
            return;
        }
        use(frame);
        for (int[] r : shadowedRanges) mesh.drawRange(r[0], r[1]);
        use(frame, LitShader.Variant.UNSHADOWED);
        for (int[] r : sunlitRanges) mesh.drawRange(r[0], r[1]);
        // The skirts last, as in the single draw (where they meet the surface's edge at equal depth, the later wins).
        use(frame);
        int skirts = cellStarts[cellStarts.length - 1];
        mesh.drawRange(skirts, indexCount - skirts);
    }

    /**
     * Only the rows of quads that meet y in [box[1], box[4]] (the box: min x, y, z, max x, y, z), and
     * the skirts if the box reaches past the course's edge: the second draw round the balls' shadows.
     */
    void renderWithin(FrameContext frame, float[] box) {
        var b = course.bounds();
        int quadRows = rowStarts.length - 1;
        double dy = b.depth() / quadRows;
        int j0 = (int) Math.max(0, Math.floor((box[1] - b.minY()) / dy));
        int j1 = (int) Math.min(quadRows, Math.ceil((box[4] - b.minY()) / dy));
        boolean edge = box[0] <= b.minX() || box[3] >= b.maxX() || box[1] <= b.minY() || box[4] >= b.maxY();
        if (j1 <= j0 && !edge) return;
        use(frame);
        if (j1 > j0) mesh.drawRange(rowStarts[j0], rowStarts[j1] - rowStarts[j0]);
        if (edge) mesh.drawRange(rowStarts[quadRows], indexCount - rowStarts[quadRows]);
    }

    /** Draws into the water's reflection image, from the coarser mesh where there is one. */
    void renderForWaterTarget(FrameContext frame) {
        if (targetMeshStale) rebuildTargetMesh();
        draw(frame, targetMesh != null ? targetMesh : mesh);
    }

    /** Vertices in the water targets' mesh (the same as {@link #vertexCount()} without a coarser one). */
    public int targetVertexCount() {
        return targetMesh == null ? vertexCount : targetVertexCount;
    }

    private void draw(FrameContext frame, Mesh drawn) {
        use(frame);
        drawn.draw();
    }

    private ShaderProgram use(FrameContext frame) {
        return use(frame, LitShader.Variant.of(frame));
    }

    private ShaderProgram use(FrameContext frame, LitShader.Variant variant) {
        ShaderProgram program = shader.use(frame, variant);
        program.set("uViewProjection", frame.viewProjection);
        program.set("uClipPlane", frame.clipPlane);
        program.set("uShininess", 24f);
        program.set("uSpecularStrength", mode == TerrainMesh.ColorMode.GREEN ? 0.10f : 0.05f);
        return program;
    }

    @Override
    public void close() {
        if (mesh != null) mesh.close();
        if (targetMesh != null) targetMesh.close();
        shader.close();
    }
}
