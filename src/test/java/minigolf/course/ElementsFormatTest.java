package minigolf.course;

import static minigolf.course.CourseLoaderTest.BASE;
import static minigolf.course.CourseLoaderTest.SRC;
import static minigolf.course.CourseLoaderTest.edit;
import static minigolf.course.CourseLoaderTest.error;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The course elements of issue 24 in the file format: moving obstacles, bumpers, one-way gates,
 * push zones, magnets and teleports. Parsing with defaults, the writer's exact round trip, and a
 * one-line error for each bad value.
 */
class ElementsFormatTest {
    static final String OBSTACLES = String.join(", ",
            "{ \"type\": \"box\", \"min\": [-0.5, -0.05, 0], \"max\": [0.5, 0.05, 0.2], \"motion\": { \"type\": \"rotate\", \"pivot\": [0, 0, 0], \"period\": 4 } }",
            "{ \"type\": \"wall\", \"from\": [2, -1], \"to\": [2, 1], \"thickness\": 0.05, \"height\": 0.3, \"motion\": { \"type\": \"swing\", \"pivot\": [2, 0, 1], \"axis\": [1, 0, 0], \"amplitudeDeg\": 40, \"period\": 2.5, \"phase\": 0.5 } }",
            "{ \"type\": \"tree\", \"position\": [-2, 3], \"radius\": 0.1, \"height\": 0.3, \"motion\": { \"type\": \"slide\", \"path\": [[0, 0, 0], [1, 0, 0], [1, 1, 0]], \"period\": 3, \"closed\": true } }",
            "{ \"type\": \"bumper\", \"position\": [-3, -3], \"radius\": 0.12 }",
            "{ \"type\": \"gate\", \"from\": [3, -2], \"to\": [3, -1], \"height\": 0.1, \"passTo\": \"left\", \"restitution\": 0.5 }");
    static final String ELEMENTS = String.join("\n",
            "  \"obstacles\": [" + OBSTACLES + "],",
            "  \"pushZones\": [ { \"shape\": { \"type\": \"rect\", \"min\": [-4, 2], \"max\": [-3, 4] }, \"push\": [0, -1.5] } ],",
            "  \"magnets\": [ { \"position\": [3, 3], \"radius\": 0.6, \"strength\": -2 } ],",
            "  \"teleports\": [ { \"entry\": { \"type\": \"circle\", \"center\": [0, -3], \"radius\": 0.2 }, \"exits\": [ { \"position\": [3.5, 0] }, { \"position\": [-4, -4], \"directionDeg\": 45 } ], \"seed\": 7 } ]");

    static String withElements() {
        return edit("  \"obstacles\": []", ELEMENTS);
    }

    @Test
    void readsEveryElementWithDefaults() throws CourseException {
        Course c = CourseLoader.parse(withElements(), SRC);
        List<Obstacle> o = c.obstacles();
        assertEquals(new Obstacle.Moving(new Obstacle.Box(new Vec3(-0.5, -0.05, 0), new Vec3(0.5, 0.05, 0.2), 0, 0.7),
                new Motion.Rotate(new Vec3(0, 0, 0), new Vec3(0, 0, 1), 4, 0)), o.get(0));
        assertEquals(new Motion.Swing(new Vec3(2, 0, 1), new Vec3(1, 0, 0), 40, 2.5, 0.5), ((Obstacle.Moving) o.get(1)).motion());
        Motion.Slide slide = (Motion.Slide) ((Obstacle.Moving) o.get(2)).motion();
        assertEquals(List.of(new Vec3(0, 0, 0), new Vec3(1, 0, 0), new Vec3(1, 1, 0)), slide.path());
        assertEquals(2 + Math.sqrt(2), slide.travel(), 1e-12); // round the closed loop
        assertEquals(new Obstacle.Bumper(new Vec2(-3, -3), 0.12, 0.1, 1.5), o.get(3));
        assertEquals(new Obstacle.Gate(new Vec2(3, -2), new Vec2(3, -1), 0.1, Obstacle.Side.LEFT, 0.5), o.get(4));
        assertEquals(new Vec2(-1, 0), ((Obstacle.Gate) o.get(4)).passNormal());
        assertEquals(List.of(new PushZone(new Shape.Rect(new Vec2(-4, 2), new Vec2(-3, 4)), new Vec2(0, -1.5))), c.pushZones());
        assertEquals(List.of(new Magnet(new Vec2(3, 3), 0.6, -2)), c.magnets());
        Teleport t = c.teleports().get(0);
        assertEquals(new Shape.Circle(new Vec2(0, -3), 0.2), t.entry());
        assertNull(t.exits().get(0).directionDeg());
        assertEquals(45.0, t.exits().get(1).directionDeg());
        assertEquals(7L, t.seed());
        assertEquals(true, c.hasMovingObstacles());
    }

    @Test
    void writerRoundTripsEveryElementExactly() throws CourseException {
        Course c = CourseLoader.parse(withElements(), SRC);
        String json = CourseWriter.toJson(c);
        Course back = CourseLoader.parse(json, SRC);
        assertEquals(c, back);
        assertEquals(json, CourseWriter.toJson(back));
        // A course without the new lists is written without them, as before.
        String plain = CourseWriter.toJson(CourseLoader.parse(BASE, SRC));
        assertEquals(false, plain.contains("pushZones") || plain.contains("magnets") || plain.contains("teleports"));
    }

    @Test
    void motionPosesAreRigidAndRepeat() {
        double[] a = new double[12], b = new double[12];
        Motion turn = new Motion.Rotate(new Vec3(1, 2, 0), new Vec3(0, 0, 2), 4, 0);
        turn.poseAt(1, a); // a quarter turn counter-clockwise about (1, 2)
        assertArrayEquals(new double[] {0, -1, 0, 1, 0, 0, 0, 0, 1}, java.util.Arrays.copyOf(a, 9), 1e-15);
        // The point (2, 2) goes to (1, 3): R p + T.
        assertEquals(1, a[0] * 2 + a[1] * 2 + a[9], 1e-15);
        assertEquals(3, a[3] * 2 + a[4] * 2 + a[10], 1e-15);
        turn.poseAt(5, b);
        assertArrayEquals(a, b, 1e-12);
        Motion slide = new Motion.Slide(List.of(new Vec3(0, 0, 0), new Vec3(2, 0, 0)), 4, 0, false);
        slide.poseAt(1, a);
        assertEquals(1, a[9], 1e-15); // there and back in 4 s: 1 m after 1 s
        slide.poseAt(3, a);
        assertEquals(1, a[9], 1e-15); // and on the way back
        double[] v = new double[9];
        slide.velocityAt(3, v);
        assertEquals(-1, v[6], 1e-15);
        Motion swing = new Motion.Swing(new Vec3(0, 0, 1), new Vec3(1, 0, 0), 30, 2, 0);
        swing.velocityAt(0, v); // fastest at the bottom: amplitude * 2 pi / period
        assertEquals(Math.toRadians(30) * Math.PI, v[0], 1e-15);
    }

    @Test
    void badElementsGiveOneLineErrors() {
        String box = "{ \"type\": \"box\", \"min\": [-0.5, -0.05, 0], \"max\": [0.5, 0.05, 0.2], \"motion\": %s }";
        assertEquals("courses/x.json: obstacles[0].motion.type: expected one of rotate, swing, slide, got \"spin\"",
                error(obstacles(String.format(box, "{ \"type\": \"spin\" }"))));
        assertEquals("courses/x.json: obstacles[0].motion.period: must be between 0.2 and 3600 s, got 0.1",
                error(obstacles(String.format(box, "{ \"type\": \"rotate\", \"pivot\": [0, 0, 0], \"period\": 0.1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion.pivot: missing required field",
                error(obstacles(String.format(box, "{ \"type\": \"rotate\", \"period\": 1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion.axis: must not be the zero vector",
                error(obstacles(String.format(box, "{ \"type\": \"rotate\", \"pivot\": [0, 0, 0], \"axis\": [0, 0, 0], \"period\": 1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion.amplitudeDeg: must be more than 0 and at most 180, got 200",
                error(obstacles(String.format(box, "{ \"type\": \"swing\", \"pivot\": [0, 0, 0], \"amplitudeDeg\": 200, \"period\": 1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion.path: a path needs at least 2 points, got 1",
                error(obstacles(String.format(box, "{ \"type\": \"slide\", \"path\": [[0, 0, 0]], \"period\": 1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion: slides at 40 m/s (path length per period; the limit is 20 m/s)",
                error(obstacles(String.format(box, "{ \"type\": \"slide\", \"path\": [[0, 0, 0], [20, 0, 0]], \"period\": 1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion: the obstacle reaches 12.01 m from the pivot (the limit is 10 m)",
                error(obstacles(String.format(box, "{ \"type\": \"rotate\", \"pivot\": [-11.5, 0, 0], \"period\": 1 }"))));
        assertEquals("courses/x.json: obstacles[0].motion.closed: expected true or false, got a string",
                error(obstacles(String.format(box, "{ \"type\": \"slide\", \"path\": [[0, 0, 0], [1, 0, 0]], \"period\": 1, \"closed\": \"yes\" }"))));
        assertEquals("courses/x.json: obstacles[0].motion: unknown field (known: type, from, to, height, passTo, restitution)",
                error(obstacles("{ \"type\": \"gate\", \"from\": [0, 0], \"to\": [1, 0], \"height\": 0.1, \"passTo\": \"left\", \"motion\": {} }")));
        assertEquals("courses/x.json: obstacles[0].passTo: expected one of left, right, got \"up\"",
                error(obstacles("{ \"type\": \"gate\", \"from\": [0, 0], \"to\": [1, 0], \"height\": 0.1, \"passTo\": \"up\" }")));
        assertEquals("courses/x.json: obstacles[0]: from and to are the same point: the gate has no extent",
                error(obstacles("{ \"type\": \"gate\", \"from\": [1, 0], \"to\": [1, 0], \"height\": 0.1, \"passTo\": \"left\" }")));
        assertEquals("courses/x.json: obstacles[0].restitution: must be between 0 and 2, got 2.1",
                error(obstacles("{ \"type\": \"bumper\", \"position\": [0, 0], \"radius\": 0.1, \"restitution\": 2.1 }")));
        assertEquals("courses/x.json: pushZones[0].push: pushes with 60 m/s^2 (the limit is 50)",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"pushZones\": [ { \"shape\": { \"type\": \"circle\", \"center\": [0, 0], \"radius\": 1 }, \"push\": [60, 0] } ]")));
        assertEquals("courses/x.json: pushZones[0].force: unknown field (known: shape, push)",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"pushZones\": [ { \"shape\": { \"type\": \"circle\", \"center\": [0, 0], \"radius\": 1 }, \"force\": [1, 0] } ]")));
        assertEquals("courses/x.json: magnets[0].strength: must be between -50 and 50 m/s^2, got 51",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"magnets\": [ { \"position\": [0, 0], \"radius\": 1, \"strength\": 51 } ]")));
        assertEquals("courses/x.json: magnets[0].radius: must be > 0, got 0",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"magnets\": [ { \"position\": [0, 0], \"radius\": 0, \"strength\": 1 } ]")));
        assertEquals("courses/x.json: teleports[0].seed: expected a whole number, got 1.5",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"teleports\": [ { \"entry\": { \"type\": \"circle\", \"center\": [0, 0], \"radius\": 0.2 }, \"exits\": [ { \"position\": [1, 1] } ], \"seed\": 1.5 } ]")));
        assertEquals("courses/x.json: teleports[0].exits: a teleport needs at least one exit",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"teleports\": [ { \"entry\": { \"type\": \"circle\", \"center\": [0, 0], \"radius\": 0.2 }, \"exits\": [] } ]")));
        assertEquals("courses/x.json: teleports[0].exits[0].position: (0.1, 0) is inside the entry of teleports[0] (the ball would be sent on at once)",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"teleports\": [ { \"entry\": { \"type\": \"circle\", \"center\": [0, 0], \"radius\": 0.2 }, \"exits\": [ { \"position\": [0.1, 0] } ] } ]")));
        assertEquals("courses/x.json: teleports[0].exits[0].position: (9, 0) is outside the bounds",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"teleports\": [ { \"entry\": { \"type\": \"circle\", \"center\": [0, 0], \"radius\": 0.2 }, \"exits\": [ { \"position\": [9, 0] } ] } ]")));
        assertEquals("courses/x.json: start: (-3, 0) is inside the entry of teleports[0] (the ball would be sent on at once)",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"teleports\": [ { \"entry\": { \"type\": \"circle\", \"center\": [-3, 0], \"radius\": 0.2 }, \"exits\": [ { \"position\": [1, 1] } ] } ]")));
    }

    @Test
    void limitsAreChecked() {
        StringBuilder many = new StringBuilder();
        for (int i = 0; i <= Limits.MOVING_OBSTACLES; i++) {
            many.append(i > 0 ? ", " : "").append("{ \"type\": \"tree\", \"position\": [0, 0], \"radius\": 0.05, \"height\": 0.1, "
                    + "\"motion\": { \"type\": \"slide\", \"path\": [[0, 0, 0], [1, 0, 0]], \"period\": 2 } }");
        }
        assertEquals("courses/x.json: obstacles[64]: too many moving obstacles: 65 with this one (the limit is 64)",
                error(obstacles(many.toString())));
        StringBuilder magnets = new StringBuilder();
        for (int i = 0; i <= Limits.MAGNETS; i++) {
            magnets.append(i > 0 ? ", " : "").append("{ \"position\": [0, 0], \"radius\": 1, \"strength\": 1 }");
        }
        assertEquals("courses/x.json: magnets: too many magnets: 101 (the limit is 100)",
                error(edit("  \"obstacles\": []", "  \"obstacles\": [],\n  \"magnets\": [" + magnets + "]")));
    }

    private static String obstacles(String list) {
        return edit("  \"obstacles\": []", "  \"obstacles\": [" + list + "]");
    }
}
