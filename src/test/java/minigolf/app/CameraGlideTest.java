package minigolf.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The camera's glide after the ball covers the same share of the way in the same time at any frame rate. */
class CameraGlideTest {
    /** The share covered after {@code frames} frames of {@code dt} seconds each. */
    private static double covered(int frames, float dt) {
        double left = 1;
        for (int i = 0; i < frames; i++) left *= 1 - CourseScene.glide(0.12f, dt);
        return 1 - left;
    }

    @Test
    void oneFrameAtSixtyIsTheOldStepAndHalfASecondIsTheSameAtEveryFrameRate() {
        assertEquals(0.12, CourseScene.glide(0.12f, 1 / 60f), 1e-6);
        double closedForm = 1 - Math.pow(0.88, 30); // half a second at 60 frames a second: 97.840%
        assertEquals(0.97840, closedForm, 1e-5);
        assertEquals(closedForm, covered(30, 1 / 60f), 1e-5);
        assertEquals(closedForm, covered(10, 1 / 20f), 1e-5); // a slow software renderer
        assertEquals(closedForm, covered(72, 1 / 144f), 1e-5);
        // Before, 10 frames at 20 a second covered only 1 - 0.88^10 = 72.1% in that half second.
        assertEquals(0.0, CourseScene.glide(0.12f, 0), 0);
        assertEquals(0.0, CourseScene.glide(0.12f, -1), 0);
    }
}
