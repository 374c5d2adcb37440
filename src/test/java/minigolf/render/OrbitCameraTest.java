package minigolf.render;

import minigolf.course.Course;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** CPU-only: no GL needed. */
class OrbitCameraTest {
    @Test
    void pitchAndDistanceAreClamped() {
        OrbitCamera c = new OrbitCamera(new Vector3f(), 0, 0.5f, 5);
        c.rotate(0, 10);
        assertEquals(OrbitCamera.MAX_PITCH, c.pitch(), 1e-6);
        c.rotate(0, -20);
        assertEquals(OrbitCamera.MIN_PITCH, c.pitch(), 1e-6);
        for (int i = 0; i < 200; i++) c.zoom(1);
        assertTrue(c.distance() >= 0.3f - 1e-6 && c.distance() < 0.31f, "zoom in not clamped: " + c.distance());
        for (int i = 0; i < 400; i++) c.zoom(-1);
        assertTrue(c.distance() <= 200f + 1e-3, "zoom out not clamped: " + c.distance());
    }

    @Test
    void resetRestoresTheOpeningView() {
        Course lake = TestCourses.lake();
        OrbitCamera c = OrbitCamera.behindBall(lake, TestCourses.LAKE, 1.6f);
        Vector3f eye = c.eye();
        c.rotate(1, 0.3f);
        c.pan(100, -40, 600);
        c.zoom(3);
        assertTrue(c.eye().distance(eye) > 0.5f);
        c.reset();
        assertEquals(0, c.eye().distance(eye), 1e-4);
    }

    @Test
    void openingViewStandsBehindTheBallAndSeesTheWholeCourse() {
        Course lake = TestCourses.lake();
        OrbitCamera c = OrbitCamera.behindBall(lake, TestCourses.LAKE, 1.6f);
        Vector3f ball = c.target();
        assertEquals(lake.start().x(), ball.x, 1e-6);
        Vector3f toHole = new Vector3f((float) lake.hole().position().x(), (float) lake.hole().position().y(), ball.z).sub(ball);
        Vector3f toEye = c.eye().sub(ball);
        assertTrue(toEye.x * toHole.x + toEye.y * toHole.y < 0, "the eye is not behind the ball");
        assertTrue(c.eye().z > ball.z + 1, "the eye is not above the course");
        for (Vector3f p : OrbitCamera.courseOutline(lake, TestCourses.LAKE)) {
            float[] s = c.project(p, 1600, 1000);
            assertNotNull(s, "behind the eye: " + p);
            assertTrue(s[0] >= 0 && s[0] <= 1600 && s[1] >= 0 && s[1] <= 1000, "off screen: " + p + " at " + s[0] + "," + s[1]);
        }
        // The ball is drawn in the lower half, the hole above it.
        float[] b = c.project(ball, 1600, 1000);
        assertTrue(b[1] > 500, "ball at y " + b[1]);
    }

    @Test
    void theFinalCardsViewKeepsTheCourseInSightFromEverySideRightOfTheMiddle() {
        Course lake = TestCourses.lake();
        OrbitCamera c = new OrbitCamera(new Vector3f(0, 0, 0), 0.3f, (float) Math.toRadians(40), 1);
        c.setScreenShiftX(0.42f);
        c.frameFromAllSides(lake, TestCourses.LAKE, 1.6f, 0.92f);
        float framed = c.distance();
        for (int k = 0; k < 16; k++) { // also the yaws between the eight it was framed from
            c.rotate((float) (Math.PI / 8), 0);
            for (Vector3f p : OrbitCamera.courseOutline(lake, TestCourses.LAKE)) {
                float[] s = c.project(p, 1600, 1000);
                assertNotNull(s, "behind the eye: " + p);
                assertTrue(s[0] >= 0 && s[0] <= 1600 && s[1] >= 0 && s[1] <= 1000, "off screen at yaw " + c.yaw() + ": " + p);
            }
        }
        assertEquals(framed, c.distance(), 0, "turning keeps the distance");
        float[] middle = c.project(new Vector3f(0, 0, 0), 1600, 1000);
        assertEquals(800 * 1.42, middle[0], 1, "the target shows 0.42 NDC right of the middle");
        // Tighter than framing from one side would need only if some side needs more: never less.
        OrbitCamera one = new OrbitCamera(new Vector3f(0, 0, 0), 0.3f, (float) Math.toRadians(40), 1);
        one.setScreenShiftX(0.42f);
        one.fit(OrbitCamera.courseOutline(lake, TestCourses.LAKE), 1.6f, 0.92f);
        assertTrue(framed >= one.distance() - 1e-4, framed + " vs " + one.distance());
    }

    @Test
    void panningDragsTheGroundWithTheCursor() {
        OrbitCamera c = new OrbitCamera(new Vector3f(), 0, 0.6f, 10); // eye on +x, looking towards -x; screen right is +y
        c.pan(100, 0, 600);
        assertEquals(0, c.target().z, 1e-6);
        assertEquals(0, c.target().x, 1e-5);
        assertTrue(c.target().y < -0.5f, "dragging right should slide the ground right, the target left: " + c.target());
        c.pan(0, 100, 600); // dragging down pulls the ground towards the eye: the target moves away, to -x
        assertTrue(c.target().x < -0.5f, "dragging down: " + c.target());
    }
}
