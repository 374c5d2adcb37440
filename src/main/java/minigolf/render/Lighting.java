package minigolf.render;

/** Sets the uniforms of {@code lighting.glsl} from the frame's sun and eye. */
final class Lighting {
    private Lighting() {
    }

    static void apply(ShaderProgram shader, FrameContext frame) {
        shader.set("uEye", frame.eye);
        shader.set("uSunDirection", frame.sun.direction());
        shader.set("uSunColor", frame.sun.color());
        shader.set("uSkyAmbient", frame.sun.skyAmbient());
        shader.set("uGroundAmbient", frame.sun.groundAmbient());
        if (frame.shadowMap != null) {
            frame.shadowMap.apply(shader, frame.shadowsOn);
            shader.set("uBallCount", frame.ballShadowCount);
            shader.setVec4Array("uBalls", frame.ballShadows, frame.ballShadowCount);
        }
    }
}
