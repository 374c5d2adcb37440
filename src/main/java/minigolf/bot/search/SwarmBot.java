package minigolf.bot.search;

import java.util.SplittableRandom;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;

/** {@code swarm}: {@link SwarmSolver} at the hole, particles spread over the hole's half-plane. */
public final class SwarmBot extends SearchBot {
    private final SwarmSolver solver;

    public SwarmBot() {
        this(new SwarmSolver());
    }

    public SwarmBot(SwarmSolver solver) {
        this.solver = solver;
    }

    @Override
    public String name() {
        return "swarm";
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        sim.phase("swarm");
        Shot shot = solver.solve(sim, Target.hole(sim, request.ballX(), request.ballY()), null, 0, 0,
                new SplittableRandom(request.seed()));
        if (shot != null) return shot;
        Shot best = sim.bestShot();
        return best != null ? best : directGuess(request.world(), request.ballX(), request.ballY());
    }
}
