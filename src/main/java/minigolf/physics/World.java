package minigolf.physics;

import minigolf.course.Bounds;
import minigolf.course.Course;
import minigolf.course.Hole;
import minigolf.course.PhysicsSettings;
import minigolf.terrain.Terrain;

/**
 * A course made ready for simulation: the compiled terrain, the friction field, the bounds and
 * the hole. Immutable and shared by every stroke (and every bot thread) on the course.
 */
public final class World {
    private final Course course;
    private final Terrain terrain;
    private final FrictionField friction;

    public World(Course course, Terrain terrain) {
        this.course = course;
        this.terrain = terrain;
        this.friction = new FrictionField(course.physics(), course.zones(), course.terrain());
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

    public Bounds bounds() {
        return course.bounds();
    }

    public Hole hole() {
        return course.hole();
    }

    public PhysicsSettings physics() {
        return course.physics();
    }

    /** True where a ball would end its stroke: in water (h < 0) or outside the bounds. */
    public boolean isHazard(double x, double y) {
        return !course.bounds().contains(x, y) || terrain.height(x, y) < 0;
    }
}
