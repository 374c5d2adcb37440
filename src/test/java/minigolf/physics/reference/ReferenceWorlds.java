package minigolf.physics.reference;

import java.util.List;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.HoleRule;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Vec2;
import minigolf.course.Zone;
import minigolf.physics.World;
import minigolf.terrain.Terrain;

/** Hand-written terrains with closed-form motions, for the reference's own tests. */
final class ReferenceWorlds {
    static final double G = 9.81;

    private ReferenceWorlds() {
    }

    /** h = s·x + c. */
    static Terrain plane(double s, double c) {
        return new Terrain() {
            public double height(double x, double y) {
                return s * x + c;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = s * x + c;
                out[1] = s;
                out[2] = 0;
            }
        };
    }

    /** h = s·|x| + c: a V-shaped valley along the y axis, a crease at x = 0. */
    static Terrain valley(double s, double c) {
        return new Terrain() {
            public double height(double x, double y) {
                return s * Math.abs(x) + c;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = s * Math.abs(x) + c;
                out[1] = x >= 0 ? s : -s;
                out[2] = 0;
            }
        };
    }

    static World world(Terrain terrain, double muK, double muS, double halfSize, PhysicsModel model, List<Zone> zones) {
        Course course = new Course(1, "test", new TerrainSpec.HeightExpression("test"),
                new Bounds(-halfSize, -halfSize, halfSize, halfSize),
                new PhysicsSettings(G, muK, muS, 5.0, model), new Vec2(0, 0),
                new Hole(new Vec2(halfSize - 0.5, halfSize - 0.5), 0.1, HoleRule.REST, null), zones);
        return new World(course, terrain);
    }

    /** A classic-model world with the flight settings given (drag coefficient, ground restitution or null for Penner's). */
    static World flightWorld(Terrain terrain, double muK, double halfSize, double drag, Double restitution) {
        PhysicsSettings physics = new PhysicsSettings(G, muK, 0.2, 5.0, PhysicsModel.CLASSIC,
                PhysicsSettings.DEFAULT_BALL_RADIUS, PhysicsSettings.DEFAULT_BALL_MASS, drag,
                PhysicsSettings.DEFAULT_AIR_DENSITY, restitution);
        Course course = new Course(1, "test", new TerrainSpec.HeightExpression("test"),
                new Bounds(-halfSize, -halfSize, halfSize, halfSize), physics, new Vec2(0, 0),
                new Hole(new Vec2(halfSize - 0.5, halfSize - 0.5), 0.1, HoleRule.REST, null), List.of());
        return new World(course, terrain);
    }

    /** h = c − a·x²/2: a crest along the y axis, curvature −a across it. */
    static Terrain crest(double a, double c) {
        return new Terrain() {
            public double height(double x, double y) {
                return c - 0.5 * a * x * x;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = c - 0.5 * a * x * x;
                out[1] = -a * x;
                out[2] = 0;
            }
        };
    }

    static World world(Terrain terrain, double muK, double muS, double halfSize) {
        return world(terrain, muK, muS, halfSize, PhysicsModel.CLASSIC, List.of());
    }
}
