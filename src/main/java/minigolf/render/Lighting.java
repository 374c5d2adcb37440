package minigolf.render;

/** Sets the uniforms of {@code lighting.glsl} and {@code shadow.glsl} from the frame's sun, eye and shadows. */
final class Lighting {
    private Lighting() {
    }

    static void apply(ShaderProgram shader, FrameContext frame) {
        apply(shader, frame, LitShader.Variant.UNSHADOWED);
    }

    static void apply(ShaderProgram shader, FrameContext frame, LitShader.Variant variant) {
        shader.set("uEye", frame.eye);
        shader.set("uSunDirection", frame.sun.direction());
        shader.set("uSunColor", frame.sun.color());
        shader.set("uSkyAmbient", frame.sun.skyAmbient());
        shader.set("uGroundAmbient", frame.sun.groundAmbient());
        frame.atmosphere.apply(shader);
        shader.set("uTime", frame.time);
        if (frame.materials != null) frame.materials.apply(shader);
        if (variant != LitShader.Variant.UNSHADOWED) frame.shadowMap.apply(shader, frame.sun.shadowSoftness());
        if (variant == LitShader.Variant.MAP_AND_BALLS) {
            shader.set("uBallCount", frame.ballShadowCount);
            shader.setVec4Array("uBalls", frame.ballShadows, frame.ballShadowCount);
        }
    }
}
