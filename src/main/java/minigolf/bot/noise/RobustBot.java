package minigolf.bot.noise;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.Bot;
import minigolf.bot.BotCancelledException;
import minigolf.bot.BotRequest;
import minigolf.bot.BudgetExhaustedException;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.planner.PlannerBot;
import minigolf.physics.World;

/**
 * The planner, made aware of the noise ({@link BotRequest#noise()}). The planner's search runs as
 * usual; then, on every stroke, its chosen shot, the best other shots it simulated from the ball
 * and shots around the best are scored by their expected strokes over common draws of the noise
 * model, and the best is played if it is clearly better than the planner's ({@link NoisyChoice}).
 * Expected strokes after a draw come from a {@link ValueMap} (built once per course and noise).
 * Without noise it plays the planner's shot. Budget, time limit and cancel: as every bot (its
 * simulations go through the counting simulator); when the budget runs out it plays the best shot
 * scored so far.
 */
public final class RobustBot implements Bot {
    private final PlannerBot planner = new PlannerBot();
    private World valueWorld;
    private NoiseModel valueNoise;
    private ValueMap values;
    /**
     * Where this game's ball lay when the planner's shot was replaced, and its value there: back
     * near one and no nearer the hole by the value map, the planner's shot is played (the value
     * map may misjudge a spot, e.g. a basin the ball rolls back into; the planner's own cycle
     * memory then takes over).
     */
    private final List<double[]> replacedFrom = new ArrayList<>();
    /** "Near" for {@link #replacedFrom}, metres. */
    static final double RETURN_RADIUS = 0.5;
    /** Back near such a spot, the value map must expect this many strokes fewer than there. */
    static final double PROGRESS = 0.05;

    @Override
    public String name() {
        return "robust";
    }

    @Override
    public Shot nextShot(BotRequest request) {
        Shot base = planner.nextShot(request);
        NoiseModel noise = request.noise();
        if (noise.isNone()) return base;
        double x = request.ballX(), y = request.ballY();
        ValueMap map;
        try {
            map = valuesFor(request);
        } catch (BotCancelledException e) {
            throw e;
        } catch (RuntimeException e) {
            request.simulator().recordError(name() + ": " + e);
            return base;
        }
        double here = map.fromRest(x, y);
        for (double[] p : replacedFrom) {
            // Exactly there: a lost ball put back, which the choice has already priced in. Nearer
            // the hole by the map: progress (a missed putt that stopped closer), not a cycle.
            double d = Math.hypot(p[0] - x, p[1] - y);
            if (d > 0 && d < RETURN_RADIUS && here > p[2] - PROGRESS) return base;
        }
        NoisyChoice choice = null;
        try {
            choice = new NoisyChoice(request, base, map);
            choice.search();
        } catch (BudgetExhaustedException e) {
            // The best scored so far (the planner's shot if none was).
        } catch (BotCancelledException e) {
            throw e;
        } catch (RuntimeException e) {
            request.simulator().recordError(name() + ": " + e);
            if (request.token().isCancelled()) throw new BotCancelledException();
        }
        Shot chosen = choice == null ? base : choice.best();
        if (!chosen.equals(base)) replacedFrom.add(new double[] {x, y, here});
        return chosen;
    }

    private ValueMap valuesFor(BotRequest request) {
        World world = request.world();
        if (world != valueWorld || !request.noise().equals(valueNoise)) {
            // The planner's own maps and stroke plan for this course: built once for both.
            values = new ValueMap(world, planner.strokePlan(request), planner.courseMaps(request).toHole(), request.noise());
            valueWorld = world;
            valueNoise = request.noise();
        }
        return values;
    }
}
