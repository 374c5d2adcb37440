package minigolf.bot.friction;

import minigolf.physics.World;

/** The hidden-friction test courses, for tests in other packages. */
public final class HiddenFrictionTestAccess {
    private HiddenFrictionTestAccess() {
    }

    /** Flat, one friction (mu_k 0.16, mu_s 0.27), a hole 9 m from the start. */
    public static World slowFlat() {
        return HiddenFrictionTest.parse(HiddenFrictionTest.FLAT);
    }
}
