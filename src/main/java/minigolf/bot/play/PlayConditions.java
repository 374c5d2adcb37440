package minigolf.bot.play;

import minigolf.bot.NoiseModel;


/**
 * What makes a game harder than the bare course: noise on the played strokes, and friction the
 * bot must learn ({@link minigolf.bot.friction.FrictionPrior}).
 */
public record PlayConditions(NoiseModel noise, boolean hideFriction) {
    public static final PlayConditions NONE = new PlayConditions(NoiseModel.NONE, false);

    public PlayConditions {
        if (noise == null) throw new IllegalArgumentException("noise must be given (NoiseModel.NONE for none)");
    }
}
