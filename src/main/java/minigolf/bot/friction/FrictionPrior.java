package minigolf.bot.friction;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import minigolf.course.Course;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.course.Zone;
import minigolf.physics.World;

/**
 * The course a bot sees when friction is hidden: every friction value (the default, each zone's,
 * the grid's) replaced by the prior μk {@value #KINETIC}, μs {@value #STATIC} (a typical green,
 * docs/bots.md), times scales the bot estimates (one for the default, one per zone). Zone shapes stay visible (a player sees where
 * the sand is, not how slow it is); the friction grids are dropped, so the default applies there.
 * The world built here shares only the terrain's heights with the true one.
 */
public final class FrictionPrior {
    public static final double KINETIC = 0.1;
    public static final double STATIC = 0.2;

    private FrictionPrior() {
    }

    /** The true world with every friction value replaced by the prior times {@code scale}. */
    public static World scaled(World truth, double scale) {
        double[] scales = new double[regions(truth)];
        Arrays.fill(scales, scale);
        return scaled(truth, scales);
    }

    /** Friction regions a bot can tell apart: the course's default (index 0), then each zone in order. */
    public static int regions(World truth) {
        return 1 + truth.course().zones().size();
    }

    /**
     * The true world with the default friction replaced by the prior times {@code scales[0]} and
     * zone i's by the prior times {@code scales[i + 1]}.
     */
    public static World scaled(World truth, double[] scales) {
        if (scales.length != regions(truth)) {
            throw new IllegalArgumentException("need " + regions(truth) + " scales, got " + scales.length);
        }
        for (double scale : scales) {
            if (!(scale > 0) || !Double.isFinite(scale)) throw new IllegalArgumentException("scale must be > 0, got " + scale);
        }
        Course c = truth.course();
        PhysicsSettings p = c.physics();
        PhysicsSettings physics = new PhysicsSettings(p.gravity(), KINETIC * scales[0], STATIC * scales[0], p.maxSpeed(),
                p.model(), p.ballRadius(), p.ballMass(), p.dragCoefficient(), p.airDensity(), p.groundRestitution(),
                p.puttsOnly());
        List<Zone> zones = new ArrayList<>();
        for (int i = 0; i < c.zones().size(); i++) {
            Zone z = c.zones().get(i);
            zones.add(new Zone(z.shape(), KINETIC * scales[i + 1], STATIC * scales[i + 1]));
        }
        TerrainSpec terrain = c.terrain();
        if (terrain instanceof TerrainSpec.HeightGrid g) {
            terrain = new TerrainSpec.HeightGrid(g.origin(), g.spacing(), g.heights(), null, null, g.deleted());
        }
        Course hidden = new Course(c.format(), c.name(), terrain, c.bounds(), physics, c.start(), c.hole(), zones,
                c.obstacles(), c.pushZones(), c.magnets(), c.teleports(), c.world(), c.extraHoles(), c.bricks());
        return new World(hidden, truth.terrain());
    }
}
