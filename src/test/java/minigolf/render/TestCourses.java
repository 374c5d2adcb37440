package minigolf.render;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.Shape;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Zone;
import minigolf.terrain.Terrain;

import java.nio.file.Path;
import java.util.List;

/** Courses built in code for the rendering tests. */
final class TestCourses {
    private TestCourses() {
    }

    static final PhysicsSettings PHYSICS = new PhysicsSettings(9.81, 0.08, 0.2, 5.0, PhysicsModel.CLASSIC);

    /** h = 0.4 (0.9 - exp(-(x^2 + y^2) / 8)): a pond around the origin (radius about 0.92 m), rising to the edges. */
    static final Terrain LAKE = new Terrain() {
        @Override
        public double height(double x, double y) {
            return 0.4 * (0.9 - Math.exp(-(x * x + y * y) / 8));
        }

        @Override
        public void sample(double x, double y, double[] out) {
            double e = Math.exp(-(x * x + y * y) / 8);
            out[0] = 0.4 * (0.9 - e);
            out[1] = 0.4 * e * x / 4; // d/dx of -0.4 e = 0.4 e x / 4
            out[2] = 0.4 * e * y / 4;
        }
    };

    static final Terrain FLAT = new Terrain() {
        @Override
        public double height(double x, double y) {
            return 0.1;
        }

        @Override
        public void sample(double x, double y, double[] out) {
            out[0] = 0.1;
            out[1] = 0;
            out[2] = 0;
        }
    };

    static Course lake() {
        return new Course(Course.FORMAT, "Lake", new TerrainSpec.HeightExpression("0.4*(0.9-exp(-(x^2+y^2)/8))"),
                new Bounds(-5, -5, 5, 5), PHYSICS, new Vec2(-3.6, -3.2), new Hole(new Vec2(3.3, 3.0), 0.1, HoleRule.REST, null),
                List.of(new Zone(new Shape.Circle(new Vec2(2.4, -2.6), 0.9), 0.35, 0.5)));
    }

    static Course flat() {
        return new Course(Course.FORMAT, "Flat", new TerrainSpec.HeightExpression("0.1"),
                new Bounds(-5, -5, 5, 5), PHYSICS, new Vec2(-3.6, -3.2), new Hole(new Vec2(3.3, 3.0), 0.1, HoleRule.REST, null),
                List.of());
    }

    /** A hole of the bundled worlds, such as "seaside/07-jetty.json". */
    static minigolf.physics.World worldHole(String hole) throws minigolf.course.CourseException {
        return minigolf.physics.World.load(Path.of(System.getProperty("minigolf.projectDir", "."), "courses", "worlds", hole));
    }

    /** The middle of a course's bounds, 0.3 m up: where views round a hole look. */
    static org.joml.Vector3f middle(Course course) {
        Bounds b = course.bounds();
        return new org.joml.Vector3f((float) (b.minX() + b.maxX()) / 2, (float) (b.minY() + b.maxY()) / 2, 0.3f);
    }

    static Path screenshotDir() {
        return Path.of(System.getProperty("minigolf.projectDir", "."), "build", "screenshots");
    }
}
