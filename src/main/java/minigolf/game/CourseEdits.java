package minigolf.game;

import minigolf.course.Course;
import minigolf.course.CourseException;
import minigolf.course.CourseWriter;
import minigolf.course.Hole;
import minigolf.course.PhysicsSettings;
import minigolf.course.Vec2;
import minigolf.physics.World;

/**
 * Changes the settings screen makes to the course being played: its physical constants, the start
 * and the hole. The edited course goes through the course loader's checks again (start and hole in
 * bounds and on dry land, constants in range), so a bad edit gives the loader's one-line message.
 */
public record CourseEdits(double gravity, double kineticFriction, double staticFriction, double maxSpeed,
                          double startX, double startY, double holeX, double holeY, double holeRadius) {

    public static CourseEdits of(Course c) {
        PhysicsSettings p = c.physics();
        return new CourseEdits(p.gravity(), p.kineticFriction(), p.staticFriction(), p.maxSpeed(),
                c.start().x(), c.start().y(), c.hole().position().x(), c.hole().position().y(), c.hole().radius());
    }

    /** The course with these values, as a new world; the original is untouched. */
    public World applyTo(World world) throws CourseException {
        Course c = world.course();
        PhysicsSettings p = new PhysicsSettings(gravity, kineticFriction, staticFriction, maxSpeed, c.physics().model());
        Hole h = new Hole(new Vec2(holeX, holeY), holeRadius, c.hole().rule(), c.hole().captureSpeed());
        Course edited = new Course(c.format(), c.name(), c.terrain(), c.bounds(), p, new Vec2(startX, startY), h, c.zones(),
                java.util.List.of(), c.pushZones(), c.magnets(), c.teleports());
        String json;
        try {
            json = CourseWriter.toJson(edited);
        } catch (IllegalArgumentException e) {
            throw new CourseException("settings", null, e.getMessage(), e);
        }
        return World.parse(json, "settings");
    }
}
