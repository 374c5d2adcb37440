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
    /** The main mesh's own indices (cell by cell, then the skirts): the level-0 chunks are re-sorted from them. */
    private int[] ownIndices;
    /** Runs of cells (see SunlitCells.runs) as index ranges {first, count}: shadowed and sunlit; null: all shadowed. */
    private int[][] shadowedRanges, sunlitRanges;
    private final double minSpacing;
    /** Chunked level of detail over the main mesh (its indices appended after {@link #indexCount}); see {@link TerrainLod}. */
    private TerrainLod lod;
    /** The levels chosen for the last perspective frame drawn by {@link #render} (-1: culled), or null. */
    private int[] lastLevels;
    private int[] scratchLevels;
    private int lastLodIndices;
    private boolean levelOfDetail = true;
    /** The software tier's shader (lighting per vertex): a skirt side turned from the sun skips the shadow tap. */
    private final boolean vertexLit;
    private java.util.List<TerrainMesh.SkirtSide> skirtSides = java.util.List.of();
    private boolean splitSkirts = true;
    private int lastBacklitSides;

    public TerrainPass(Course course, Terrain terrain, TerrainMesh.ColorMode mode) {
        this(course, terrain, mode, false, TerrainMesh.MIN_SPACING);
    }

    /**
     * As above; {@code vertexLit} picks the software rasterisers' shader (lighting and haze per vertex,
     * shadows per pixel: terrain-vertexlit.*), which costs less per pixel on llvmpipe; {@code minSpacing}
     * the mesh's finest sample spacing in metres (llvmpipe pays per triangle too; the level of
     * detail, {@link TerrainLod}, draws far chunks coarser still).
     */
    public TerrainPass(Course course, Terrain terrain, TerrainMesh.ColorMode mode, boolean vertexLit, double minSpacing) {
        this.minSpacing = minSpacing;
        this.shader = new LitShader(vertexLit ? "terrain-vertexlit" : "terrain");
        this.vertexLit = vertexLit;
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
        int[] own = built.data().indices();
        TerrainLod newLod = new TerrainLod(built.data().vertices(), built.data().stride(), built.columns(), built.rows(),
                built.cellStarts(), TerrainMesh.sampleSpacing(course.bounds(), minSpacing));
        int[] lodIndices = newLod.indices(own);
        int[] all = java.util.Arrays.copyOf(own, own.length + lodIndices.length);
        System.arraycopy(lodIndices, 0, all, own.length, lodIndices.length);
        Mesh uploaded = new Mesh(new MeshData(built.data().layout(), built.data().vertices(), all));
        if (mesh != null) mesh.close();
        mesh = uploaded;
        vertexCount = built.data().vertices().length / built.data().stride();
        rowStarts = built.rowStarts();
        cellStarts = built.cellStarts();
        skirtSides = built.skirtSides();
        indexCount = own.length;
        lod = newLod;
        lastLevels = null;
        scratchLevels = new int[lod.chunks().size()];
        columns = built.columns();
        rows = built.rows();
        vertices = built.data().vertices();
        ownIndices = own;
        shadowedRanges = sunlitRanges = null;
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
        System.arraycopy(patch.vertices(), 0, vertices, patch.firstFloat(), patch.vertices().length);
        lod.refreshBoxes(vertices, TerrainMesh.STRIDE, columns);
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
            for (TerrainLod.Chunk c : lod.chunks()) {
                c.allSunlit = false;
                c.shadowedAtLevel0 = c.count[0];
            }
            return;
        }
        boolean[] mask = SunlitCells.shadowed(map.readDepth(), map.size(), map.lightViewProjection(), map.bias(),
                vertices, TerrainMesh.STRIDE, columns, rows);
        int[] runs = SunlitCells.runs(mask, 8);
        java.util.List<int[]> shadowed = new java.util.ArrayList<>(), sunlit = new java.util.ArrayList<>();
        for (int k = 0; k + 1 < runs.length; k++) {
            int first = cellStarts[runs[k]], end = cellStarts[runs[k + 1]];
            if (end > first) (k % 2 == 0 ? shadowed : sunlit).add(new int[]{first, end - first});
        }
        shadowedRanges = shadowed.toArray(new int[0][]);
        sunlitRanges = sunlit.toArray(new int[0][]);
        int nx = columns - 1;
        for (TerrainLod.Chunk c : lod.chunks()) {
            boolean any = false;
            for (int j = c.j0; j < c.j1 && !any; j++) for (int i = c.i0; i < c.i1 && !any; i++) any = mask[j * nx + i];
            c.allSunlit = !any;
            sortLevel0(c, mask);
        }
    }

    /**
     * Rewrites chunk c's level-0 indices (the same triangles) with the cells the map can darken first,
     * so that a near chunk, drawn at full resolution, skips the tap on its sunlit cells too: a course
     * with rails all round has a shadow in every chunk, and chunk by chunk none would skip it.
     */
    private void sortLevel0(TerrainLod.Chunk c, boolean[] mask) {
        int nx = columns - 1;
        int[] sorted = new int[c.count[0]];
        int n = 0;
        for (int pass = 0; pass < 2; pass++) {
            for (int j = c.j0; j < c.j1; j++) {
                for (int i = c.i0; i < c.i1; i++) {
                    int cell = j * nx + i;
                    if (mask[cell] != (pass == 0)) continue;
                    for (int q = cellStarts[cell]; q < cellStarts[cell + 1]; q++) sorted[n++] = ownIndices[q];
                }
            }
            if (pass == 0) c.shadowedAtLevel0 = n;
        }
        mesh.updateIndices(indexCount + c.first[0], sorted);
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
        mesh.drawRange(0, indexCount);
    }

    @Override
    public void render(FrameContext frame) {
        if (perspective(frame)) {
            renderLod(frame, scratchLevels);
            lastLevels = scratchLevels.clone();
            return;
        }
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
        int quadRows = rowStarts.length - 1;
        CellRange cells = CellRange.of(course.bounds(), columns - 1, quadRows, box, 0);
        if (!cells.hasRows() && !cells.edge()) return;
        use(frame);
        if (cells.hasRows()) mesh.drawRange(rowStarts[cells.j0()], rowStarts[cells.j1()] - rowStarts[cells.j0()]);
        if (cells.edge()) mesh.drawRange(rowStarts[quadRows], indexCount - rowStarts[quadRows]);
    }

    /**
     * Whether perspective views draw the chunks at levels chosen by distance (the default) or every
     * chunk at full resolution (level 0: for comparison in tests and benchmarks).
     */
    public void setLevelOfDetail(boolean on) {
        levelOfDetail = on;
    }

    /** Whether the frame has a perspective camera (the scene, the water's targets), not the minimap's orthographic one. */
    private static boolean perspective(FrameContext frame) {
        return frame.projection.m23() != 0;
    }

    /**
     * The surface chunk by chunk at the levels {@link TerrainLod#select} picks for this view (into
     * {@code levels}), chunks the shadow map cannot darken without the shadow tap, then the skirts.
     */
    private void renderLod(FrameContext frame, int[] levels) {
        double pixelsPerRadian = frame.projection.m11() * frame.viewportHeight / 2.0;
        lod.select(frame.viewProjection, frame.eye, pixelsPerRadian, levels);
        if (!levelOfDetail) for (int n = 0; n < levels.length; n++) levels[n] = Math.min(levels[n], 0);
        var chunks = lod.chunks();
        boolean split = shadowedRanges != null && LitShader.Variant.of(frame) != LitShader.Variant.UNSHADOWED;
        int drawn = 0;
        for (int pass = 0; pass < (split ? 2 : 1); pass++) {
            boolean sunlitPass = pass == 1;
            boolean used = false;
            for (int n = 0; n < chunks.size(); n++) {
                TerrainLod.Chunk c = chunks.get(n);
                if (levels[n] < 0) continue;
                // Full resolution: the chunk's cells the map can darken come first (sortLevel0), the sunlit rest after.
                int first = indexCount + c.first[levels[n]], count = c.count[levels[n]];
                if (split && levels[n] == 0) {
                    int shadowed = c.shadowedAtLevel0;
                    if (sunlitPass) first += shadowed;
                    count = sunlitPass ? count - shadowed : shadowed;
                } else if (split && c.allSunlit != sunlitPass) {
                    continue;
                }
                if (count <= 0) continue;
                if (!used) {
                    if (sunlitPass) use(frame, LitShader.Variant.UNSHADOWED);
                    else use(frame);
                    used = true;
                }
                mesh.drawRange(first, count);
                drawn += count;
            }
        }
        drawSkirts(frame);
        lastLodIndices = drawn;
    }

    /**
     * The skirts, their sides in order. With lighting per vertex (software tier) a side turned from the
     * sun has no sunlight at any vertex (diffuse and specular 0), so the shadow tap could only multiply
     * zero: such sides are drawn without it, the same pixels for less work per pixel.
     */
    private void drawSkirts(FrameContext frame) {
        boolean split = splitSkirts && vertexLit && LitShader.Variant.of(frame) != LitShader.Variant.UNSHADOWED;
        LitShader.Variant current = null;
        int runFirst = 0, runCount = 0;
        lastBacklitSides = 0;
        for (TerrainMesh.SkirtSide side : skirtSides) {
            boolean backlit = split && backlit(side, frame.sun.direction());
            if (backlit) lastBacklitSides++;
            LitShader.Variant v = backlit ? LitShader.Variant.UNSHADOWED : LitShader.Variant.of(frame);
            if (v != current) {
                if (runCount > 0) mesh.drawRange(runFirst, runCount);
                use(frame, v);
                current = v;
                runFirst = side.first();
                runCount = 0;
            }
            runCount += side.count();
        }
        if (runCount > 0) mesh.drawRange(runFirst, runCount);
    }

    /** Whether the sun (towards it: {@code sun}) lights no point of the side: n.l <= 0 (a side's normal is horizontal). */
    static boolean backlit(TerrainMesh.SkirtSide side, org.joml.Vector3f sun) {
        return side.normalX() * sun.x + side.normalY() * sun.y <= 0;
    }

    /** Skirt sides the last perspective frame drew without the shadow tap (tests). */
    int lastBacklitSkirtSides() {
        return lastBacklitSides;
    }

    /** Off: every skirt side with the frame's shadow variant, as before the split (tests compare the pictures). */
    void splitSkirts(boolean on) {
        splitSkirts = on;
    }

    private int drawChunk(TerrainLod.Chunk c, int level) {
        int count = c.count[level];
        if (count > 0) mesh.drawRange(indexCount + c.first[level], count);
        return count;
    }

    /** Surface indices drawn by the last perspective frame (all chunks at their levels), for benchmarks. */
    public int lastLodIndexCount() {
        return lastLodIndices;
    }

    /** Chunks at each level in the last perspective frame drawn by {@link #render} ({@code [LEVELS]}; culled chunks not counted). */
    public int[] lastLevelHistogram() {
        int[] h = new int[TerrainLod.LEVELS];
        if (lastLevels != null) for (int l : lastLevels) if (l >= 0) h[l]++;
        return h;
    }

    TerrainLod lod() {
        return lod;
    }

    /**
     * The balls' shadows' second draw: the chunks that meet the box (min x, y, z, max x, y, z) at the
     * levels the last {@link #render} drew them (the same triangles, so the same depths), and the
     * skirts if the box reaches past the course's edge.
     */
    void redrawWithin(FrameContext frame, float[] box) {
        if (lastLevels == null) {
            renderWithin(frame, box);
            return;
        }
        use(frame);
        // The grid's cells that meet the box (one cell more each way): a chunk drawn at full resolution
        // is redrawn there only, from the mesh's own indices (the same triangles), row by row.
        int nx = columns - 1;
        CellRange cells = CellRange.of(course.bounds(), nx, rows - 1, box, 1);
        var chunks = lod.chunks();
        for (int n = 0; n < chunks.size(); n++) {
            TerrainLod.Chunk c = chunks.get(n);
            if (lastLevels[n] < 0 || c.max[0] < box[0] || c.min[0] > box[3] || c.max[1] < box[1] || c.min[1] > box[4]) continue;
            if (lastLevels[n] > 0) {
                drawChunk(c, lastLevels[n]);
                continue;
            }
            int a = Math.max(c.i0, cells.i0()), e = Math.min(c.i1, cells.i1());
            if (a >= e) continue;
            for (int j = Math.max(c.j0, cells.j0()); j < Math.min(c.j1, cells.j1()); j++) {
                int first = cellStarts[j * nx + a], end = cellStarts[j * nx + e];
                if (end > first) mesh.drawRange(first, end - first);
            }
        }
        if (cells.edge()) {
            int skirts = cellStarts[cellStarts.length - 1];
            mesh.drawRange(skirts, indexCount - skirts);
        }
    }

    /** Draws into the water's reflection image at the levels of detail for that (smaller) image. */
    void renderForWaterTarget(FrameContext frame) {
        if (!perspective(frame)) {
            draw(frame, mesh);
            return;
        }
        int saved = lastLodIndices;
        renderLod(frame, new int[lod.chunks().size()]);
        lastLodIndices = saved;
    }

    private void draw(FrameContext frame, Mesh drawn) {
        use(frame);
        drawn.drawRange(0, indexCount);
    }

    private ShaderProgram use(FrameContext frame) {
        return use(frame, LitShader.Variant.of(frame));
    }

    private ShaderProgram use(FrameContext frame, LitShader.Variant variant) {
        ShaderProgram program = shader.use(frame, variant);
        program.set("uViewProjection", frame.viewProjection);
        program.set("uClipPlane", frame.clipPlane);
        program.set("uShininess", 24f);
        program.set("uStripeOrigin", (float) course.bounds().minX());
        program.set("uStripeShade", (float) minigolf.theme.Themes.of(course.world()).materials().stripeShade());
        program.set("uSpecularStrength", mode == TerrainMesh.ColorMode.GREEN ? 0.10f : 0.05f);
        return program;
    }

    @Override
    public void close() {
        if (mesh != null) mesh.close();
        shader.close();
    }
}
