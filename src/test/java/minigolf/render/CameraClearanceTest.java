package minigolf.render;

import static org.junit.jupiter.api.Assertions.*;

import java.util.List;
import minigolf.course.Obstacle;
import minigolf.game.RoundLoader;
import minigolf.physics.World;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/** The camera never sits behind or inside a tree crown, a wall, the flag: headless, plain geometry. */
class CameraClearanceTest {
    private static final float MAX_PITCH = OrbitCamera.MAX_PITCH;

    @Test
    void aCrownBetweenBallAndEyeMakesTheEyeRiseABitOverIt() {
        // A crown 5 to 7 m out along +x, 2.2 to 4.2 m high: the line to an eye 10 m out at 30 degrees
        // (height 2.89 at x = 5, 4.04 at x = 7) runs through it; at 42 degrees it passes over (4.5 at x = 5).
        CameraClearance c = new CameraClearance(List.of(new float[]{5, -1, 2.2f, 7, 1, 4.2f}), null, 0);
        Vector3f ball = new Vector3f(0, 0, 0);
        Vector3f eye = c.place(ball, 0, (float) Math.toRadians(30), 10, 0.3f, MAX_PITCH, new Vector3f());
        assertEquals(10, eye.distance(ball), 1e-3, "the same distance");
        assertEquals(42, Math.toDegrees(Math.asin(eye.z / 10)), 1e-3, "two steps of 6 degrees steeper");
        assertTrue(c.firstHit(new Vector3f(0, 0, CameraClearance.BALL_TOP), eye) >= 1);
    }

    @Test
    void aTallTreeBetweenBallAndEyeBringsTheEyeInFrontOfIt() {
        // A tall poplar 4.5 to 7 m out along +x, 20 m high: rising 24 degrees does not clear it (at 54
        // degrees the eye is 5.9 m out), so the eye comes in to just in front of it.
        float[] crown = {4.5f, -1, 0, 7, 1, 20};
        CameraClearance c = new CameraClearance(List.of(crown), null, 0);
        Vector3f ball = new Vector3f(0, 0, 0);
        float pitch = (float) Math.toRadians(30);
        Vector3f plain = CameraClearance.orbit(ball, 0, pitch, 10, new Vector3f());
        Vector3f from = new Vector3f(0, 0, CameraClearance.BALL_TOP);
        float hit = c.firstHit(from, plain);
        assertEquals(4.5 / (10 * Math.cos(pitch)), hit, 1e-3, "the line enters the crown's side at x = 4.5");
        Vector3f eye = c.place(ball, 0, pitch, 10, 0.3f, MAX_PITCH, new Vector3f());
        double d = eye.distance(ball);
        assertEquals(hit * 10 - CameraClearance.MARGIN, d, 1e-3, "in front of the crown by the margin");
        assertTrue(d < 10);
        assertTrue(c.firstHit(from, eye) >= 1, "nothing between the eye and the ball");
        assertEquals(0, Math.atan2(eye.y, eye.x), 1e-6, "the same direction");
        // A clear line is left alone.
        Vector3f away = c.place(ball, (float) Math.PI, pitch, 10, 0.3f, MAX_PITCH, new Vector3f());
        assertEquals(CameraClearance.orbit(ball, (float) Math.PI, pitch, 10, new Vector3f()), away);
    }

    @Test
    void aTreeRightBehindTheBallMakesTheEyeRiseOverIt() {
        // A trunk and crown 0.5 to 0.9 m behind the ball, 3 m high: coming in would leave under 0.5 m.
        float[] tree = {0.5f, -0.3f, 0, 0.9f, 0.3f, 3};
        CameraClearance c = new CameraClearance(List.of(tree), null, 0);
        Vector3f ball = new Vector3f(0, 0, 0);
        Vector3f eye = c.place(ball, 0, (float) Math.toRadians(34), 8, 0.3f, MAX_PITCH, new Vector3f());
        assertEquals(8, eye.distance(ball), 1e-3, "the same distance");
        double pitch = Math.asin(eye.z / 8);
        assertTrue(pitch > Math.toRadians(34) && pitch <= MAX_PITCH + 1e-4, "steeper: " + Math.toDegrees(pitch));
        assertTrue(c.firstHit(new Vector3f(0, 0, CameraClearance.BALL_TOP), eye) >= 1);
        // Over 3 m at 0.5 to 0.9 m out: tan(pitch) > (3 - 0.05) / 0.9 means about 73 degrees at least.
        assertTrue(Math.toDegrees(pitch) > 72, "over the crown: " + Math.toDegrees(pitch));
    }

    @Test
    void onTheTreeSlalomNoEyeLooksThroughACrownAtTheBall() throws Exception {
        World w = RoundLoader.load(java.nio.file.Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "rounds",
                "meadowbrook-18.json")).hole(5).world();
        assertEquals("Tree Slalom", w.course().name());
        CameraClearance c = CameraClearance.of(w.course(), w.terrain()::height);
        long trees = w.course().obstacles().stream().filter(o -> o instanceof Obstacle.Tree).count();
        assertTrue(c.boxes().size() > trees * 2, "trunks, crowns, rails and the flag: " + c.boxes().size());
        // The line of sight itself is always clear (the cone round it where it can be).
        CameraClearance bare = new CameraClearance(c.boxes(), w.terrain()::height, 0);
        int blockedBefore = 0, placed = 0;
        float[][] balls = {{3.3f, 0}, {2.6f, -0.1f}, {-0.6f, 0.2f}, {1.0f, 0}};
        for (float[] b : balls) {
            Vector3f ball = new Vector3f(b[0], b[1], (float) w.terrain().height(b[0], b[1]));
            Vector3f from = new Vector3f(ball).add(0, 0, CameraClearance.BALL_TOP);
            for (int k = 0; k < 72; k++) {
                float yaw = (float) (k * Math.PI / 36);
                for (float pitch : new float[]{(float) Math.toRadians(20), OrbitCamera.DEFAULT_PITCH, (float) Math.toRadians(55)}) {
                    Vector3f plain = CameraClearance.orbit(ball, yaw, pitch, 9, new Vector3f());
                    if (bare.firstHit(from, plain) < 1) blockedBefore++;
                    Vector3f eye = c.place(ball, yaw, pitch, 9, 0.3f, MAX_PITCH, new Vector3f());
                    assertTrue(bare.firstHit(from, eye) >= 1, "ball " + b[0] + "," + b[1] + " yaw " + k * 5 + " pitch "
                            + Math.toDegrees(pitch) + ": eye " + eye);
                    placed++;
                }
            }
        }
        assertEquals(4 * 72 * 3, placed);
        assertTrue(blockedBefore > 20, "the test is not blind: plain orbits blocked " + blockedBefore);
    }

    @Test
    void theConeKeepsACrownBesideTheLineOutOfTheMiddleOfThePicture() {
        // A crown 5 to 6 m out, 0.5 m to the side of the line of sight: the bare line misses it; the
        // cone (0.14 per metre: 0.8 m at 5.7 m) does not, and the eye rises until it is clear of it too.
        float[] crown = {5, 0.5f, 0, 6, 1.5f, 3};
        Vector3f from = new Vector3f(0, 0, CameraClearance.BALL_TOP);
        Vector3f eye = CameraClearance.orbit(new Vector3f(), 0, (float) Math.toRadians(20), 10, new Vector3f());
        assertTrue(new CameraClearance(List.of(crown), null, 0).firstHit(from, eye) >= 1);
        CameraClearance cone = new CameraClearance(List.of(crown), null);
        assertTrue(cone.firstHit(from, eye) < 1);
        Vector3f placed = cone.place(new Vector3f(), 0, (float) Math.toRadians(20), 10, 0.3f, MAX_PITCH, new Vector3f());
        assertTrue(cone.firstHit(from, placed) >= 1);
        assertTrue(placed.z > eye.z, "higher: " + placed.z);
    }

    @Test
    void aRayThatStartsInsideABoxIgnoresIt() {
        float[] box = {-1, -1, -1, 1, 1, 1};
        assertEquals(Float.POSITIVE_INFINITY, CameraClearance.entry(box, 0, 0, 0, 5, 0, 0));
        assertEquals(0.25f, CameraClearance.entry(box, -2, 0, 0, 4, 0, 0), 1e-6);
        assertEquals(Float.POSITIVE_INFINITY, CameraClearance.entry(box, -2, 3, 0, 4, 0, 0), "passes beside it");
    }

    /**
     * The orbit camera takes a correction at once where the ball would be hidden (a crown comes in
     * between), and glides back out once the way is clear; the player's turning stays instant.
     */
    @Test
    void theCameraNeverHidesTheBallAndGlidesBackOut() {
        CameraClearance c = new CameraClearance(List.of(new float[]{5, -1, 2.2f, 7, 1, 4.2f}), null, 0);
        OrbitCamera cam = new OrbitCamera(new Vector3f(0, 0, 0), (float) Math.PI / 2, (float) Math.toRadians(30), 10);
        cam.setClearance(c);
        cam.ease(1f / 60);
        assertEquals(30, pitchDegrees(cam.eye()), 1e-3, "the eye out along +y, the crown along +x: nothing in the way");
        // The player turns to look along -x: the crown comes in between, the eye rises over it at once.
        cam.rotate((float) -Math.PI / 2, 0);
        cam.ease(1f / 60);
        assertEquals(42, pitchDegrees(cam.eye()), 1e-3);
        assertEquals(0, cam.eye().y, 1e-4, "the turn itself is instant");
        assertTrue(c.firstHit(new Vector3f(0, 0, CameraClearance.BALL_TOP), cam.eye()) >= 1, "the ball is in sight");
        // Turned back, the way is clear: the eye glides back down instead of dropping 12 degrees in a frame.
        cam.rotate((float) Math.PI / 2, 0);
        cam.ease(1f / 60);
        double oneFrame = pitchDegrees(cam.eye());
        assertTrue(oneFrame > 40 && oneFrame < 42, "one frame in: " + oneFrame);
        for (int i = 0; i < 60; i++) cam.ease(1f / 60);
        assertEquals(30, pitchDegrees(cam.eye()), 0.01, "down after a second");
        cam.rotate((float) -Math.PI / 2, 0);
        cam.ease(1f / 60);
        cam.reset();
        assertEquals(30, Math.toDegrees(Math.asin(cam.eye().z / 10)), 1e-3, "a reset cuts, it does not glide");
    }

    private static double pitchDegrees(Vector3f eye) {
        return Math.toDegrees(Math.asin(eye.z / eye.length()));
    }
}
