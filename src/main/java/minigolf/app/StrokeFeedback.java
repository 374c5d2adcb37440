package minigolf.app;

import minigolf.physics.StrokeEvent;
import minigolf.physics.TrajectoryListener;

/**
 * What a stroke sounds and looks like: the hit itself, then its events (hits, landings, water, the
 * cup, applause for a hole in one) as sounds, and as effects a splash where the ball meets the water,
 * the ball dropping into the cup and confetti from the cup when it drops (more for a hole in one).
 */
final class StrokeFeedback {
    private StrokeFeedback() {
    }

    /** The sounds (none where {@code sounds} is null) and the effects' bursts into {@code effects} (none where null). */
    static TrajectoryListener listener(Sounds sounds, boolean firstStroke, minigolf.render.Particles effects,
                                       minigolf.physics.World world) {
        return listener(sounds, firstStroke, effects, world, null, null);
    }

    /** As above, and the ball's drop into the cup ({@code cupDrop}, in the player's colour) when it is holed. */
    static TrajectoryListener listener(Sounds sounds, boolean firstStroke, minigolf.render.Particles effects,
                                       minigolf.physics.World world, minigolf.render.CupDrop cupDrop, float[] ballColour) {
        return listener(sounds, firstStroke, e -> {
            if (cupDrop != null && e.type() == StrokeEvent.Type.HOLED) {
                var cupHole = world.nearestHole(e.x(), e.y()).position();
                double hx = cupHole.x(), hy = cupHole.y();
                cupDrop.start(e.x(), e.y(), hx, hy, world.terrain().height(hx, hy),
                        minigolf.render.ObjectsPass.visualBallRadius(), ballColour);
            }
            if (effects == null) return;
            long seed = Double.doubleToLongBits(e.x()) * 31 + Double.doubleToLongBits(e.y());
            if (e.type() == StrokeEvent.Type.WATER) {
                effects.burst(minigolf.render.Particles.Kind.SPLASH, e.x(), e.y(), 0, seed); // the water's surface is h = 0
            } else if (e.type() == StrokeEvent.Type.HOLED) {
                var cupHole = world.nearestHole(e.x(), e.y()).position();
                double hx = cupHole.x(), hy = cupHole.y();
                effects.burst(firstStroke ? minigolf.render.Particles.Kind.ACE_CONFETTI : minigolf.render.Particles.Kind.CONFETTI,
                        hx, hy, world.terrain().height(hx, hy), seed);
            }
        });
    }

    /** The club meeting the ball: louder and brighter the faster it is hit (the whole velocity, chips included). */
    static void hit(Sounds sounds, double speed, double maxSpeed) {
        if (sounds != null) sounds.play(SoundSynth.Sound.PUTT, 0.25 + 0.75 * speed / maxSpeed, 0.9 + 0.2 * speed / maxSpeed);
    }

    /** A listener that plays each event of the stroke (nothing where {@code sounds} is null), then tells {@code more}. */
    static TrajectoryListener listener(Sounds sounds, boolean firstStroke, java.util.function.Consumer<StrokeEvent> more) {
        return new TrajectoryListener() {
            @Override
            public void onStep(double t, double x, double y, double vx, double vy) {
            }

            @Override
            public void onEvent(StrokeEvent e) {
                if (more != null) more.accept(e);
                if (sounds == null) return;
                switch (e.type()) {
                    case COLLISION -> sounds.play(SoundSynth.Sound.KNOCK, e.speedBefore() / 3, 0.9 + 0.1 * Math.min(2, e.speedBefore()));
                    case LAND, BOUNCE -> sounds.play(SoundSynth.Sound.THUD, e.speedBefore() / 3, 1);
                    case WATER -> sounds.play(SoundSynth.Sound.SPLASH, 0.8, 1);
                    case HOLED -> {
                        sounds.play(SoundSynth.Sound.CUP, 0.9, 1);
                        if (firstStroke) sounds.play(SoundSynth.Sound.APPLAUSE, 0.8, 1);
                    }
                    default -> {
                    }
                }
            }
        };
    }
}
