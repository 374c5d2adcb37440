package minigolf.course;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import minigolf.theme.Themes;

/**
 * A course as read from (and written to) a course file. Plain data: the physics engine builds
 * its own fast representation from it (minigolf.physics.World). {@code world} names the themed
 * world it is set in (minigolf.theme.Themes; scenery, light and materials only, never physics).
 * {@code extraHoles} are further holes (the classic tracks have up to ten): the ball dropping into
 * any hole ends the stroke and the course, as in the original; {@code hole} is the one the flag,
 * the camera and the bots' first aim use.
 */
public record Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                     Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles, List<PushZone> pushZones,
                     List<Magnet> magnets, List<Teleport> teleports, String world, List<Hole> extraHoles,
                     List<Brick> bricks) {
    public static final int FORMAT = 1;

    public Course {
        zones = List.copyOf(zones);
        obstacles = List.copyOf(obstacles);
        pushZones = List.copyOf(pushZones);
        magnets = List.copyOf(magnets);
        teleports = List.copyOf(teleports);
        extraHoles = extraHoles == null ? List.of() : List.copyOf(extraHoles);
        bricks = bricks == null ? List.of() : List.copyOf(bricks);
        if (world == null) world = Themes.DEFAULT_ID;
    }

    /** A course without breakable bricks. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles, List<PushZone> pushZones,
                  List<Magnet> magnets, List<Teleport> teleports, String world, List<Hole> extraHoles) {
        this(format, name, terrain, bounds, physics, start, hole, zones, obstacles, pushZones, magnets, teleports, world,
                extraHoles, List.of());
    }

    /** A course with one hole. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles, List<PushZone> pushZones,
                  List<Magnet> magnets, List<Teleport> teleports, String world) {
        this(format, name, terrain, bounds, physics, start, hole, zones, obstacles, pushZones, magnets, teleports, world,
                List.of());
    }

    /** A course in the default world. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles, List<PushZone> pushZones,
                  List<Magnet> magnets, List<Teleport> teleports) {
        this(format, name, terrain, bounds, physics, start, hole, zones, obstacles, pushZones, magnets, teleports,
                Themes.DEFAULT_ID);
    }

    /** A course without push zones, magnets and teleports. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles, String world) {
        this(format, name, terrain, bounds, physics, start, hole, zones, obstacles, List.of(), List.of(), List.of(), world);
    }

    /** A course in the default world without push zones, magnets and teleports. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles) {
        this(format, name, terrain, bounds, physics, start, hole, zones, obstacles, Themes.DEFAULT_ID);
    }

    /** A course without obstacles. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones) {
        this(format, name, terrain, bounds, physics, start, hole, zones, List.of());
    }

    public Course withPhysics(PhysicsSettings newPhysics) {
        return new Course(format, name, terrain, bounds, newPhysics, start, hole, zones, obstacles, pushZones, magnets,
                teleports, world, extraHoles, bricks);
    }

    public Course withObstacles(List<Obstacle> newObstacles) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, newObstacles, pushZones, magnets,
                teleports, world, extraHoles, bricks);
    }

    public Course withWorld(String newWorld) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, obstacles, pushZones, magnets,
                teleports, newWorld, extraHoles, bricks);
    }

    /** The same course with other push zones, magnets and teleports. */
    public Course withElements(List<PushZone> newPushZones, List<Magnet> newMagnets, List<Teleport> newTeleports) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, obstacles, newPushZones, newMagnets,
                newTeleports, world, extraHoles, bricks);
    }

    /** The same course with these holes: {@code main} where the flag stands, {@code extra} the others. */
    public Course withHoles(Hole main, List<Hole> extra) {
        return new Course(format, name, terrain, bounds, physics, start, main, zones, obstacles, pushZones, magnets,
                teleports, world, extra, bricks);
    }

    /** The same course with these breakable bricks (as the hole starts). */
    public Course withBricks(List<Brick> newBricks) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, obstacles, pushZones, magnets,
                teleports, world, extraHoles, newBricks);
    }

    /**
     * The obstacles to draw: the course's own, then the breakable bricks that {@code standing} says
     * still stand (by index), each as its box.
     */
    public List<Obstacle> obstaclesWithBricks(java.util.function.IntPredicate standing) {
        if (bricks.isEmpty()) return obstacles;
        List<Obstacle> all = new ArrayList<>(obstacles);
        for (int i = 0; i < bricks.size(); i++) if (standing.test(i)) all.add(bricks.get(i).box());
        return Collections.unmodifiableList(all);
    }

    /** Every hole: the main one first, then the extra holes in order. */
    public List<Hole> holes() {
        List<Hole> all = new ArrayList<>(1 + extraHoles.size());
        all.add(hole);
        all.addAll(extraHoles);
        return Collections.unmodifiableList(all);
    }

    /** Whether any obstacle moves (its motion is a function of the course clock). */
    public boolean hasMovingObstacles() {
        for (Obstacle o : obstacles) if (o instanceof Obstacle.Moving) return true;
        return false;
    }
}
