package minigolf.course;

import minigolf.mesh.TriangleMesh;

/**
 * Something solid on the course that the ball bounces off (course file field {@code obstacles};
 * see docs/course-format.md for the fields and how each one stands on the terrain).
 */
public sealed interface Obstacle permits Obstacle.Wall, Obstacle.Tree, Obstacle.Box, Obstacle.Model {
    /** Restitution used when a field is not given. */
    double DEFAULT_RESTITUTION = 0.7;

    /** The share of the normal speed the ball keeps when it bounces off this obstacle, in [0, 1]. */
    double restitution();

    /**
     * A straight wall from {@code from} to {@code to}: a rectangular slab {@code thickness} wide
     * (0 = an infinitely thin fence). Its top runs straight from h(from) + height to h(to) + height;
     * below the top it is solid down into the ground.
     */
    record Wall(Vec2 from, Vec2 to, double thickness, double height, double restitution) implements Obstacle {
    }

    /** A tree trunk: a vertical cylinder whose top is h(position) + height. The crown is decoration. */
    record Tree(Vec2 position, double radius, double height, double restitution) implements Obstacle {
    }

    /**
     * A box between min and max (absolute heights), turned by rotationDeg (counter-clockwise seen
     * from above) about the vertical axis through its centre.
     */
    record Box(Vec3 min, Vec3 max, double rotationDeg, double restitution) implements Obstacle {
    }

    /**
     * A Wavefront .obj mesh: a model point p is placed at position + Rz(rotationDeg) (scale p), so
     * position.z is an absolute height. {@code file} is kept as written in the course (for saving);
     * {@code mesh} is what was loaded from it.
     */
    record Model(String file, Vec3 position, double rotationDeg, double scale, double restitution,
                 TriangleMesh mesh) implements Obstacle {
    }
}
