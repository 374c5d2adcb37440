package minigolf.render;

import java.util.Locale;

import static org.lwjgl.opengl.GL11.GL_RENDERER;
import static org.lwjgl.opengl.GL11.glGetString;

/**
 * How much the renderer spends per frame. Real GPUs get {@link #HIGH}; software rasterisers
 * (Mesa llvmpipe/softpipe, lavapipe, Microsoft's basic driver) get {@link #SOFTWARE}, where
 * multisampling alone quadruples the cost of every pixel (measured: 546 against 206 ms per frame on
 * the lake at 1280x720, 2 shared cores). {@code -Dminigolf.quality=high|software} or the
 * environment variable {@code MINIGOLF_QUALITY} overrides the choice.
 *
 * @param samples          multisampling of the window or off-screen target (0: none)
 * @param shadowMapSize    texels per side of the sun's shadow map
 * @param waterTargetScale the water's reflection/refraction images relative to the viewport
 * @param shadowsInWater   whether the mirrored and refracted scenes sample the shadow map too
 * @param shadowTaps       depth-compare taps per shadowed pixel: 4 (a 3x3-texel footprint) or 1 (2x2)
 * @param vertexLit        whether the terrain and the objects are lit per vertex (Gouraud; only shadows per pixel)
 * @param terrainSpacing   the terrain mesh's finest sample spacing in metres (llvmpipe pays per triangle)
 * @param sunlitTerrain    whether terrain cells the shadow map cannot darken are drawn without the shadow tap
 *                         (the map is read back and searched once after it is drawn, see {@link SunlitCells})
 * @param ballShadowRedraw whether the balls' shadows are shaded only in a scissored second draw round them
 *                         (true), instead of by every lit pixel of the screen (see {@link BallShadowBounds})
 * @param waterImages      whether the water mirrors the scene and shows the bed through images drawn for it
 *                         (true); false: the sky's gradient is mirrored and the bed already drawn behind the
 *                         water is tinted by blending (see {@link WaterPass}), no extra scene drawn
 * @param cullBackFaces    whether the closed meshes (terrain, obstacles, elements, props) skip their faces turned
 *                         away from the camera before they are rasterised: hidden anyway, but a software
 *                         rasteriser pays for every pixel it depth-tests (see SceneRenderer.render)
 */
public record RenderQuality(String name, int samples, int shadowMapSize, float waterTargetScale, boolean shadowsInWater,
                            int shadowTaps, boolean vertexLit,
                            double terrainSpacing, boolean sunlitTerrain,
                            boolean ballShadowRedraw, boolean waterImages, boolean cullBackFaces) {
    public static final RenderQuality HIGH = new RenderQuality("high", 4, 2048, 0.5f, true, 4, false, 0.05, false, false, true, false);
    public static final RenderQuality SOFTWARE = new RenderQuality("software", 0, 1024, 0.35f, false, 1, true, 0.1, true, true, false, true);

    /** Whether a GL_RENDERER string names a software rasteriser. */
    public static boolean isSoftware(String glRenderer) {
        if (glRenderer == null) return false;
        String r = glRenderer.toLowerCase(Locale.ROOT);
        return r.contains("llvmpipe") || r.contains("softpipe") || r.contains("swrast") || r.contains("lavapipe")
                || r.contains("software") || r.contains("basic render");
    }

    /** The quality for a renderer, unless overridden by the property or environment variable. */
    public static RenderQuality forRenderer(String glRenderer) {
        RenderQuality forced = named(override());
        if (forced != null) return forced;
        return isSoftware(glRenderer) ? SOFTWARE : HIGH;
    }

    /** high, software (or low), or null for anything else (auto). */
    public static RenderQuality named(String name) {
        if (name == null) return null;
        return switch (name.strip().toLowerCase(Locale.ROOT)) {
            case "high" -> HIGH;
            case "software", "low" -> SOFTWARE;
            default -> null;
        };
    }

    /** The quality for the current GL context. */
    public static RenderQuality current() {
        return forRenderer(glGetString(GL_RENDERER));
    }

    /**
     * The quality for this machine, found before the game window exists (its multisampling must be
     * chosen when it is created): a hidden 64x64 window is opened, asked for GL_RENDERER and closed.
     * If even that fails, {@link #HIGH} (the real window will report the actual problem).
     */
    public static RenderQuality probe() {
        RenderQuality forced = named(override());
        if (forced != null) return forced;
        try (Window w = new Window("Minigolf probe", 64, 64, Window.Options.hidden())) {
            return current();
        } catch (RuntimeException e) {
            return HIGH;
        }
    }

    private static String override() {
        String p = System.getProperty("minigolf.quality");
        return p != null ? p : System.getenv("MINIGOLF_QUALITY");
    }
}
