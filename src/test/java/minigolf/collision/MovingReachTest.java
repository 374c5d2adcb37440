package minigolf.collision;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import minigolf.course.Bounds;
import minigolf.course.Motion;
import minigolf.course.Obstacle;
import minigolf.course.Vec3;
import org.junit.jupiter.api.Test;

/**
 * The reach of a turning obstacle (MovingObstacles): beyond its box of reach, a blade turning
 * about an axis never comes farther from the axis than its farthest corner, so a ball's centre
 * farther than that plus a ball radius is never touched, though it may lie inside the box.
 */
class MovingReachTest {
    static final double R = 0.02135;
    // One blade of courses/windmill-push.json: 0.04 x 0.2 x 0.51 m, turning about x at height 0.62.
    static final Vec3 MIN = new Vec3(-0.28, -0.1, 0.62), MAX = new Vec3(-0.24, 0.1, 1.13);
    static final Vec3 PIVOT = new Vec3(-0.26, 0, 0.62);
    static final MovingObstacles BLADE = MovingObstacles.build(
            List.of(new Obstacle.Moving(new Obstacle.Box(MIN, MAX, 0, 0.5), new Motion.Rotate(PIVOT, new Vec3(1, 0, 0), 4, 0))),
            (x, y) -> 0.1, new Bounds(-4, -1, 4, 1), R);

    @Test
    void aBallBesideTheDoorIsInsideTheBoxOfReachButNeverTouched() {
        // Resting on the ground (centre 0.1 + R high) 0.4 m beside the axis: 0.63 m from it, and
        // the blade's corners reach sqrt(0.51^2 + 0.1^2) = 0.520 m (+ R = 0.541).
        assertTrue(BLADE.anyNear(-0.26, 0.4, -0.26, 0.4));
        assertFalse(BLADE.mayReach(-0.26, 0.4, 0.1 + R, -0.26, 0.4, 0.1 + R));
        assertEquals(Double.POSITIVE_INFINITY, BLADE.sweeper().stillContact(-0.26, 0.4, 0.1 + R, 0, new Hit()));
        // In the door (under the axis: 0.499 m from it) the blade comes down to it.
        assertTrue(BLADE.mayReach(-0.26, 0, 0.1 + R, -0.26, 0, 0.1 + R));
        double touch = BLADE.sweeper().stillContact(-0.26, 0, 0.1 + R, 0, new Hit());
        assertTrue(touch < 4, "touched within a period, at " + touch);
        // Where |y| < sqrt(0.541^2 - 0.499^2) = 0.209 it may: a segment from beside the door into
        // it; a short one beside the door stays out of reach (its nearer end 0.639 m from the axis,
        // less half its length, 0.025 m).
        assertTrue(BLADE.mayReach(-0.26, 0.4, 0.1 + R, -0.26, 0.15, 0.1 + R));
        assertFalse(BLADE.mayReach(-0.26, 0.45, 0.1 + R, -0.26, 0.4, 0.1 + R));
    }

    @Test
    void noPoseOfTheBladeTouchesABallWhereItIsOutOfReach() {
        // 4,000 seeded centres inside the box of reach; each one called out of reach is farther
        // than a ball radius from the posed box at every one of 3,600 angles (its exact distance).
        SplittableRandom random = new SplittableRandom(24);
        int outside = 0, closest = 0;
        double least = Double.POSITIVE_INFINITY;
        for (int i = 0; i < 4000; i++) {
            double x = -0.31 + 0.1 * random.nextDouble(), y = -0.6 + 1.2 * random.nextDouble(), z = 1.3 * random.nextDouble();
            if (BLADE.mayReach(x, y, z, x, y, z)) continue;
            outside++;
            for (int k = 0; k < 3600; k++) {
                double d = distanceToBlade(x, y, z, 2 * Math.PI * k / 3600);
                least = Math.min(least, d);
            }
        }
        assertTrue(outside > 1000, outside + " centres out of reach");
        assertTrue(least > R, "a posed blade came within " + least + " m of a centre called out of reach");
        // And the bound is tight: the nearest of them came within 2 cm of touching.
        assertTrue(least < R + 0.02, "nearest " + least);
    }

    /** The distance from (x, y, z) to the blade turned by angle a about its axis (the box in its own frame). */
    static double distanceToBlade(double x, double y, double z, double a) {
        // Into the blade's frame: turn back by a about x through the pivot.
        double dy = y - PIVOT.y(), dz = z - PIVOT.z();
        double ly = Math.cos(a) * dy + Math.sin(a) * dz + PIVOT.y(), lz = -Math.sin(a) * dy + Math.cos(a) * dz + PIVOT.z();
        double ex = Math.max(0, Math.max(MIN.x() - x, x - MAX.x()));
        double ey = Math.max(0, Math.max(MIN.y() - ly, ly - MAX.y()));
        double ez = Math.max(0, Math.max(MIN.z() - lz, lz - MAX.z()));
        return Math.sqrt(ex * ex + ey * ey + ez * ez);
    }
}
