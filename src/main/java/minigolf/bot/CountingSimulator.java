package minigolf.bot;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Simulator;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;

/**
 * The one door through which bots simulate shots, so "simulations" means the same for every bot.
 * Every call counts (probes, particles, look-ahead alike), checks the cancellation token and
 * enforces the budget. It also remembers the best shot seen from the current ball position, which
 * is what a bot returns when its budget runs out.
 *
 * <p>Not thread-safe: one bot run, one thread (the token may be cancelled from any thread). Only
 * {@link #simulateInOrder} spreads shots over more threads ({@link #spreadOver}), each with an
 * engine of its own, and hands their results back on the bot's thread in order.
 */
public final class CountingSimulator {
    /** Inside one simulated shot, the token is checked every this many steps (a slow shot stays cancellable). */
    static final int STEPS_PER_CHECK = 256;
    /** Progress is reported every this many simulations. */
    public static final int PROGRESS_INTERVAL = 32;
    /** The most threads a batch may use. */
    public static final int MAX_THREADS = 256;

    /** Scores a shot for {@link #bestShot()}: lower is better. */
    @FunctionalInterface
    public interface ShotScore {
        double score(ShotResult result);
    }

    /** Shared by a simulator and its {@link #variant variants}: one budget, one count. */
    private static final class Account {
        final long budget;
        final CancellationToken token;
        final BotProgress progress;
        long used;
        String phase = "start";
        double fromX = Double.NaN, fromY = Double.NaN;
        ShotScore score;
        Shot best;
        ShotResult bestResult;
        double bestScore = Double.POSITIVE_INFINITY;
        /** Every real-world result simulated from (fromX, fromY) this stroke, by the shot played. */
        final Map<Shot, ShotResult> results = new HashMap<>();
        /** Errors a bot recovered from (see SearchBot): none on a correct bot. */
        final List<String> errors = new ArrayList<>();
        /** Whoever plays the shot can only putt (the game): bots must not choose chips. */
        boolean puttsOnly;
        /** The course clock the shots are played at (plus their wait). */
        double clock;
        /** Threads a batch ({@link #simulateInOrder}) may run its shots on, the caller's included. */
        int threads = 1;

        Account(long budget, CancellationToken token, BotProgress progress) {
            this.budget = budget;
            this.token = token;
            this.progress = progress;
        }
    }

    private final World world;
    private final Simulator simulator;
    private final Account account;
    /** Variants simulate another world (e.g. a probe); their shots are not candidates for bestShot. */
    private final boolean primary;
    /** The simulator of the real world (not a variant): all its results are real, for {@link #knownResult}. */
    private final boolean real;
    /** Whether obstacles move in this world (then the clock and a shot's wait matter). */
    private final boolean moving;
    /** The watchdog every shot runs under, reused (a shot allocates nothing for it). */
    private final Watchdog watchdog;
    /** Engines of this world for a batch's helper threads, one per helper (made on the bot's thread). */
    private final List<Simulator> helpers = new ArrayList<>();

    /**
     * @param budget the most simulations allowed in total ({@code Long.MAX_VALUE}: unlimited)
     */
    public CountingSimulator(World world, SimulationSettings settings, long budget, CancellationToken token,
                             BotProgress progress) {
        this(world, new Simulator(world, settings), new Account(budget, token, progress), true, true);
        if (budget < 0) throw new IllegalArgumentException("budget must be >= 0, got " + budget);
        // A course that plays putts only (a classic track) has no chips for the bots to search.
        if (world.physics().puttsOnly()) account.puttsOnly = true;
    }

    /** Unlimited, never cancelled, default settings: for tests and tools. */
    public CountingSimulator(World world) {
        this(world, SimulationSettings.DEFAULT, Long.MAX_VALUE, CancellationToken.none(), BotProgress.NONE);
    }

    private CountingSimulator(World world, Simulator simulator, Account account, boolean primary, boolean real) {
        this.moving = world.moving() != null;
        this.world = world;
        this.simulator = simulator;
        this.account = account;
        this.primary = primary;
        this.real = real;
        this.watchdog = new Watchdog(account.token);
    }

    /**
     * A simulator of another world that shares this one's count, budget and token. With
     * {@code candidates} its shots compete for {@link #bestShot()}: only for a world whose
     * non-holed results are the real world's (the same course with a stricter hole rule).
     */
    public CountingSimulator variant(World other, boolean candidates) {
        return new CountingSimulator(other, new Simulator(other, simulator.settings()), account, candidates, false);
    }

    /**
     * This simulator on the same course with the bricks as {@code state} leaves them (what the strokes
     * so far broke): the same count, budget, token and threads. Itself when the state is its world's.
     */
    public CountingSimulator inState(minigolf.physics.CourseState state) {
        if (state.equals(world.state())) return this;
        World other = world.withState(state);
        return new CountingSimulator(other, new Simulator(other, simulator.settings()), account, primary, real);
    }

    public World world() {
        return world;
    }

    /** Whether the shot chosen will be played as a putt only (a caller that cannot play chips): no chips. */
    public boolean puttsOnly() {
        return account.puttsOnly;
    }

    /** Says that the chosen shot can only be a putt; shared with every {@link #variant}. */
    public void allowPuttsOnly() {
        account.puttsOnly = true;
    }

    public SimulationSettings settings() {
        return simulator.settings();
    }

    public double maxSpeed() {
        return world.physics().maxSpeed();
    }

    /** Simulations used so far. */
    public long count() {
        return account.used;
    }

    public long budget() {
        return account.budget;
    }

    public long remaining() {
        return account.budget - account.used;
    }

    public CancellationToken token() {
        return account.token;
    }

    /**
     * Lets {@link #simulateInOrder} run up to {@code threads} shots at once (1: one after the other,
     * on the caller's thread); shared with every {@link #variant}. The results, counts and choices
     * are the same for any number.
     */
    public void spreadOver(int threads) {
        if (threads < 1 || threads > MAX_THREADS) {
            throw new IllegalArgumentException("threads must be 1 to " + MAX_THREADS + ", got " + threads);
        }
        account.threads = threads;
    }

    /** The threads {@link #simulateInOrder} may use (see {@link #spreadOver}). */
    public int threads() {
        return account.threads;
    }

    /** What {@link #simulateInOrder} needs to know of a caller's trials (a sweep's shots). */
    public interface InOrder<T> {
        /** The trial's shot. */
        Shot shot(T trial);

        /**
         * The trial's listener, or null: its own, made before any shot runs, and touching nothing
         * shared while its shot runs (the shot may run on another thread; it is read afterwards).
         */
        default TrajectoryListener listener(T trial) {
            return null;
        }

        /** Checked before each trial is counted, as a loop checks its bounds: false ends the batch there. */
        default boolean mayGoOn() {
            return true;
        }

        /** The trial's result, handed on in order on the caller's thread once it is counted: true ends the batch. */
        boolean stopsAt(T trial, ShotResult result);

        /** Bare shots (each shot its own trial, no listener), each result to {@code stop}: true ends the batch. */
        static InOrder<Shot> shots(java.util.function.BiPredicate<Shot, ShotResult> stop) {
            return new InOrder<>() {
                @Override
                public Shot shot(Shot shot) {
                    return shot;
                }

                @Override
                public boolean stopsAt(Shot shot, ShotResult result) {
                    return stop.test(shot, result);
                }
            };
        }
    }

    /**
     * The trials' shots from (x, y), exactly as if each were {@link #simulate simulated} in turn
     * with {@code order.stopsAt} after it, stopping before a trial where {@code order.mayGoOn()}
     * says no and after one where {@code stopsAt} says yes: the same count, budget, exceptions,
     * known results and best shot. Up to {@link #threads()} shots run at once (each thread on an
     * engine of its own, the world shared read-only); a shot simulated past the end of the batch
     * is neither counted nor kept. The trial that ended the batch, or null.
     */
    public <T> T simulateInOrder(double x, double y, List<T> trials, InOrder<T> order) {
        if (account.threads > 1 && trials.size() > 1) return new ShotBatch<>(this, x, y, trials, order).run();
        // One thread: the loop itself.
        for (T trial : trials) {
            if (!order.mayGoOn()) return null;
            if (order.stopsAt(trial, simulate(x, y, order.shot(trial), order.listener(trial)))) return trial;
        }
        return null;
    }

    /** The engine for a batch's helper {@code k} (1, 2, ...): made on the caller's thread, used by one thread at a time. */
    Simulator helper(int k) {
        while (helpers.size() < k) helpers.add(new Simulator(world, simulator.settings()));
        return helpers.get(k - 1);
    }

    /** The engine this simulator runs shots on (a batch's own thread uses it). */
    Simulator engine() {
        return simulator;
    }

    /** A new watchdog on this game's token (a batch's thread each has one). */
    Watchdog newWatchdog() {
        return new Watchdog(account.token);
    }

    /** Whether a shot is played later than now (where obstacles move and it waits): not kept as one of now's results. */
    boolean later(Shot shot) {
        return moving && shot.waitSeconds() != 0;
    }

    /** Throws if cancelled; for bots' own long loops. */
    public void checkCancelled() {
        account.token.throwIfCancelled();
    }

    /** Reports the route the bot intends (ball first, hole last) to the progress listener; copies it. */
    public void showPlan(java.util.List<double[]> points) {
        java.util.List<double[]> copy = new java.util.ArrayList<>(points.size());
        for (double[] p : points) copy.add(new double[] {p[0], p[1]});
        account.progress.plan(java.util.Collections.unmodifiableList(copy));
    }

    /** Names the bot's current phase for the progress indicator and reports progress. */
    public void phase(String phase) {
        account.phase = phase;
        account.progress.update(account.used, account.budget, phase);
    }

    /**
     * Starts looking for a shot from (x, y): the best-shot memory is cleared and shots from there
     * are scored with {@code score}.
     */
    public void beginShot(double x, double y, ShotScore score) {
        account.fromX = x;
        account.fromY = y;
        account.score = score;
        account.best = null;
        account.bestResult = null;
        account.bestScore = Double.POSITIVE_INFINITY;
        account.results.clear();
    }

    /**
     * What {@code shot} did from the position given to {@link #beginShot}, if it was simulated
     * there this stroke in the real world, or in a candidate variant that did not hole it (null
     * otherwise): the engine is deterministic, so a bot can check where its chosen shot ends
     * without simulating it again.
     */
    public ShotResult knownResult(Shot shot) {
        return account.results.get(shot);
    }

    /** Every real-world result from the position given to {@link #beginShot}, by shot (read-only view). */
    public Map<Shot, ShotResult> knownResults() {
        return java.util.Collections.unmodifiableMap(account.results);
    }

    /** Records an error a bot recovered from (its message); {@link #errors()} lists them. */
    public void recordError(String message) {
        account.errors.add(message);
    }

    /** The errors bots recovered from in this game: empty unless a bot has a bug. */
    public List<String> errors() {
        return List.copyOf(account.errors);
    }

    /** The best-scored shot simulated from the position given to {@link #beginShot}, or null. */
    public Shot bestShot() {
        return account.best;
    }

    public ShotResult bestResult() {
        return account.bestResult;
    }

    public ShotResult simulate(double x, double y, Shot shot) {
        return simulate(x, y, shot, null);
    }

    /**
     * Simulates {@code shot} (scaled down to the course's maxSpeed if faster) from (x, y).
     *
     * @throws BotCancelledException    if the token was cancelled (also during the shot)
     * @throws BudgetExhaustedException if the budget or the time limit is spent (also during the shot)
     */
    public ShotResult simulate(double x, double y, Shot shot, TrajectoryListener listener) {
        account.token.throwIfCancelled();
        if (moving && shot.waitSeconds() != 0) return simulateLater(x, y, shot, listener);
        Shot limited = limit(shot);
        charge();
        Watchdog watchdog = this.watchdog;
        // A listener that simulates while its shot runs gets a watchdog of its own.
        if (watchdog.busy) watchdog = new Watchdog(account.token);
        ShotResult result = run(simulator, watchdog, x, y, limited, listener);
        remember(x, y, limited, result);
        return result;
    }

    /**
     * Counts one simulation against the budget (reporting progress every so often).
     *
     * @throws BudgetExhaustedException if the budget is spent
     */
    void charge() {
        if (account.used >= account.budget) throw new BudgetExhaustedException(account.budget);
        account.used++;
        if (account.used % PROGRESS_INTERVAL == 0) account.progress.update(account.used, account.budget, account.phase);
    }

    /** Plays a shot (already limited) on {@code engine} under {@code watchdog}, at the account's clock plus its wait. */
    ShotResult run(Simulator engine, Watchdog watchdog, double x, double y, Shot limited, TrajectoryListener listener) {
        watchdog.busy = true;
        watchdog.inner = listener;
        watchdog.steps = 0;
        try {
            return play(engine, account.clock, x, y, limited, watchdog);
        } finally {
            watchdog.inner = null;
            watchdog.busy = false;
        }
    }

    /** Keeps a result from the stroke's position among the known results and the best shot. */
    void remember(double x, double y, Shot limited, ShotResult result) {
        // A candidate variant's results are the real world's except where it holes.
        if (primary && (real || result.outcome() != Outcome.HOLED) && x == account.fromX && y == account.fromY) {
            account.results.put(limited, result);
        }
        if (primary && account.score != null && x == account.fromX && y == account.fromY) {
            double s = account.score.score(result);
            if (s < account.bestScore) {
                account.bestScore = s;
                account.best = limited;
                account.bestResult = result;
            }
        }
    }

    /**
     * A shot with a wait, where obstacles move: played at the clock plus its wait. Counted as any
     * simulation, but not kept as a candidate of this moment (its result belongs to a later one).
     */
    private ShotResult simulateLater(double x, double y, Shot shot, TrajectoryListener listener) {
        charge();
        return run(simulator, new Watchdog(account.token), x, y, limit(shot), listener);
    }

    /**
     * The course clock (s) the shots are played at (plus their wait): the moment the bot is asked.
     * Where obstacles move a new moment forgets what was simulated at the old one (its results and
     * best shot): the same shot does something else now.
     */
    public void setClock(double clock) {
        if (!(clock >= 0) || !Double.isFinite(clock)) throw new IllegalArgumentException("the clock must be >= 0, got " + clock);
        if (moving && clock != account.clock) {
            account.results.clear();
            account.best = null;
            account.bestResult = null;
            account.bestScore = Double.POSITIVE_INFINITY;
        }
        account.clock = clock;
    }

    public double clock() {
        return account.clock;
    }

    /** Runs a shot on the engine at course clock 0 (see {@link #play(Simulator, double, double, double, Shot, TrajectoryListener)}). */
    public static ShotResult play(Simulator simulator, double x, double y, Shot shot, TrajectoryListener listener) {
        return play(simulator, 0, x, y, shot, listener);
    }

    /**
     * Runs a shot on the engine: a putt with the rolling call, a shot with a vertical component
     * (a chip) with the 3-component one, exactly as the game plays them; where obstacles move, at
     * course clock {@code clock} plus the shot's wait.
     */
    public static ShotResult play(Simulator simulator, double clock, double x, double y, Shot shot, TrajectoryListener listener) {
        try {
            if (simulator.world().moving() != null) {
                double at = clock + shot.waitSeconds();
                if (shot.isPutt()) return simulator.simulatePuttAt(at, x, y, shot.vx(), shot.vy(), listener);
                return simulator.simulateAt(at, x, y, shot.vx(), shot.vy(), shot.vz(), listener, false);
            }
            if (shot.isPutt()) return simulator.simulate(x, y, shot.vx(), shot.vy(), listener);
            return simulator.simulate(x, y, shot.vx(), shot.vy(), shot.vz(), listener, false);
        } catch (minigolf.physics.NonFiniteMotionException e) {
            // The ball's motion overflowed (terrain too steep, or not finite between the loader's
            // samples): out of play, as the game rules it (StrokeAnimator); the ball stays where it was.
            return new ShotResult(Outcome.OUT, x, y, 0, 0, Double.NaN, java.util.List.of(), simulator.world().state());
        }
    }

    /** The shot as it is played: never faster than the course allows. */
    public Shot limit(Shot shot) {
        // A hair below maxSpeed so rounding never trips the engine's own check.
        return shot.limitedTo(maxSpeed() * (1 - 1e-12));
    }

    /** Whether an outcome ends the search for this shot: the ball is in. */
    public static boolean holed(ShotResult result) {
        return result.outcome() == Outcome.HOLED;
    }

    /**
     * Passes every step on to the bot's own listener (if any) and checks the token every
     * {@link #STEPS_PER_CHECK} steps, so that a shot that rolls or bounces for a long time of
     * simulated time cannot hold a cancel or the time limit up.
     */
    static final class Watchdog implements TrajectoryListener {
        private final CancellationToken token;
        /** The bot's own listener for the shot running, or null. */
        TrajectoryListener inner;
        boolean busy;
        int steps;

        Watchdog(CancellationToken token) {
            this.token = token;
        }

        /** Events and the path only if the bot's own listener wants them: a bare watchdog only counts steps. */
        @Override
        public boolean wantsDetail() {
            return inner != null && inner.wantsDetail();
        }

        @Override
        public void onStep(double t, double x, double y, double vx, double vy) {
            if (inner != null) inner.onStep(t, x, y, vx, vy);
            if (++steps % STEPS_PER_CHECK == 0) token.throwIfCancelled();
        }

        @Override
        public void onState(double t, double x, double y, double z, double vx, double vy, double vz) {
            if (inner != null) inner.onState(t, x, y, z, vx, vy, vz);
            if (++steps % STEPS_PER_CHECK == 0) token.throwIfCancelled();
        }

        @Override
        public void onEvent(minigolf.physics.StrokeEvent event) {
            if (inner != null) inner.onEvent(event);
        }
    }
}
