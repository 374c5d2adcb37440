package minigolf.render;

import minigolf.course.Course;
import minigolf.course.Obstacle;
import minigolf.terrain.Terrain;
import minigolf.theme.Theme;
import minigolf.theme.Themes;
import org.joml.Vector3f;

import java.nio.file.Path;
import java.util.List;

import static org.lwjgl.opengl.GL11.*;
import static org.lwjgl.opengl.GL13.GL_MULTISAMPLE;
import static org.lwjgl.opengl.GL30.*;

/**
 * Draws a course: terrain, objects, the surroundings (meadow, trees), the sky where they left the far plane, then water (translucent, last). Owns the passes; needs a
 * current GL context from construction to {@link #close()}.
 */
public final class SceneRenderer implements AutoCloseable {
    /** Shadow map texels per side: about 5 mm per texel on a 10 m course. */
    public static final int SHADOW_MAP_SIZE = 2048;
    /** How far above the highest caster the shadow map reaches, so a chipped ball keeps its shadow. */
    static final double FLIGHT_HEADROOM = 1.0;

    private final SkyPass sky;
    private final TerrainPass terrain;
    private final ObjectsPass objects;
    private final ObstaclesPass obstacles;
    private final ElementsPass elements;
    private final SurroundingsPass surroundings;
    private final WaterPass water;
    private final List<RenderPass> passes;
    /** The world the course is set in (its light, sky, materials and scenery). */
    private final Theme theme;
    private final FrameContext frame;
    private final FrameContext mirrorFrame;
    private final FrameContext refractionFrame;
    private final FrameContext minimapFrame;
    private final Course course;
    private float lastTime;
    private boolean waterReflections = true;
    private final ShaderProgram depthShader;
    private ShadowMap shadowMap;
    /** The heights the shadow map is fitted to (its box must hold every caster). */
    private final double shadowMinZ;
    private double shadowMaxZ;
    private final int shadowMapSize;
    private final int shadowTaps;
    private boolean shadows = true;
    /** The water's render targets' size relative to the viewport (0.5: a quarter of the pixels). */
    private float waterTargetScale;
    /** Whether the water's mirrored and refracted scenes are shadowed too (barely visible there). */
    private final boolean shadowsInWater;
    /** Whether the water's reflection and refraction are images of the scene drawn for it (else sky and blending). */
    private final boolean waterImages;
    /** Whether the balls' shadows are shaded in a second, scissored draw (software rasterisers). */
    private final boolean ballShadowRedraw;
    /** Whether the terrain's sunlit cells skip the shadow tap (software rasterisers). */
    private final boolean sunlitTerrain;
    /** Whether the closed meshes skip the faces turned away from the camera (software rasterisers). */
    private boolean cullBackFaces;
    /**
     * Frames to wait, after the terrain last changed, before its sunlit cells are searched again (a
     * brush stroke changes it every frame; meanwhile every cell keeps the tap); -1 when up to date.
     */
    private int sunlitCountdown = 0;
    static final int SUNLIT_SETTLE_FRAMES = 30;
    /** The shadow map holds only what stands still, so it is drawn again only after a change. */
    private boolean shadowMapDirty = true;
    /** The minimap's still part, drawn again only after a change. */
    private final RenderTarget minimapCache = new RenderTarget();
    private boolean minimapDirty = true;
    private final ShaderProgram blitShader;
    /** FXAA where the quality has no MSAA (made on first use), and whether it is on. */
    private FxaaPass fxaa;
    private boolean antiAliasing;
    private final int emptyVao;
    private final PassTimer timer = new PassTimer();
    private final MaterialTextures materials;

    public SceneRenderer(Course course, Terrain surface, TerrainMesh.ColorMode mode) {
        this(course, surface, mode, RenderQuality.HIGH);
    }

    /** As above at a chosen quality (shadow map size, water targets; see {@link RenderQuality#current()}). */
    public SceneRenderer(Course course, Terrain surface, TerrainMesh.ColorMode mode, RenderQuality quality) {
        this.course = course;
        this.theme = Themes.of(course.world());
        FrameContext.Sun sun = FrameContext.Sun.of(theme.light());
        Atmosphere air = Atmosphere.of(theme);
        frame = new FrameContext(sun);
        mirrorFrame = new FrameContext(sun);
        refractionFrame = new FrameContext(sun);
        minimapFrame = new FrameContext(sun);
        for (FrameContext f : new FrameContext[]{frame, mirrorFrame, refractionFrame, minimapFrame}) f.atmosphere = air;
        this.shadowMapSize = quality.shadowMapSize();
        this.waterTargetScale = quality.waterTargetScale();
        this.shadowsInWater = quality.shadowsInWater();
        this.shadowTaps = quality.shadowTaps();
        this.ballShadowRedraw = quality.ballShadowRedraw();
        this.waterImages = quality.waterImages();
        this.sunlitTerrain = quality.sunlitTerrain();
        this.cullBackFaces = quality.cullBackFaces();
        SkyPass s = null;
        TerrainPass t = null;
        ObstaclesPass ob = null;
        ElementsPass el = null;
        ObjectsPass o = null;
        SurroundingsPass u = null;
        try {
            s = new SkyPass(!theme.scenery().sea() ? null : new SkyPass.Sea((float) theme.scenery().shoreDistance(),
                    new float[]{(float) course.bounds().minX(), (float) course.bounds().minY(), (float) course.bounds().maxX(),
                            (float) course.bounds().maxY()}, theme.materials().water().toArray(), theme.materials().sand().toArray()),
                    quality.vertexLit() ? -1 : MaterialTextures.groundLayer(theme));
            t = new TerrainPass(course, surface, mode, quality.vertexLit(), quality.terrainSpacing());
            // Rounded rails cost a software rasteriser about four times the triangles: square ones there.
            ObstacleMeshes.Style style = ObstacleMeshes.Style.of(theme);
            // The bricks as the hole starts, every one standing (the game shows what strokes broke: setObstacles).
            ob = new ObstaclesPass(course.obstaclesWithBricks(i -> true), surface::height, quality.vertexLit(), quality.vertexLit() ? style.squareWalls() : style,
                    TerrainMesh.skirtBase(t.minHeight(), course.bounds()));
            el = new ElementsPass(course, surface::height, quality.vertexLit());
            o = new ObjectsPass(course, surface, quality.vertexLit());
            u = new SurroundingsPass(course, TerrainMesh.skirtBase(t.minHeight(), course.bounds()), theme,
                    SurroundingsPass.shareFor(quality), quality.vertexLit());
            water = new WaterPass(course, surface, quality.terrainSpacing());
        } catch (RuntimeException e) {
            for (RenderPass p : new RenderPass[]{u, o, el, ob, t, s}) if (p != null) p.close();
            throw e;
        }
        sky = s;
        terrain = t;
        obstacles = ob;
        elements = el;
        objects = o;
        surroundings = u;
        sky.setGround(u.level(), theme.materials().surroundGround().toArray(), SurroundingsPass.FADE_START, SurroundingsPass.FADE_END);
        passes = List.of(terrain, obstacles, elements, objects, surroundings, sky, water);
        ShaderProgram depth = null;
        try {
            depth = ShaderProgram.load("shadow");
            shadowMinZ = Math.min(0, t.minHeight()) - 0.5;
            shadowMaxZ = casterTop();
            shadowMap = new ShadowMap(course.bounds(), shadowMinZ, shadowMaxZ, frame.sun.direction(), shadowMapSize);
            shadowMap.setTaps(shadowTaps);
        } catch (RuntimeException e) {
            if (depth != null) depth.close();
            for (RenderPass p : passes) p.close();
            throw e;
        }
        depthShader = depth;
        ShaderProgram blit;
        try {
            blit = ShaderProgram.load("blit");
        } catch (RuntimeException e) {
            close();
            throw e;
        }
        blitShader = blit;
        MaterialTextures m;
        try {
            m = new MaterialTextures(theme);
            m.setOcclusion(OcclusionMap.of(course.bounds(), course.obstacles(), surface::height));
        } catch (RuntimeException e) {
            close();
            throw e;
        }
        materials = m;
        for (FrameContext f : new FrameContext[]{frame, mirrorFrame, refractionFrame, minimapFrame}) f.materials = m;
        emptyVao = glGenVertexArrays();
        frame.shadowMap = shadowMap;
        minimapFrame.shadowMap = shadowMap;
    }

    /** The world the course is set in. */
    public Theme theme() {
        return theme;
    }

    /** The per-pass timer (off by default; the benchmark's --breakdown turns it on). */
    public PassTimer passTimer() {
        return timer;
    }

    SkyPass skyPass() {
        return sky;
    }

    public TerrainPass terrainPass() {
        return terrain;
    }

    public ObjectsPass objectsPass() {
        return objects;
    }

    /** Rebuilds the water for changed ground (the editor's brush), so new water shows at once. */
    public void updateWater(Course course, Terrain terrain) {
        water.rebuild(course, terrain);
    }

    public WaterPass waterPass() {
        return water;
    }

    public ObstaclesPass obstaclesPass() {
        return obstacles;
    }

    /**
     * Rebuilds the drawn obstacles (walls, boxes, trees, models) from {@code list}, e.g. when the
     * editor places, moves or deletes one; null or empty draws none. The shadow map is refitted if
     * something now stands higher than it reaches.
     */
    public void setObstacles(List<Obstacle> list) {
        obstacles.setObstacles(list);
        materials.setOcclusion(OcclusionMap.of(course.bounds(), list == null ? List.of() : list, terrain.terrain()::height));
        refitShadowMap();
        shadowMapDirty = true;
        minimapDirty = true;
        terrain.setShadowedCells(null);
        sunlitCountdown = SUNLIT_SETTLE_FRAMES;
    }

    public ElementsPass elementsPass() {
        return elements;
    }

    /** Rebuilds the drawn course elements (bumpers, gates, push zones, magnets, teleports, moving obstacles). */
    public void setElements(Course changed) {
        elements.setCourse(changed);
        shadowMapDirty = true;
        minimapDirty = true;
    }

    /** The course clock (s) the moving obstacles are drawn at: the game's and the replays' clock. */
    public void setClock(double clock) {
        elements.setClock(clock);
    }

    /**
     * Call after changing the terrain's mesh: the sun's shadow map (terrain, obstacles, flag) and the
     * minimap's cached image are drawn again before they are next used. (Balls need nothing: their
     * shadows are analytic and they are drawn over the minimap each frame.)
     */
    public void terrainChanged() {
        shadowMapDirty = true;
        minimapDirty = true;
        terrain.setShadowedCells(null);
        sunlitCountdown = SUNLIT_SETTLE_FRAMES;
    }

    /** The course file's folder, where model obstacles' .mtl files are looked for first (then the classpath). */
    public void setCourseFolder(Path folder) {
        obstacles.setCourseFolder(folder);
    }

    /** The highest caster: terrain, flag, obstacles, plus room for a ball in flight. */
    private double casterTop() {
        double top = Math.max(0, terrain.maxHeight()) + ObjectsPass.FLAG_HEIGHT + 0.1;
        return Math.max(top, obstacles.top()) + FLIGHT_HEADROOM;
    }

    private void refitShadowMap() {
        double top = casterTop();
        if (top <= shadowMaxZ) return;
        ShadowMap fitted = new ShadowMap(course.bounds(), shadowMinZ, top, frame.sun.direction(), shadowMapSize);
        fitted.setTaps(shadowTaps);
        shadowMap.close();
        shadowMap = fitted;
        shadowMaxZ = top;
        shadowMapDirty = true;
        frame.shadowMap = shadowMap;
        minimapFrame.shadowMap = shadowMap;
    }

    public Vector3f ballCenter() {
        return objects.ballCenter();
    }

    /** The balls to draw (contact points, see {@link BallView}); null restores the default ball at the start, empty draws none. */
    public void setBalls(List<BallView> balls) {
        objects.setBalls(balls);
    }

    /** The effects' particles for this frame (confetti, splashes: {@link Particles#mesh()}), or null. */
    public void setEffects(MeshData particles) {
        objects.setEffects(particles);
    }

    /** Shows the aiming arrow on the ground from the ball; null hides it. */
    public void setAim(AimView aim) {
        objects.setAim(aim);
    }

    /** Rings the current player's ball (null: no ring). */
    public void setMarker(BallView ball) {
        objects.setMarker(ball);
    }

    /** The trail behind the rolling ball ({@link BallTrail#path()}) in its colour; null draws none. */
    public void setTrail(float[] path, float[] rgb) {
        objects.setTrail(path, rgb);
    }

    /**
     * Draws the minimap, a top-down view of the whole course (terrain, water, obstacles, hole, balls), into a
     * square of {@code sizePx} pixels whose TOP-LEFT corner is at (x, y) framebuffer pixels from the
     * framebuffer's TOP-LEFT corner (window/ImGui convention, not GL's). Call after {@link #render};
     * it restores the full viewport. What stands still (terrain, water, obstacles) is drawn once into
     * a cached image and copied each frame; only the hole and the balls are drawn on top.
     */
    public void renderMinimap(int x, int y, int sizePx, int framebufferWidth, int framebufferHeight) {
        if (sizePx < 8) return;
        int target = glGetInteger(GL_FRAMEBUFFER_BINDING);
        timer.start();
        if (minimapDirty || minimapCache.width() != sizePx) {
            drawMinimapCache(sizePx);
            minimapDirty = false;
            glBindFramebuffer(GL_FRAMEBUFFER, target);
        }
        int glY = framebufferHeight - y - sizePx;
        glViewport(x, glY, sizePx, sizePx);
        glDisable(GL_DEPTH_TEST);
        blitShader.use();
        minimapCache.bindColour(0);
        blitShader.set("uImage", 0);
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glBindVertexArray(0);
        int border = minimapBorder(sizePx), inner = sizePx - 2 * border;
        glViewport(x + border, glY + border, inner, inner);
        glEnable(GL_SCISSOR_TEST);
        glScissor(x + border, glY + border, inner, inner);
        float metresPerPixel = updateMinimapFrame(inner);
        objects.renderMinimap(minimapFrame, 4f * metresPerPixel);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_DEPTH_TEST);
        glViewport(0, 0, framebufferWidth, framebufferHeight);
        timer.mark("minimap");
    }

    private static int minimapBorder(int sizePx) {
        return Math.max(2, sizePx / 100);
    }

    /** The minimap's camera for an inner square of {@code inner} pixels; returns metres per pixel. */
    private float updateMinimapFrame(int inner) {
        var b = course.bounds();
        double pad = 0.02 * Math.max(b.width(), b.depth());
        minimapFrame.updateTopDown(b.minX() - pad, b.minY() - pad, b.maxX() + pad, b.maxY() + pad,
                Math.min(0, terrain.minHeight()) - 1,
                Math.max(Math.max(0, terrain.maxHeight()) + ObjectsPass.FLAG_HEIGHT, obstacles.top()) + 1,
                inner, inner, lastTime);
        return (float) (Math.max(b.width(), b.depth()) + 2 * pad) / inner;
    }

    /** The minimap's still part (frame, terrain, plain water, solid obstacles) into its cached image. */
    private void drawMinimapCache(int sizePx) {
        minimapCache.ensureSize(sizePx, sizePx);
        minimapCache.bind();
        glDisable(GL_MULTISAMPLE);
        glClearColor(0.08f, 0.10f, 0.08f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        int border = minimapBorder(sizePx), inner = sizePx - 2 * border;
        glViewport(border, border, inner, inner);
        glEnable(GL_SCISSOR_TEST);
        glScissor(border, border, inner, inner);
        glClearColor(0.20f, 0.24f, 0.20f, 1f);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        updateMinimapFrame(inner);
        terrain.render(minimapFrame);
        water.renderSimple(minimapFrame);
        obstacles.renderMinimap(minimapFrame);
        elements.renderMinimap(minimapFrame);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_MULTISAMPLE);
    }

    /** Whether the water shows the mirrored scene and the refracted bed (on by default); off: flat colours, cheaper. */
    public void setWaterReflections(boolean on) {
        waterReflections = on;
    }

    /** Turns the quality's back-face culling off or on again (tests compare the pictures). */
    void cullBackFaces(boolean on) {
        cullBackFaces = on;
    }

    /** Whether the sun casts shadows (on by default). */
    public void setShadows(boolean on) {
        shadows = on;
    }

    public boolean shadows() {
        return shadows;
    }

    public float waterTargetScale() {
        return waterTargetScale;
    }

    public boolean waterReflections() {
        return waterReflections;
    }

    /** The resolution of the water's reflection and refraction images relative to the viewport, 0.1 to 1 (default 0.5). */
    public void setWaterTargetScale(float scale) {
        waterTargetScale = Math.max(0.1f, Math.min(1f, scale));
    }

    /**
     * Whether the scene goes through the FXAA filter ({@link FxaaPass}; off by default): for frames
     * without MSAA. On llvmpipe it costs about 8 ms a frame at 1280x720 (docs/rendering.md), so the
     * game turns it on only when the player asks (UserSettings.antiAliasing).
     */
    public void setAntiAliasing(boolean on) {
        antiAliasing = on;
    }

    public boolean antiAliasing() {
        return antiAliasing;
    }

    /** Renders one frame into the currently bound framebuffer, whose size is width x height pixels. */
    public void render(OrbitCamera camera, int width, int height, float time) {
        lastTime = time;
        frame.update(camera, width, height, time);
        int output = glGetInteger(GL_FRAMEBUFFER_BINDING);
        int target = output;
        if (antiAliasing) {
            if (fxaa == null) fxaa = new FxaaPass();
            target = fxaa.begin(width, height); // the scene into FXAA's image, filtered onto the output at the end
        }
        timer.start();
        frame.shadowsOn = shadows;
        frame.ballShadowsInline = !ballShadowRedraw;
        objects.ballShadows(frame);
        minimapFrame.shadowsOn = false; // a map reads better without shadows
        if (shadows && shadowMapDirty) {
            renderShadowMap();
            shadowMapDirty = false;
            glBindFramebuffer(GL_FRAMEBUFFER, target);
        }
        // Rebuilt meshes (another colouring, say) lose their cells: search them again.
        if (sunlitCountdown < 0 && terrain.sunlitIndexCount() < 0) sunlitCountdown = 0;
        if (sunlitTerrain && shadows && sunlitCountdown >= 0 && sunlitCountdown-- == 0) {
            terrain.setShadowedCells(shadowMap);
        }
        timer.mark("shadowMap");
        boolean mirror = water.hasWater() && waterReflections;
        boolean targets = mirror && waterImages;
        if (targets) {
            renderWaterTargets(width, height);
            glBindFramebuffer(GL_FRAMEBUFFER, target);
        }
        water.useTargets(targets);
        water.useBedBlend(mirror && !waterImages);
        glViewport(0, 0, width, height);
        // No colour clear: the sky fills every pixel the scene leaves at the far plane.
        glClear(GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDisable(GL_CULL_FACE);
        glEnable(GL_MULTISAMPLE);
        timer.mark("clear");
        // The closed meshes without their far faces (software tier): the pixels behind the near faces are
        // never rasterised. The elements (decals) and objects (the flag's cloth is seen from both sides) keep every face.
        cullFaces(cullBackFaces);
        terrain.render(frame);
        timer.mark("terrain");
        obstacles.renderInRect(frame, new int[]{0, 0, width, height});
        timer.mark("obstacles");
        cullFaces(false);
        elements.render(frame);
        timer.mark("elements");
        objects.render(frame);
        timer.mark("objects");
        if (ballShadowRedraw && shadows && frame.ballShadowCount > 0) drawBallShadows(width, height);
        timer.mark("ballShadows");
        cullFaces(cullBackFaces);
        surroundings.render(frame); // after the course: early depth test skips what it covers
        timer.mark("surroundings");
        cullFaces(false);
        // The sky after the opaque passes, depth-tested at the far plane: its clouds are shaded only where it shows.
        sky.render(frame);
        timer.mark("sky");
        water.render(frame);
        timer.mark("water");
        if (antiAliasing) {
            fxaa.resolve(output, width, height);
            timer.mark("fxaa");
        }
    }

    /**
     * The balls' shadows on software rasterisers: the opaque passes again, with the per-ball shadow
     * term, inside a scissor round where the shadows can fall (the same depths at GL_LEQUAL, as the
     * vertex shaders' positions are invariant). The first draw left them out.
     */
    private void drawBallShadows(int width, int height) {
        BallShadowBounds.Region region = BallShadowBounds.of(frame.ballShadows, frame.ballShadowCount, frame.sun.direction(), terrain.terrain()::height,
                course.bounds(), Math.min(0, terrain.minHeight()) - 0.1, frame.viewProjection, width, height);
        if (region == null) return;
        int[] r = region.rect();
        glEnable(GL_SCISSOR_TEST);
        glScissor(r[0], r[1], r[2], r[3]);
        frame.ballShadowsInline = true;
        cullFaces(cullBackFaces); // the faces just drawn, no others
        terrain.redrawWithin(frame, region.box()); // the chunks at the levels just drawn
        obstacles.renderWithin(frame, region.box());
        cullFaces(false);
        objects.renderForBallShadows(frame);
        frame.ballShadowsInline = false;
        glDisable(GL_SCISSOR_TEST);
    }

    private static void cullFaces(boolean on) {
        if (on) glEnable(GL_CULL_FACE);
        else glDisable(GL_CULL_FACE);
    }

    /** The sun's view of the casters that stand still (terrain, obstacles, pole, flag) into the shadow map. */
    private void renderShadowMap() {
        shadowMap.begin();
        depthShader.use();
        depthShader.set("uLightViewProjection", shadowMap.lightViewProjection());
        terrain.drawDepth(depthShader);
        obstacles.drawDepth(depthShader);
        elements.drawDepth(depthShader);
        objects.drawShadowCasters(depthShader);
        shadowMap.end();
    }

    /**
     * Fills the water's targets: the scene above z = 0 seen in the mirror (sky, terrain, objects)
     * and the terrain below z = 0 from the real camera. The clip planes reach a little past the
     * surface so that ripples never reveal a gap at the waterline.
     */
    private void renderWaterTargets(int width, int height) {
        int w = Math.max(1, Math.round(width * waterTargetScale)), h = Math.max(1, Math.round(height * waterTargetScale));
        RenderTarget reflection = water.reflection(), refraction = water.refraction();
        reflection.ensureSize(w, h);
        refraction.ensureSize(w, h);
        glDisable(GL_MULTISAMPLE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDisable(GL_CULL_FACE);
        glEnable(GL_CLIP_DISTANCE0);

        // Only where the water shows (plus the ripples' reach) is ever read back: draw there only.
        int[] wet = water.screenRect(frame.viewProjection, w, h, 2.5f * WaterPass.DISTORTION);
        if (wet == null) wet = new int[]{0, 0, 1, 1};
        reflection.bind();
        glClearColor(0.62f, 0.78f, 0.93f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(wet[0], wet[1], wet[2], wet[3]);
        mirrorFrame.mirrorOf(frame, w, h);
        mirrorFrame.shadowsOn = shadows && shadowsInWater;
        mirrorFrame.clipPlane.set(0, 0, 1, 0.01f);
        terrain.renderForWaterTarget(mirrorFrame); // the coarser mesh, where there is one: far banks, mirrored
        obstacles.renderInRect(mirrorFrame, wet);
        objects.render(mirrorFrame);
        surroundings.render(mirrorFrame);
        sky.render(mirrorFrame);
        timer.mark("reflectionTarget");

        refraction.bind();
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.30f, 0.27f, 0.18f, 1f); // lake-bed mud where nothing was drawn
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        refractionFrame.copyOf(frame, w, h);
        refractionFrame.shadowsOn = shadows && shadowsInWater;
        refractionFrame.clipPlane.set(0, 0, -1, 0.01f);
        // The full mesh (the lake bed's edge shows through the shallows), but only the rows and the
        // obstacles that reach under the water: nothing else survives the clip plane.
        float[] under = water.underwaterBox(0.2f, 0.02f);
        terrain.renderWithin(refractionFrame, under);
        obstacles.renderWithin(refractionFrame, under);
        objects.render(refractionFrame);
        timer.mark("refractionTarget");

        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_CLIP_DISTANCE0);
        glEnable(GL_MULTISAMPLE);
    }

    @Override
    public void close() {
        if (fxaa != null) fxaa.close();
        if (materials != null) materials.close();
        if (blitShader != null) blitShader.close();
        if (emptyVao != 0) glDeleteVertexArrays(emptyVao);
        minimapCache.close();
        shadowMap.close();
        depthShader.close();
        for (int i = passes.size() - 1; i >= 0; i--) passes.get(i).close();
    }
}
