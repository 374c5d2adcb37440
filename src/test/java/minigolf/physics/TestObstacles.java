package minigolf.physics;

import java.util.List;
import minigolf.course.Obstacle;
import minigolf.course.PhysicsSettings;

/** Worlds of TestWorlds with obstacles and flight settings. */
final class TestObstacles {
    private TestObstacles() {
    }

    static World with(World world, List<Obstacle> obstacles) {
        return new World(world.course().withObstacles(obstacles), world.terrain());
    }

    static World withFlight(World world, double dragCoefficient, Double groundRestitution) {
        PhysicsSettings p = world.physics().withFlight(dragCoefficient, groundRestitution);
        return new World(world.course().withPhysics(p), world.terrain());
    }

    /** Steps a stroke until it has recorded at least {@code count} events of the type (or ends). */
    static Stroke stepUntil(Stroke stroke, List<StrokeEvent> events, StrokeEvent.Type type, int count) {
        while (!stroke.isFinished() && events.stream().filter(e -> e.type() == type).count() < count) stroke.step();
        return stroke;
    }

    /** A listener that only collects events. */
    static TrajectoryListener collect(List<StrokeEvent> into) {
        return new TrajectoryListener() {
            public void onStep(double t, double x, double y, double vx, double vy) {
            }

            public void onEvent(StrokeEvent event) {
                into.add(event);
            }
        };
    }
}
