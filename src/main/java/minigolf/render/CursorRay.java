package minigolf.render;

import org.joml.Matrix4f;
import org.joml.Vector4f;

/** Where the ray under a cursor meets a horizontal plane: aiming on the ground. Plain geometry. */
public final class CursorRay {
    private CursorRay() {
    }

    /**
     * The point (x, y) where the ray through framebuffer pixel (fx, fy) of a fw x fh image meets the
     * plane at height z, or null when the ray runs parallel to it or meets it behind the eye.
     */
    public static double[] onPlane(OrbitCamera camera, int fw, int fh, double fx, double fy, double z) {
        float nx = (float) (2 * fx / fw - 1), ny = (float) (1 - 2 * fy / fh);
        Matrix4f inv = camera.viewProjection((float) fw / fh, new Matrix4f()).invert();
        Vector4f near = new Vector4f(nx, ny, -1, 1).mul(inv), far = new Vector4f(nx, ny, 1, 1).mul(inv);
        near.div(near.w);
        far.div(far.w);
        double dz = far.z - near.z;
        if (Math.abs(dz) < 1e-9) return null;
        double t = (z - near.z) / dz;
        if (t < 0) return null;
        return new double[]{near.x + t * (far.x - near.x), near.y + t * (far.y - near.y)};
    }
}
