package minigolf.bot.search;

import java.util.SplittableRandom;
import minigolf.bot.BotRequest;
import minigolf.bot.CountingSimulator;
import minigolf.bot.Shot;

/** {@code newton}: {@link NewtonSolver} at the hole from the physics guess; else the best shot seen. */
public final class NewtonBot extends SearchBot {
    private final NewtonSolver solver;

    public NewtonBot() {
        this(new NewtonSolver());
    }

    public NewtonBot(NewtonSolver solver) {
        this.solver = solver;
    }

    @Override
    public String name() {
        return "newton";
    }

    @Override
    protected Shot search(BotRequest request) {
        CountingSimulator sim = request.simulator();
        sim.phase("newton");
        Shot guess = directGuess(request.world(), request.ballX(), request.ballY());
        Shot shot = solver.solve(sim, Target.hole(sim, request.ballX(), request.ballY()), guess,
                new SplittableRandom(request.seed()));
        if (shot != null) return shot;
        Shot best = sim.bestShot();
        return best != null ? best : guess;
    }
}
