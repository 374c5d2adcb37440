package minigolf.physics;

import java.nio.file.Path;
import java.util.List;
import minigolf.collision.CollisionScene;
import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseLoader;
import minigolf.course.Hole;
import minigolf.course.PhysicsModel;
import minigolf.course.PhysicsSettings;
import minigolf.course.TerrainSpec;
import minigolf.terrain.Terrain;
import minigolf.terrain.Terrains;

/**
 * A course made ready for simulation: the compiled terrain, the friction field, the bounds and
 * the hole. Immutable and shared by every stroke (and every bot thread) on the course.
 */
public final class World {
    private final Course course;
    private final List<Hole> holes;
    private final Terrain terrain;
    private final FrictionField friction;
    private final CollisionScene obstacles;
    private final PlayArea playArea;
    /** Push zones and magnets; null when the course has none. */
    private final ForceField forces;
    /** One-way gates and moving obstacles; null when the course has none. */
    private final minigolf.collision.Gates gates;
    private final minigolf.collision.MovingObstacles moving;
    /** The teleports; null when the course has none. */
    private final TeleportField teleports;
    /** Every breakable brick as collision geometry (its obstacle index: the brick's); null when the course has none. */
    private final CollisionScene bricks;
    /** The bricks left standing when a stroke on this world starts. */
    private final CourseState state;

    public World(Course course, Terrain terrain) {
        this.course = course;
        this.holes = course.holes();
        this.terrain = terrain;
        this.friction = new FrictionField(course.physics(), course.zones(), course.terrain());
        this.playArea = new PlayArea(course);
        ForceField field = new ForceField(course.pushZones(), course.magnets());
        this.forces = field.isEmpty() ? null : field;
        double radius = course.physics().ballRadius();
        this.gates = minigolf.collision.Gates.build(course.obstacles(), terrain::height, radius);
        this.moving = minigolf.collision.MovingObstacles.build(course.obstacles(), terrain::height, course.bounds(), radius);
        this.teleports = course.teleports().isEmpty() ? null : new TeleportField(course.teleports());
        this.obstacles = course.obstacles().stream().noneMatch(minigolf.collision.ObstacleGeometry::isStillSolid) ? null
                : CollisionScene.build(course.obstacles(), terrain::height, course.bounds(), course.physics().ballRadius());
        this.bricks = course.bricks().isEmpty() ? null : CollisionScene.build(
                course.bricks().stream().map(minigolf.course.Brick::box).map(b -> (minigolf.course.Obstacle) b).toList(),
                terrain::height, course.bounds(), radius);
        this.state = CourseState.initial(course);
    }

    /** The same world in another state: everything shared but the bricks left standing. */
    private World(World base, CourseState state) {
        this.course = base.course;
        this.holes = base.holes;
        this.terrain = base.terrain;
        this.friction = base.friction;
        this.playArea = base.playArea;
        this.forces = base.forces;
        this.gates = base.gates;
        this.moving = base.moving;
        this.teleports = base.teleports;
        this.obstacles = base.obstacles;
        this.bricks = base.bricks;
        this.state = state;
    }

    /**
     * This course with the bricks as {@code newState} leaves them: strokes on it start from that state,
     * and bots plan on it. The same world when the state is this one's.
     */
    public World withState(CourseState newState) {
        if (newState.equals(state)) return this;
        if (newState.bricks() != course.bricks().size()) {
            throw new IllegalArgumentException("the course has " + course.bricks().size() + " bricks, the state "
                    + newState.bricks());
        }
        return new World(this, newState);
    }

    /** The bricks left standing when a stroke on this world starts ({@link CourseState#initial} for a loaded course). */
    public CourseState state() {
        return state;
    }

    /** Every brick as collision geometry, standing or not (the stroke skips broken ones); null without bricks. */
    public CollisionScene bricks() {
        return bricks;
    }

    /** Builds the terrain from the course's own terrain description. */
    public static World of(Course course) {
        return new World(course, Terrains.create(course.terrain()));
    }

    /** Loads and validates a course file (start and hole on dry land included) and compiles its terrain. */
    public static World load(Path file) throws CourseException {
        TerrainBuilder builder = new TerrainBuilder();
        Course course = CourseLoader.load(file, builder::build);
        return new World(course, builder.terrainFor(course.terrain()));
    }

    /** As {@link #load(Path)} for course JSON from elsewhere (the classpath, a save game). */
    public static World parse(String json, String sourceName) throws CourseException {
        TerrainBuilder builder = new TerrainBuilder();
        Course course = CourseLoader.parse(json, sourceName, builder::build);
        return new World(course, builder.terrainFor(course.terrain()));
    }

    /** The same course under another physics model. */
    public World withModel(PhysicsModel model) {
        return new World(course.withPhysics(course.physics().withModel(model)), terrain).withState(state);
    }

    public Course course() {
        return course;
    }

    public Terrain terrain() {
        return terrain;
    }

    public FrictionField friction() {
        return friction;
    }

    /** The still obstacles (not gates or moving ones) as collision geometry, or null when the course has none. */
    public CollisionScene obstacles() {
        return obstacles;
    }

    /** The one-way gates, or null when the course has none. */
    public minigolf.collision.Gates gates() {
        return gates;
    }

    /** The teleports, or null when the course has none. */
    public TeleportField teleports() {
        return teleports;
    }

    /** The moving obstacles, or null when none moves. */
    public minigolf.collision.MovingObstacles moving() {
        return moving;
    }

    /** The push zones and magnets, or null when the course has none. */
    public ForceField forces() {
        return forces;
    }

    /** The bounds less the deleted terrain cells: where the ball is in play. */
    public PlayArea playArea() {
        return playArea;
    }

    public Bounds bounds() {
        return course.bounds();
    }

    public Hole hole() {
        return course.hole();
    }

    /** Every hole of the course, the main one first (any of them ends the stroke). */
    public List<Hole> holes() {
        return holes;
    }

    /** The hole whose centre is nearest (x, y): the one a holed ball dropped into. */
    public Hole nearestHole(double x, double y) {
        Hole best = holes.get(0);
        for (Hole h : holes) {
            if (Math.hypot(x - h.position().x(), y - h.position().y())
                    < Math.hypot(x - best.position().x(), y - best.position().y())) best = h;
        }
        return best;
    }

    public PhysicsSettings physics() {
        return course.physics();
    }

    /** Compiles the terrain once: the loader's water check and the world share it. */
    private static final class TerrainBuilder {
        private TerrainSpec spec;
        private Terrain terrain;

        minigolf.course.HeightProbe build(TerrainSpec requested) {
            spec = requested;
            terrain = Terrains.create(requested);
            return terrain::height;
        }

        Terrain terrainFor(TerrainSpec loaded) {
            return loaded == spec && terrain != null ? terrain : Terrains.create(loaded);
        }
    }
}
