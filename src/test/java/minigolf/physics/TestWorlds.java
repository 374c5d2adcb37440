package minigolf.physics;

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
import minigolf.terrain.Terrain;

/** Worlds with hand-written terrains whose motion has closed forms. */
final class TestWorlds {
    static final double G = 9.81;

    private TestWorlds() {
    }

    /** h = a*x + b*y + c. */
    static Terrain plane(double a, double b, double c) {
        return new Terrain() {
            public double height(double x, double y) {
                return a * x + b * y + c;
            }

            public void sample(double x, double y, double[] out) {
                out[0] = a * x + b * y + c;
                out[1] = a;
                out[2] = b;
            }
        };
    }

    /** h = 0.4 + 0.1 sin(x) cos(0.7 y): smooth, dry everywhere. */
    static Terrain sine() {
        return new Terrain() {
            public double height(double x, double y) {
                return 0.4 + 0.1 * Math.sin(x) * Math.cos(0.7 * y);
            }

            public void sample(double x, double y, double[] out) {
                out[0] = height(x, y);
                out[1] = 0.1 * Math.cos(x) * Math.cos(0.7 * y);
                out[2] = -0.07 * Math.sin(x) * Math.sin(0.7 * y);
            }
        };
    }

    /** The manual's lake course: h = 0.4 (0.9 - exp(-(x^2+y^2)/8)). */
    static Terrain lake() {
        return new Terrain() {
            public double height(double x, double y) {
                return 0.4 * (0.9 - Math.exp(-(x * x + y * y) / 8));
            }

            public void sample(double x, double y, double[] out) {
                double e = Math.exp(-(x * x + y * y) / 8);
                out[0] = 0.4 * (0.9 - e);
                out[1] = 0.1 * x * e;
                out[2] = 0.1 * y * e;
            }
        };
    }

    /** The terrain, smooth (long steps allowed), calling onHeight for every height asked (full samples are not counted). */
    static Terrain countingHeights(Terrain terrain, Runnable onHeight) {
        return new Terrain() {
            public double height(double x, double y) {
                onHeight.run();
                return terrain.height(x, y);
            }

            public void sample(double x, double y, double[] out) {
                terrain.sample(x, y, out);
            }

            public boolean isSmooth() {
                return true;
            }
        };
    }

    static World world(Terrain terrain, double muK, double muS, double halfSize, PhysicsModel model,
                       Hole hole, List<Zone> zones) {
        Course course = new Course(1, "test", new TerrainSpec.HeightExpression("test"),
                new Bounds(-halfSize, -halfSize, halfSize, halfSize),
                new PhysicsSettings(G, muK, muS, 5.0, model), new Vec2(0, 0), hole, zones);
        return new World(course, terrain);
    }

    static World world(Terrain terrain, double muK, double muS, double halfSize) {
        return world(terrain, muK, muS, halfSize, PhysicsModel.CLASSIC, farHole(halfSize), List.of());
    }

    /** A hole in a corner, out of the way of the shots under test. */
    static Hole farHole(double halfSize) {
        return new Hole(new Vec2(halfSize - 0.5, halfSize - 0.5), 0.1, HoleRule.REST, null);
    }

    static Simulator rk4(World world) {
        return new Simulator(world, SimulationSettings.DEFAULT);
    }

    /** When a ball braking at a from speed v has gone the distance d (the closed form). */
    static double timeToCover(double d, double v, double a) {
        return (v - Math.sqrt(v * v - 2 * a * d)) / a;
    }
}
