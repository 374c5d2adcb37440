package minigolf.course;

import java.util.List;

/**
 * A course as read from (and written to) a course file. Plain data: the physics engine builds
 * its own fast representation from it (minigolf.physics.World).
 */
public record Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                     Vec2 start, Hole hole, List<Zone> zones, List<Obstacle> obstacles) {
    public static final int FORMAT = 1;

    public Course {
        zones = List.copyOf(zones);
        obstacles = List.copyOf(obstacles);
    }

    /** A course without obstacles. */
    public Course(int format, String name, TerrainSpec terrain, Bounds bounds, PhysicsSettings physics,
                  Vec2 start, Hole hole, List<Zone> zones) {
        this(format, name, terrain, bounds, physics, start, hole, zones, List.of());
    }

    public Course withPhysics(PhysicsSettings newPhysics) {
        return new Course(format, name, terrain, bounds, newPhysics, start, hole, zones, obstacles);
    }

    public Course withObstacles(List<Obstacle> newObstacles) {
        return new Course(format, name, terrain, bounds, physics, start, hole, zones, newObstacles);
    }
}
