package minigolf.course;

import java.util.List;
import minigolf.theme.Themes;

/**
 * A course as read from (and written to) a course file. Plain data: the physics engine builds
 * its own fast representation from it (minigolf.physics.World). {@code world} names the themed
 * world it is set in (minigolf.theme.Themes; scenery, light and materials only, never physics).
 */
public record Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                     Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles, String world) {
    public static final int FORMAT = 1;

    public Course {
        zones = List.copyOf(zones);
        obstacles = List.copyOf(obstacles);
        if (world == null) world = Themes.DEFAULT_ID;
    }

    /** A course in the default world. */
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
        return new Course(format, name, terrain, bounds, newPhysics, start, hole, zones, obstacles, world);
    }

    public Course withObstacles(List<Obstacle> newObstacles) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, newObstacles, world);
    }

    public Course withWorld(String newWorld) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, obstacles, newWorld);
    }
}
