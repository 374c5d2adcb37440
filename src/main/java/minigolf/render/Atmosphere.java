package minigolf.render;

import minigolf.theme.Rgb;
import minigolf.theme.Theme;
import org.joml.Vector3f;

/**
 * A world's sky and air as the shaders take them (lighting.glsl's fog, sky-colour.glsl's gradient and
 * glow, sky.frag's clouds), from its {@link Theme.Sky}; set on every lit program by {@link Lighting}.
 */
public record Atmosphere(Vector3f zenith, Vector3f horizon, Vector3f below, Vector3f fog, float fogDensity,
                         float cloudCover, Vector3f cloudLit, Vector3f cloudShade, Vector3f sunGlow) {
    /** The haze never hides more than this share of a far surface's own colour. */
    public static final float MAX_FOG = 0.6f;

    public static Atmosphere of(Theme theme) {
        Theme.Sky s = theme.sky();
        return new Atmosphere(v(s.zenith()), v(s.horizon()), v(s.below()), v(s.fog()), (float) s.fogDensity(),
                (float) s.cloudCover(), v(s.cloudLit()), v(s.cloudShade()), v(s.sunGlow()));
    }

    static Vector3f v(Rgb c) {
        return new Vector3f(c.r(), c.g(), c.b());
    }

    /** Sets the fog, sky and cloud uniforms (programs without them ignore them). */
    void apply(ShaderProgram shader) {
        shader.set("uFogColor", fog);
        shader.set("uFogDensity", fogDensity);
        shader.set("uSkyZenith", zenith);
        shader.set("uSkyHorizon", horizon);
        shader.set("uSkyBelow", below);
        shader.set("uSunGlowColor", sunGlow);
    }
}
