package minigolf.physics;

import java.nio.file.Path;
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
    private final Terrain terrain;
    private final FrictionField friction;
    private final CollisionScene obstacles;
    private final PlayArea playArea;

    public World(Course course, Terrain terrain) {
        this.course = course;
        this.terrain = terrain;
        this.friction = new FrictionField(course.physics(), course.zones(), course.terrain());
        this.playArea = new PlayArea(course);
        this.obstacles = course.obstacles().isEmpty() ? null
                : CollisionScene.build(course.obstacles(), terrain::height, course.bounds(), course.physics().ballRadius());
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
        return new World(course.withPhysics(course.physics().withModel(model)), terrain);
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

    /** The obstacles as collision geometry, or null when the course has none. */
    public CollisionScene obstacles() {
        return obstacles;
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
