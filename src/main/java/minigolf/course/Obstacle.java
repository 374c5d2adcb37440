package minigolf.course;

import minigolf.mesh.TriangleMesh;

/**
 * Something solid on the course that the ball bounces off (course file field {@code obstacles};
 * see docs/course-format.md for the fields and how each one stands on the terrain).
 */
public sealed interface Obstacle permits Obstacle.Wall, Obstacle.Tree, Obstacle.Box, Obstacle.Model, Obstacle.Bumper,
        Obstacle.Gate, Obstacle.Moving {
    /** Restitution used when a field is not given. */
    double DEFAULT_RESTITUTION = 0.7;
    /** A bumper's restitution when the field is not given. */
    double DEFAULT_BUMPER_RESTITUTION = 1.5;
    /** The most restitution any obstacle may have: above 1 a bounce gives the ball speed (a bumper). */
    double MAX_RESTITUTION = 2.0;

    /**
     * The share of the normal speed the ball keeps when it bounces off this obstacle, in
     * [0, {@link #MAX_RESTITUTION}]; above 1 the bounce adds speed, up to the cap of
     * docs/course-format.md ("Bumpers").
     */
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

    /**
     * A bumper: a short post (a vertical cylinder, like a trunk without a crown) whose top is
     * h(position) + height, with a restitution that may exceed 1, so it kicks the ball away.
     */
    record Bumper(Vec2 position, double radius, double height, double restitution) implements Obstacle {
    }

    /**
     * A one-way gate: a thin fence from {@code from} to {@code to} (its top at the ground plus
     * {@code height}, as a wall's) that the ball crosses freely towards the {@code passTo} side and
     * bounces off from that side. Sides are seen from {@code from} looking towards {@code to}.
     */
    record Gate(Vec2 from, Vec2 to, double height, Side passTo, double restitution) implements Obstacle {
        /** The unit normal of the side the ball may pass to. */
        public Vec2 passNormal() {
            double dx = to.x() - from.x(), dy = to.y() - from.y(), length = Math.hypot(dx, dy);
            double sign = passTo == Side.LEFT ? 1 : -1;
            return new Vec2(-dy / length * sign, dx / length * sign);
        }
    }

    /** A side of a gate, seen from its {@code from} end looking towards {@code to}. */
    enum Side {
        LEFT("left"), RIGHT("right");

        private final String jsonName;

        Side(String jsonName) {
            this.jsonName = jsonName;
        }

        public String jsonName() {
            return jsonName;
        }

        public static Side fromJsonName(String name) {
            for (Side s : values()) if (s.jsonName.equals(name)) return s;
            return null;
        }
    }

    /**
     * A moving (kinematic) obstacle: {@code body} (a wall, tree, box, model or bumper, placed as
     * the file gives it, standing on the terrain there) carried by {@code motion}, a function of the
     * course clock. The course file writes it as the body's object with a {@code motion} field.
     */
    record Moving(Obstacle body, Motion motion) implements Obstacle {
        public Moving {
            if (body instanceof Moving || body instanceof Gate) {
                throw new IllegalArgumentException("a moving obstacle's body is a wall, tree, box, model or bumper");
            }
        }

        public double restitution() {
            return body.restitution();
        }
    }
}
