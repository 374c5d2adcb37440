package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.HeightProbe;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The screen rectangle round the balls' shadows (plain geometry, no GL). */
class BallShadowBoundsTest {
    static final int W = 1280, H = 720;
    static final Bounds COURSE = new Bounds(-10, -10, 10, 10);
    static final HeightProbe FLAT = (x, y) -> 0.0;
    static final Vector3f SUN = FrameContext.Sun.afternoon().direction();

    /** Looking down at the origin from 6 m away at 40 degrees. */
    static Matrix4f camera() {
        return new Matrix4f().perspective((float) Math.toRadians(45), (float) W / H, 0.05f, 200f)
                .lookAt(0, -4.6f, 3.86f, 0, 0, 0, 0, 0, 1);
    }

    static float[] pixel(Matrix4f vp, double x, double y, double z) {
        Vector4f c = vp.transform(new Vector4f((float) x, (float) y, (float) z, 1));
        return new float[]{(c.x / c.w * 0.5f + 0.5f) * W, (c.y / c.w * 0.5f + 0.5f) * H};
    }

    static boolean inside(int[] r, float[] p) {
        return p[0] >= r[0] && p[0] <= r[0] + r[2] && p[1] >= r[1] && p[1] <= r[1] + r[3];
    }

    @Test
    void groundAlongTheSunsRayOnFlatGroundIsTheClosedForm() {
        double t = BallShadowBounds.groundAlong(0.3, -0.2, 0.5, SUN.x, SUN.y, SUN.z, FLAT, COURSE, -1);
        assertEquals(0.5 / SUN.z, t, 1e-3);
        // On a slope h = 0.2 x the ray meets z = 0.2 x: 0.5 - t lz = 0.2 (0.3 - t lx).
        HeightProbe slope = (x, y) -> 0.2 * x;
        double ts = BallShadowBounds.groundAlong(0.3, -0.2, 0.5, SUN.x, SUN.y, SUN.z, slope, COURSE, -5);
        assertEquals((0.5 - 0.06) / (SUN.z - 0.2 * SUN.x), ts, 1e-3);
        // A ray that leaves the course before reaching the ground.
        assertTrue(Double.isNaN(BallShadowBounds.groundAlong(9.9, 9.9, 3, SUN.x, SUN.y, SUN.z, FLAT, COURSE, -1)));
    }

    @Test
    void theRectangleHoldsTheShadowAndTheBallAndLittleElse() {
        float r = 0.064f;
        float[] ball = {0.2f, 0.1f, r, r};
        Matrix4f vp = camera();
        int[] rect = BallShadowBounds.of(ball, 1, SUN, FLAT, COURSE, -1, vp, W, H).rect();
        assertNotNull(rect);
        // The shadow's centre: where the sun's ray through the ball's centre meets the ground.
        double t = r / SUN.z;
        assertTrue(inside(rect, pixel(vp, 0.2 - t * SUN.x, 0.1 - t * SUN.y, 0)), "shadow centre outside " + java.util.Arrays.toString(rect));
        assertTrue(inside(rect, pixel(vp, 0.2, 0.1, r)), "ball outside");
        // The darkened edge: a point on the ground 1.1 r across the ray from the centre's foot is still inside.
        Vector3f across = new Vector3f(SUN).cross(0, 0, 1).normalize().mul(1.1f * r);
        assertTrue(inside(rect, pixel(vp, 0.2 - t * SUN.x + across.x, 0.1 - t * SUN.y + across.y, 0)));
        // The world box holds the ball and the shadow's centre, and not much more.
        float[] box = BallShadowBounds.of(ball, 1, SUN, FLAT, COURSE, -1, vp, W, H).box();
        assertTrue(box[0] <= 0.2 - r && box[3] >= 0.2 + r && box[2] <= 0 && box[5] >= 2 * r, java.util.Arrays.toString(box));
        assertTrue(box[0] <= 0.2 - t * SUN.x && box[3] >= 0.2 - t * SUN.x && box[1] <= 0.1 - t * SUN.y && box[4] >= 0.1 - t * SUN.y);
        assertTrue(box[3] - box[0] < 0.5 && box[4] - box[1] < 0.5, java.util.Arrays.toString(box));
        // A few dozen pixels across, not the screen.
        assertTrue(rect[2] * rect[3] < 0.01 * W * H, "rectangle too big: " + java.util.Arrays.toString(rect));
    }

    @Test
    void twoBallsGiveOneRectangleRoundBoth() {
        float r = 0.064f;
        float[] balls = {-1f, 0f, r, r, 1.5f, 0.5f, r, r};
        Matrix4f vp = camera();
        int[] both = BallShadowBounds.of(balls, 2, SUN, FLAT, COURSE, -1, vp, W, H).rect();
        int[] first = BallShadowBounds.of(balls, 1, SUN, FLAT, COURSE, -1, vp, W, H).rect();
        assertTrue(both[2] > first[2] + 100, "the second ball did not widen the rectangle");
        assertTrue(inside(both, pixel(vp, 1.5, 0.5, r)));
        assertTrue(inside(both, pixel(vp, -1, 0, r)));
    }

    @Test
    void aShadowOffScreenGivesNoRectangle() {
        float r = 0.064f;
        // Far to the side, well outside the 45-degree view.
        float[] ball = {9.5f, -3f, r, r};
        assertNull(BallShadowBounds.of(ball, 1, SUN, FLAT, COURSE, -1, camera(), W, H));
        assertNull(BallShadowBounds.of(ball, 0, SUN, FLAT, COURSE, -1, camera(), W, H));
    }

    @Test
    void aBallInTheAirReachesItsShadowFarBelow() {
        float r = 0.064f;
        float[] ball = {0f, 0f, 1.5f, r};
        Matrix4f vp = camera();
        int[] rect = BallShadowBounds.of(ball, 1, SUN, FLAT, COURSE, -1, vp, W, H).rect();
        double t = 1.5 / SUN.z;
        assertTrue(inside(rect, pixel(vp, -t * SUN.x, -t * SUN.y, 0)));
        assertTrue(inside(rect, pixel(vp, 0, 0, 1.5)));
    }
}
