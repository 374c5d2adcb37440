package minigolf.render;

import java.util.HashMap;
import java.util.Map;

/**
 * A sun-lit program (terrain, object) in the shadow variants of shadow.glsl: unshadowed, with the
 * sun's shadow map, and with the map plus the balls' analytic shadows, each with the map's tap count.
 * Each variant is compiled on first use. Passes call {@link #use} per draw and get the program whose
 * lighting and shadow uniforms are set; the frame decides the variant.
 */
final class LitShader implements AutoCloseable {
    private final String name;
    /** Defines every variant gets (such as terrain-vertexlit's SKIRTS). */
    private final String[] defines;
    private final Map<String, ShaderProgram> variants = new HashMap<>();

    LitShader(String name, String... defines) {
        this.name = name;
        this.defines = defines.clone();
        use(Variant.UNSHADOWED, 4); // fail at construction on a broken source, not mid-frame
    }

    /** Which shadow code a draw needs. */
    enum Variant {
        UNSHADOWED, MAP, MAP_AND_BALLS;

        static Variant of(FrameContext frame) {
            if (!frame.shadowsOn || frame.shadowMap == null) return UNSHADOWED;
            return frame.ballShadowsInline && frame.ballShadowCount > 0 ? MAP_AND_BALLS : MAP;
        }
    }

    /** Binds the frame's variant and sets the sun, eye and shadow uniforms; the pass sets the rest. */
    ShaderProgram use(FrameContext frame) {
        return use(frame, Variant.of(frame));
    }

    /** As above with a chosen variant (UNSHADOWED for ground the sun's map cannot darken, see SunlitCells). */
    ShaderProgram use(FrameContext frame, Variant v) {
        ShaderProgram program = use(v, frame.shadowMap == null ? 4 : frame.shadowMap.taps());
        Lighting.apply(program, frame, v);
        return program;
    }

    private ShaderProgram use(Variant v, int taps) {
        String key = v + "/" + taps;
        ShaderProgram program = variants.get(key);
        if (program == null) {
            String[] shadows = switch (v) {
                case UNSHADOWED -> new String[0];
                case MAP -> new String[]{"SHADOW_MAP", "SHADOW_TAPS " + taps};
                case MAP_AND_BALLS -> new String[]{"SHADOW_MAP", "SHADOW_TAPS " + taps, "BALL_SHADOWS"};
            };
            String[] all = java.util.Arrays.copyOf(defines, defines.length + shadows.length);
            System.arraycopy(shadows, 0, all, defines.length, shadows.length);
            program = ShaderProgram.load(name, all);
            variants.put(key, program);
        }
        program.use();
        return program;
    }

    /** Variants compiled so far (tests: a frame without shadows compiles no shadowed one). */
    int compiledVariants() {
        return variants.size();
    }

    @Override
    public void close() {
        for (ShaderProgram p : variants.values()) p.close();
        variants.clear();
    }
}
