package minigolf.bot;

import minigolf.physics.World;

/**
 * What a bot is given to choose one shot.
 *
 * <p>What a bot may know: the whole course (terrain, friction, hole, bounds and, once the engine
 * has them, obstacles) through {@code simulator.world()}, and the ball's position. It learns
 * nothing else and may simulate only through {@code simulator}.
 *
 * @param simulator    the counting simulator for this game (its budget spans all strokes)
 * @param ballX        where the ball lies
 * @param ballY        where the ball lies
 * @param strokesTaken strokes already played on this hole (penalties included)
 * @param seed         the seed for this stroke: same request, same shot
 * @param noise        the noise the played stroke will get (public knowledge, like the course);
 *                     the simulator itself is always exact
 * @param clock        the course clock (s) when the bot is asked: a shot with no wait is played then
 *                     (where obstacles move; the simulator plays its shots at this clock plus their wait)
 */
public record BotRequest(CountingSimulator simulator, double ballX, double ballY, int strokesTaken, long seed,
                         NoiseModel noise, double clock) {
    public BotRequest {
        if (noise == null) throw new IllegalArgumentException("noise must be given (NoiseModel.NONE for none)");
        if (!(clock >= 0) || !Double.isFinite(clock)) throw new IllegalArgumentException("the clock must be >= 0, got " + clock);
    }

    /** A request at course clock 0. */
    public BotRequest(CountingSimulator simulator, double ballX, double ballY, int strokesTaken, long seed,
                      NoiseModel noise) {
        this(simulator, ballX, ballY, strokesTaken, seed, noise, 0);
    }

    /** The same request at another moment of the course clock. */
    public BotRequest at(double newClock) {
        return new BotRequest(simulator, ballX, ballY, strokesTaken, seed, noise, newClock);
    }

    /** A request without noise. */
    public BotRequest(CountingSimulator simulator, double ballX, double ballY, int strokesTaken, long seed) {
        this(simulator, ballX, ballY, strokesTaken, seed, NoiseModel.NONE);
    }

    public World world() {
        return simulator.world();
    }

    public CancellationToken token() {
        return simulator.token();
    }
}
