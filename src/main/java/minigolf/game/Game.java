package minigolf.game;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import minigolf.bot.NoiseModel;
import minigolf.bot.Shot;
import minigolf.bot.noise.PlayedStroke;
import minigolf.bot.noise.ShotNoise;
import minigolf.physics.CourseState;
import minigolf.physics.Outcome;
import minigolf.physics.ShotResult;
import minigolf.physics.SimulationSettings;
import minigolf.physics.Stroke;
import minigolf.physics.Landing;
import minigolf.physics.World;

/**
 * A hot-seat game of 1 to 4 players on one hole (one course). Plain Java: the window animates the
 * {@link Stroke} that {@link #startShot} hands out, the tests and bots run it to its end; both use
 * the same engine and the same rules.
 *
 * <p>Rules: every ball starts on a spot of its own beside the tee ({@link TeeSpots}). Every hit is
 * a stroke. Water or out of bounds adds one penalty stroke and the ball goes back to where the
 * stroke began. Turn order is golf's: everyone tees off first, in seat order; then the player
 * farthest from the hole plays next; at equal distance (within a millimetre) the one with fewer
 * strokes, then the lower seat. Holed
 * players are skipped. A player whose hits plus penalties reach the stroke limit without holing
 * picks up and scores the limit plus one. The game is over when nobody is still playing. Balls
 * do not collide with each other. What a stroke changes on the course (breakable bricks) lasts
 * for the strokes after it, for every player, until the hole ends ({@link #world()}).
 */
public final class Game {
    public static final int MAX_PLAYERS = 4;
    public static final int DEFAULT_STROKE_LIMIT = 10;
    public static final int MAX_STROKE_LIMIT = 99;
    /** Distances to the hole closer than this count as equal for the turn order. */
    public static final double TIE_DISTANCE = 0.001;

    /** The hole as it starts (every brick standing) and as the strokes so far have left it. */
    private final World startWorld;
    private World world;
    private final SimulationSettings settings;
    private final List<Player> players;
    private final int strokeLimit;
    private final List<PlayerState> states = new ArrayList<>();
    private final List<ShotRecord> history = new ArrayList<>();
    /** Seats the turn passes over while another can play (an online player who dropped); not part of a save. */
    private final boolean[] passedOver;

    private final NoiseModel noise;
    private final long noiseSeed;
    /** The seed the computer opponents' decisions are drawn from (see {@link #botSeed()}). */
    private final long botSeed;
    private Stroke stroke;
    private int strokePlayer = -1;
    /** The stroke in flight as the player chose it (what a save keeps: the noise is drawn again, the same). */
    private double strokeVx, strokeVy, strokeVz;
    /** The stroke in flight as played (what the history and replays keep). */
    private PlayedStroke strokePlayed;
    /**
     * The course clock (s): where moving obstacles are. It runs on between strokes (the game loop
     * calls {@link #advanceClock}) and through each stroke; a stroke is played at its current value.
     */
    private double clock;

    public Game(World world, SimulationSettings settings, List<Player> players, int strokeLimit) {
        this(world, settings, players, strokeLimit, NoiseModel.NONE, 0);
    }

    /**
     * A game whose strokes are played with noise (the "realistic" setting, for every player, human
     * or bot). Stroke n of the game (0-based, all players) draws its noise from a stream seeded by
     * {@code noiseSeed} and n alone, so a restored game plays its next strokes as the original would.
     */
    public Game(World world, SimulationSettings settings, List<Player> players, int strokeLimit, NoiseModel noise,
                long noiseSeed) {
        this(world, settings, players, strokeLimit, noise, noiseSeed, 0);
    }

    /** As {@link #Game(World, SimulationSettings, List, int, NoiseModel, long)}, its bots drawing from {@code botSeed}. */
    public Game(World world, SimulationSettings settings, List<Player> players, int strokeLimit, NoiseModel noise,
                long noiseSeed, long botSeed) {
        if (world == null || settings == null) throw new IllegalArgumentException("world and settings must be given");
        if (players == null || players.isEmpty() || players.size() > MAX_PLAYERS) {
            throw new IllegalArgumentException("a game has 1 to " + MAX_PLAYERS + " players");
        }
        if (strokeLimit < 1 || strokeLimit > MAX_STROKE_LIMIT) {
            throw new IllegalArgumentException("the stroke limit must be 1 to " + MAX_STROKE_LIMIT + ", got " + strokeLimit);
        }
        // Every game starts its hole afresh: the bricks as the course file gives them.
        this.startWorld = world.withState(CourseState.initial(world.course()));
        this.world = startWorld;
        this.settings = settings;
        this.players = List.copyOf(players);
        this.strokeLimit = strokeLimit;
        this.noise = noise == null ? NoiseModel.NONE : noise;
        // Without noise the seed means nothing (and a save does not keep it): one state, one save.
        this.noiseSeed = this.noise.isNone() ? 0 : noiseSeed;
        // Likewise without a computer opponent.
        this.botSeed = this.players.stream().anyMatch(Player::isBot) ? botSeed : 0;
        // Each ball waits on a spot of its own beside the tee (TeeSpots: checked like a start).
        for (minigolf.course.Vec2 spot : TeeSpots.of(world, players.size())) {
            states.add(new PlayerState(spot.x(), spot.y(), 0, 0, PlayerStatus.PLAYING));
        }
        passedOver = new boolean[players.size()];
    }

    /** Rebuilds a game from saved state (see {@link GameState}); a stroke that was rolling starts again. */
    public static Game restore(World world, GameState saved) {
        Game game = new Game(world, saved.settings(), saved.players(), saved.strokeLimit(), saved.noise(), saved.noiseSeed(),
                saved.botSeed());
        game.states.clear();
        game.states.addAll(saved.states());
        game.history.addAll(saved.history());
        game.world = courseAfter(game.startWorld, saved.settings(), saved.history());
        game.clock = saved.clock();
        if (saved.pendingShot() != null) {
            int who = game.currentPlayer();
            if (who < 0) throw new IllegalArgumentException("the saved game has a shot in flight but nobody left to play");
            PendingShot p = saved.pendingShot();
            game.startShot(p.vx(), p.vy(), p.vz(), null);
        }
        return game;
    }

    /**
     * The hole as {@code history} leaves it: its strokes replayed in order, each from the state the
     * one before left (the engine is deterministic, so this is the state play reached; a save or a
     * server's event need not carry it). Nothing is simulated on a course without bricks.
     */
    static World courseAfter(World start, SimulationSettings settings, List<ShotRecord> history) {
        if (start.course().bricks().isEmpty()) return start;
        World w = start;
        for (ShotRecord r : history) {
            w = w.withState(new Stroke(w, settings, r.startX(), r.startY(), r.vx(), r.vy(), r.vz(), r.clock(), null,
                    false).runOrEndOutOfPlay().state());
        }
        return w;
    }

    /** Everything needed to resume this game exactly. A stroke in flight is saved as its start and velocity. */
    public GameState state() {
        PendingShot pending = stroke == null ? null : new PendingShot(strokeVx, strokeVy, strokeVz);
        return new GameState(settings, players, strokeLimit, List.copyOf(states), List.copyOf(history), pending, noise,
                noiseSeed, clock, botSeed);
    }

    /**
     * The course clock (s): with a stroke rolling, the moment it has reached; otherwise where it
     * stands (the next stroke is played at it).
     */
    public double clock() {
        return stroke != null ? stroke.clock() : clock;
    }

    /** Lets the course clock run on by {@code seconds} between strokes (the players aim, a bot's planned wait). */
    public void advanceClock(double seconds) {
        if (stroke != null) throw new IllegalStateException("a stroke is rolling: its own time moves the clock");
        if (!(seconds >= 0) || !Double.isFinite(seconds)) throw new IllegalArgumentException("seconds must be >= 0, got " + seconds);
        clock += seconds;
    }

    /** Runs the course clock on to exactly {@code moment} (a bot's planned moment), never back. */
    public void advanceClockTo(double moment) {
        if (stroke != null) throw new IllegalStateException("a stroke is rolling: its own time moves the clock");
        if (!(moment >= clock) || !Double.isFinite(moment)) throw new IllegalArgumentException("the clock cannot go back to " + moment);
        clock = moment;
    }

    /** Whether the course has moving obstacles (then the clock matters). */
    public boolean hasMovingObstacles() {
        return world.moving() != null;
    }

    /** The noise every stroke is played with ({@link NoiseModel#NONE}: as aimed). */
    public NoiseModel noise() {
        return noise;
    }

    /** The seed of the noise stream (0 without noise). */
    public long noiseSeed() {
        return noiseSeed;
    }

    /**
     * The seed of this game's computer opponents (0 without one): the game mixes it with the hole,
     * the strokes played and the seat for each decision ({@link BotTurn#seed}). Drawn when a game or
     * round starts and saved with it, so a resumed game's bots play the strokes an unbroken one would.
     */
    public long botSeed() {
        return botSeed;
    }

    /**
     * The course as the strokes so far have left it (the bricks still standing): what the next
     * stroke is played on, what bots plan on and what is drawn.
     */
    public World world() {
        return world;
    }

    /** The hole as it started, every brick standing: what a replay of its strokes starts from. */
    public World startWorld() {
        return startWorld;
    }

    /** The bricks left standing (the state of {@link #world()}). */
    public CourseState courseState() {
        return world.state();
    }

    public SimulationSettings settings() {
        return settings;
    }

    public List<Player> players() {
        return players;
    }

    public int strokeLimit() {
        return strokeLimit;
    }

    public PlayerState player(int seat) {
        return states.get(seat);
    }

    public List<PlayerState> states() {
        return Collections.unmodifiableList(states);
    }

    public List<ShotRecord> history() {
        return Collections.unmodifiableList(history);
    }

    public boolean isOver() {
        return currentPlayer() < 0;
    }

    /**
     * The seat whose turn it is: while a stroke rolls, its player; otherwise the playing player
     * farthest from the hole (ties: fewer strokes, then lower seat), passing over the seats of
     * {@link #passOver} while any other seat can play. -1 when the game is over.
     */
    public int currentPlayer() {
        if (stroke != null) return strokePlayer;
        int present = farthestPlaying(true);
        return present >= 0 ? present : farthestPlaying(false);
    }

    /**
     * Passes the turn over {@code seat} (on) or gives it back (off): an online player whose
     * connection dropped is skipped while others can still play; when only passed-over seats are
     * left, the turn is theirs again. Kept in memory only: a save or a restored game passes over nobody.
     */
    public void passOver(int seat, boolean on) {
        passedOver[seat] = on;
    }

    public boolean isPassedOver(int seat) {
        return passedOver[seat];
    }

    /**
     * Picks up {@code seat}'s ball without a stroke (an online player gone for good): the seat
     * scores the stroke limit plus one on this hole, as a player who reached the limit.
     *
     * @throws IllegalStateException if the seat's stroke is rolling or the seat is no longer playing
     */
    public void pickUp(int seat) {
        if (stroke != null && strokePlayer == seat) throw new IllegalStateException("the seat's stroke is still rolling");
        PlayerState s = states.get(seat);
        if (!s.isPlaying()) throw new IllegalStateException("seat " + seat + " is no longer playing");
        states.set(seat, new PlayerState(s.x(), s.y(), s.strokes(), s.penalties(), PlayerStatus.PICKED_UP));
    }

    private int farthestPlaying(boolean skipPassedOver) {
        // Teeing off goes in seat order (the balls beside the tee are at slightly different distances).
        for (int i = 0; i < states.size(); i++) {
            if (states.get(i).isPlaying() && !(skipPassedOver && passedOver[i]) && states.get(i).total() == 0) return i;
        }
        int best = -1;
        double bestDistance = -1;
        for (int i = 0; i < states.size(); i++) {
            PlayerState s = states.get(i);
            if (!s.isPlaying() || (skipPassedOver && passedOver[i])) continue;
            var hole = world.nearestHole(s.x(), s.y()).position();
            double d = Math.hypot(s.x() - hole.x(), s.y() - hole.y());
            boolean farther = d > bestDistance + TIE_DISTANCE;
            boolean tie = !farther && d >= bestDistance - TIE_DISTANCE;
            if (best < 0 || farther || (tie && s.total() < states.get(best).total())) {
                best = i;
                bestDistance = d;
            }
        }
        return best;
    }

    /** The stroke in flight, or null. */
    public Stroke activeStroke() {
        return stroke;
    }

    public boolean isShotInFlight() {
        return stroke != null;
    }

    /**
     * Hits the current player's ball with velocity (vx, vy) m/s and returns the stroke to advance.
     * With noise the stroke played starts and leaves as {@link ShotNoise} draws it.
     *
     * @throws IllegalStateException    if a stroke is already rolling or the game is over
     * @throws IllegalArgumentException if the speed exceeds the course's maximum speed
     */
    public Stroke startShot(double vx, double vy) {
        return startShot(vx, vy, null);
    }

    /** As {@link #startShot(double, double)}, with a listener for the stroke's events (the game's sounds). */
    public Stroke startShot(double vx, double vy, minigolf.physics.TrajectoryListener listener) {
        return startShot(vx, vy, 0, listener);
    }

    /**
     * Hits the ball with velocity (vx, vy, vz): vz = 0 is a putt, vz &gt; 0 a chip (the ball leaves
     * the ground). The course's speed limit applies to the whole vector.
     */
    public Stroke startShot(double vx, double vy, double vz, minigolf.physics.TrajectoryListener listener) {
        if (stroke != null) throw new IllegalStateException("a stroke is still rolling");
        int who = currentPlayer();
        if (who < 0) throw new IllegalStateException("the game is over");
        if (!(vz >= 0)) throw new IllegalArgumentException("the vertical velocity must be 0 or more, got " + vz);
        PlayerState s = states.get(who);
        // The aimed stroke is checked as before (finite, not too fast); then the noise is drawn.
        Stroke started = new Stroke(world, settings, s.x(), s.y(), vx, vy, vz, clock, listener, false);
        PlayedStroke played = new PlayedStroke(s.x(), s.y(), new Shot(vx, vy, vz));
        if (!noise.isNone()) {
            played = new ShotNoise(noise, world, noiseSeed + 0x9E3779B97F4A7C15L * history.size()).play(s.x(), s.y(), played.shot());
            Shot p = played.shot();
            started = new Stroke(world, settings, played.x(), played.y(), p.vx(), p.vy(), p.vz(), clock, listener, false);
        }
        stroke = started;
        strokePlayer = who;
        strokeVx = vx;
        strokeVy = vy;
        strokeVz = vz;
        strokePlayed = played;
        return started;
    }

    /**
     * Applies the finished stroke: counts it, adds a penalty and puts the ball back for water or
     * out of bounds, marks a holed or picked-up player.
     */
    public ShotRecord completeShot() {
        if (stroke == null) throw new IllegalStateException("no stroke is rolling");
        if (!stroke.isFinished()) throw new IllegalStateException("the stroke has not finished");
        ShotResult r = stroke.result();
        PlayerState s = states.get(strokePlayer);
        Landing landing = Landing.of(world, r, s.x(), s.y());
        double x = landing.x();
        double y = landing.y();
        int hits = s.strokes() + 1;
        int penalties = s.penalties() + landing.penalty();
        PlayerStatus status = r.outcome() == Outcome.HOLED ? PlayerStatus.HOLED
                : hits + penalties >= strokeLimit ? PlayerStatus.PICKED_UP : PlayerStatus.PLAYING;
        states.set(strokePlayer, new PlayerState(x, y, hits, penalties, status));
        // The stroke as played: a replay from the record ends exactly where play did.
        Shot v = strokePlayed.shot();
        ShotRecord record = new ShotRecord(strokePlayer, strokePlayed.x(), strokePlayed.y(), v.vx(), v.vy(), v.vz(),
                r.outcome(), r.endX(), r.endY(), clock);
        history.add(record);
        world = world.withState(r.state());
        clock = stroke.clock();
        stroke = null;
        strokePlayer = -1;
        strokePlayed = null;
        return record;
    }

    /** Plays a whole stroke at once (bots, tests, a skipped animation). */
    public ShotRecord play(double vx, double vy) {
        startShot(vx, vy).run();
        return completeShot();
    }

    /** Plays a whole stroke, putt or chip, at once. */
    public ShotRecord play(double vx, double vy, double vz) {
        startShot(vx, vy, vz, null).run();
        return completeShot();
    }

    /** Runs a rolling stroke to its end and applies it (the player skipped the animation). */
    public ShotRecord finishShotNow() {
        if (stroke == null) throw new IllegalStateException("no stroke is rolling");
        stroke.run();
        return completeShot();
    }

    /** The score so far: holed players by score, then the rest. */
    public Scorecard scorecard() {
        return Scorecard.of(players, states, strokeLimit);
    }
}
