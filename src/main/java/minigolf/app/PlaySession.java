package minigolf.app;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import java.util.function.Consumer;
import minigolf.course.CourseException;
import minigolf.game.AimModel;
import minigolf.game.BotConditions;
import minigolf.game.BotSeats;
import minigolf.game.BotTurn;
import minigolf.game.Game;
import minigolf.game.Player;
import minigolf.game.PlayerState;
import minigolf.game.Round;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.game.SavedGames;
import minigolf.game.SavedRounds;
import minigolf.game.ShotPlanner;
import minigolf.game.ShotRecord;
import minigolf.game.StrokeAnimator;
import minigolf.game.StrokeNews;
import minigolf.game.UserSettings;
import minigolf.physics.TrajectoryListener;
import minigolf.physics.World;

/**
 * What is being played and how it goes on, without a window: the course or round chosen, the game
 * and the round, the stroke rolling (animated at the fixed physics step), the bot thinking on its
 * worker thread, and strokes scripted by the command line. Screens start, advance and end play
 * through it; each change stops a thinking bot first.
 */
final class PlaySession {
    /** What a pass of {@link #advance} brought. */
    enum Progress {
        NONE,
        /** A stroke came to rest ({@link #lastStroke()}); the game goes on. */
        STROKE_ENDED,
        /** The hole, or the single game, is over: its card is due. */
        OVER,
        /** The player cancelled the bot's turn. */
        CANCELLED
    }

    /** The sounds and effects of a stroke, from the window (none in tests without one). */
    interface Feedback {
        TrajectoryListener stroke(World world, boolean firstStroke, int seat);

        void hit(double speed, double maxSpeed);
    }

    private final PlayerFiles files;
    private final Consumer<String> say;
    private final Deque<double[]> script;
    private Feedback feedback;
    /** The course shown and played next: the chosen course, or the round's hole. */
    private World world;
    private Path coursePath;
    /** The high-score key of the classic track being played, or null (docs/classic-tracks.md). */
    private String classicKey;
    /** The round the next game plays (chosen in the menu), or null for the chosen course. */
    private Round roundToPlay;
    private RoundGame round;
    private Game game;
    private StrokeAnimator animator;
    private BotTurn botTurn;
    /** A bot's shot waiting for its planned moment (the course clock runs on until then), and how long yet. */
    private double[] botShot;
    /** The course clock the waiting bot's shot is to be hit at. */
    private double botMoment;
    /** Where the view's clock starts when no game is played (the moving obstacles turn behind the menus). */
    private final long idleStart = System.nanoTime();
    /** One bot per player per hole, so the planner's memory lasts across its strokes. */
    private final BotSeats botSeats = new BotSeats();
    /**
     * The least time (s of play) a computer opponent's turn shows "... is thinking" before its stroke:
     * the levels decide within a frame or two, too soon for a player to see whose turn it is.
     */
    static final double MIN_THINKING_SECONDS = 0.8;
    /** How long the bot now to play has been thinking (s of play). */
    private double botThinking;
    private ShotRecord lastStroke;
    /** A room on a game server being played instead of a local game, or null. */
    private OnlinePlay online;
    /** The server's stroke being animated (online), or null. */
    private minigolf.online.RoomEvent rolling;
    /** A server's stroke whose wait is still running before it is animated (online), and how long yet (s). */
    private minigolf.online.RoomEvent held;
    private double heldLeft;

    PlaySession(World world, Path coursePath, List<double[]> script, PlayerFiles files, Consumer<String> say) {
        this.world = world;
        this.coursePath = coursePath;
        this.script = new ArrayDeque<>(script);
        this.files = files;
        this.say = say;
    }

    void setFeedback(Feedback f) {
        feedback = f;
    }

    World world() {
        return world;
    }

    /** The course file being played (its folder holds the models' colours), or null. */
    Path coursePath() {
        return coursePath;
    }

    Game game() {
        return game;
    }

    /** The round being played, or null (a single course). */
    RoundGame round() {
        return round;
    }

    /** The round the next game plays, or null (the chosen course). */
    Round chosenRound() {
        return roundToPlay;
    }

    void chooseRound(Round r) {
        roundToPlay = r;
    }

    StrokeAnimator animator() {
        return animator;
    }

    BotTurn botTurn() {
        return botTurn;
    }

    /** How far the bot now to play is, 0 to 1: its own progress, but never ahead of its least thinking time. */
    double botProgress() {
        return botTurn == null ? 0 : Math.min(botTurn.progress(), botThinking / MIN_THINKING_SECONDS);
    }

    /** The stroke that ended last. */
    ShotRecord lastStroke() {
        return lastStroke;
    }

    /** A human player is to play and no ball rolls. */
    boolean humanToPlay() {
        if (online != null) return animator == null && held == null && online.canShoot();
        return game != null && !game.isShotInFlight() && !game.isOver() && game.currentPlayer() >= 0
                && !game.players().get(game.currentPlayer()).isBot();
    }

    /** A game or a hole of a round for these players: the chosen round, else the chosen course. */
    void start(List<Player> players, UserSettings s) {
        stopPlay();
        closeOnline();
        // The bots' seed (BotTurn.seed), drawn for each game or round and saved with it (Game.botSeed).
        long botSeed = System.nanoTime();
        if (roundToPlay != null) {
            round = new RoundGame(roundToPlay, s.simulation(), players, s.strokeLimit(), s.noise(), System.nanoTime(), botSeed);
            showHole();
            say.accept(roundToPlay.name() + ", hole 1 of " + roundToPlay.size() + " (par " + roundToPlay.hole(0).par() + "): "
                    + teeOff(players.get(0)));
            return;
        }
        round = null;
        // The "realistic" noise, drawn from a new seed each game (saved with the game, so a resumed game goes on alike).
        game = new Game(world, s.simulation(), players, s.strokeLimit(), s.noise(), System.nanoTime(), botSeed);
        say.accept(teeOff(players.get(0)));
    }

    /**
     * The news of the stroke {@code seat} just played (hot seat and bots; online, the server decides
     * the turn), and whose turn it is when the turn passes on:
     * "Ann: 3.0 m to the hole; Bot (Hard) to play" (the line stays while the bot thinks, and without
     * the turn it read as the bot's own news).
     */
    private String strokeNews(int seat, Integer par) {
        String news = StrokeNews.of(lastStroke, game.player(seat), game.players().get(seat).name(),
                game.players().size() > 1, par, world.hole().position().x(), world.hole().position().y());
        int next = game.isOver() ? -1 : game.currentPlayer();
        return next >= 0 && next != seat ? news + "; " + Hud.turnLine(game.players().get(next)) : news;
    }

    /** "Ann tees off: drag back from the ball to aim, release to hit"; a bot only tees off (nobody aims for it). */
    static String teeOff(Player first) {
        return first.name() + " tees off" + (first.isBot() ? "." : ": drag back from the ball to aim, release to hit; ESC pauses.");
    }

    /** The round's next hole; false after the last (its final card is due). */
    boolean nextHole() {
        if (round == null) return false;
        if (round.isHoleOver()) files.recordScores(round, round.finishHole());
        if (!round.nextHole()) return false;
        stopPlay();
        showHole();
        say.accept("Hole " + (round.holeIndex() + 1) + " of " + round.round().size() + ": " + world.course().name()
                + ", par " + round.hole().par());
        return true;
    }

    /** Plays a course file from now on (single games); a broken file changes nothing. */
    void selectCourse(Path file) throws CourseException {
        selectCourse(file, null);
    }

    /**
     * As {@link #selectCourse(Path)}; {@code scoreKey} (not null: a classic track) is where the
     * players' scores on it are kept in the high scores.
     */
    void selectCourse(Path file, String scoreKey) throws CourseException {
        World w = World.load(file);
        stopPlay();
        closeOnline();
        world = w;
        coursePath = file;
        classicKey = scoreKey;
        roundToPlay = null;
        round = null;
        game = null;
        say.accept(world.course().name() + " chosen: Play starts it");
    }

    /** Resumes a saved round or game where it was left, a stroke in flight included; false (and said why) when it cannot. */
    boolean load(Path file) {
        try {
            SavedRounds.AnySave save = SavedRounds.loadAny(file);
            stopPlay();
            closeOnline();
            if (save.round() != null) {
                round = save.round();
                roundToPlay = round.round();
                showHole();
                resumeStroke();
                say.accept("Round resumed: " + round.round().name() + ", hole " + (round.holeIndex() + 1) + " of " + round.round().size());
                return true;
            }
            SavedGames.Loaded loaded = save.game();
            round = null;
            classicKey = null;
            world = loaded.world();
            coursePath = null;
            game = loaded.resume();
            resumeStroke();
            say.accept("Game resumed: " + world.course().name());
            return true;
        } catch (SaveGameException e) {
            say.accept("That save could not be loaded: " + e.problem());
            return false;
        }
    }

    void save() {
        if (game != null) files.save(game, round);
    }

    /** Play ends (back to the menu): the bot stops, nothing is in play; an online seat is kept for a resume. */
    void end() {
        stopPlay();
        closeOnline();
        game = null;
        round = null;
    }

    /** Hits the current player's ball: vz = 0 is a putt, vz &gt; 0 a chip. A refused velocity is said. */
    void hit(double vx, double vy, double vz) {
        if (game == null || game.isShotInFlight() || game.isOver()) return;
        String problem = AimModel.checkTyped(vx, vy, vz, world.physics().maxSpeed());
        if (problem != null) {
            say.accept(problem);
            return;
        }
        if (online != null) {
            // The server plays the stroke; it is animated when it comes back.
            if (animator != null || held != null || !online.canShoot()) return;
            online.shoot(vx, vy, vz);
            return;
        }
        int seat = game.currentPlayer();
        boolean firstStroke = game.player(seat).total() == 0;
        TrajectoryListener listener = feedback == null ? null : feedback.stroke(game.world(), firstStroke, seat);
        animator = new StrokeAnimator(game.startShot(vx, vy, vz, listener), game.settings().dt());
        if (feedback != null) feedback.hit(Math.sqrt(vx * vx + vy * vy + vz * vz), world.physics().maxSpeed());
    }

    /** Runs the rolling stroke to its end at once (SPACE): the same stroke, no animation. */
    void skipAnimation() {
        if (held != null) startOnlineStroke();
        if (animator == null) return;
        while (!animator.isFinished()) animator.advance(1e9, 1);
    }

    /**
     * One pass of play: the rolling ball moves on by {@code elapsed} seconds (times {@code timeScale}),
     * a stroke that ends is scored, then the player to play is served: a bot is asked (on its worker
     * thread) or its answer hit, a scripted stroke is hit.
     */
    Progress advance(double elapsed, double timeScale, boolean hideFrictionFromBots) {
        if (online != null) return advanceOnline(elapsed, timeScale);
        if (game == null) return Progress.NONE;
        Progress progress = Progress.NONE;
        if (animator != null) {
            animator.advance(elapsed, timeScale);
            if (animator.isFinished()) {
                lastStroke = game.completeShot();
                animator = null;
                int seat = lastStroke.player();
                say.accept(strokeNews(seat, round != null ? round.hole().par() : null));
                if (game.isOver()) {
                    if (round != null) files.recordScores(round, round.finishHole());
                    else if (classicKey != null) files.recordClassic(classicKey, game);
                    else files.recordPractice(game);
                    return Progress.OVER;
                }
                progress = Progress.STROKE_ENDED;
            }
        }
        if (game.isShotInFlight() || game.isOver()) return progress;
        int seat = game.currentPlayer();
        Player p = game.players().get(seat);
        if (botShot != null) {
            // The bot's shot waits for its planned moment: the clock runs on to it exactly, then it is hit.
            if (game.clock() + elapsed * timeScale < botMoment) {
                game.advanceClock(elapsed * timeScale);
            } else {
                game.advanceClockTo(botMoment);
                double[] shot = botShot;
                botShot = null;
                hit(shot[0], shot[1], shot[2]);
            }
            return progress;
        }
        // The course clock runs while players aim; it stands still while a bot thinks (its shot is
        // planned for the moment it was asked at).
        if (botTurn == null && progress != Progress.STROKE_ENDED) game.advanceClock(elapsed * timeScale);
        if (p.isBot()) {
            if (botTurn == null) {
                ShotPlanner planner = botSeats.planner(seat, p.bot(), game.world());
                if (planner == null) {
                    say.accept("no bot named " + p.bot() + "; " + p.name() + " cannot play");
                    return progress;
                }
                PlayerState s = game.player(seat);
                botTurn = new BotTurn(planner, game.world(), game.settings(), s.x(), s.y(), s.total(),
                        BotTurn.seed(game.botSeed(), round == null ? 0 : round.holeIndex(), game.history().size(), seat),
                        BotConditions.of(game, seat, hideFrictionFromBots));
                botThinking = 0;
            } else if ((botThinking += elapsed * timeScale) >= MIN_THINKING_SECONDS && botTurn.isDone()) {
                BotTurn done = botTurn;
                botTurn = null;
                if (done.shot() != null && done.waitSeconds() > 0) {
                    botShot = done.shot();
                    botMoment = game.clock() + done.waitSeconds();
                } else if (done.shot() != null) {
                    hit(done.shot()[0], done.shot()[1], done.shot()[2]);
                } else {
                    say.accept(p.name() + ": " + done.failure());
                    if ("cancelled".equals(done.failure())) return Progress.CANCELLED;
                }
            }
        } else if (!script.isEmpty()) {
            double[] v = script.poll();
            hit(v[0], v[1], v.length > 2 ? v[2] : 0);
        }
        return progress;
    }

    /** Plays a room on a game server from now on (its lobby first). */
    void startOnline(OnlinePlay room) {
        stopPlay();
        closeOnline();
        online = room;
        round = null;
        game = null;
    }

    /** Leaves the online room's connection (its seat is kept for a resume). */
    private void closeOnline() {
        if (online != null) online.close();
        online = null;
    }

    /** The online room being played, or null. */
    OnlinePlay online() {
        return online;
    }

    /** A server's stroke is waiting out its wait before it rolls (online). */
    boolean onlineStrokeWaiting() {
        return held != null;
    }

    /** The seat whose ball is rolling in the animation, or -1. */
    int rollingSeat() {
        if (rolling != null) return rolling.seat();
        return game != null && game.isShotInFlight() ? game.currentPlayer() : -1;
    }

    /**
     * One pass of online play: what the server sent is taken in; its strokes are animated one after
     * the other with the engine, each settled where the server put the ball; scripted strokes are
     * sent when it is this seat's turn. The next hole starts when the player leaves the hole's card.
     */
    private Progress advanceOnline(double elapsed, double timeScale) {
        online.poll();
        if (online.takeResync()) {
            animator = null;
            rolling = null;
            held = null;
            round = online.shown();
            if (round != null) {
                showHole();
                // A round that comes over already (a resume after the end): its card.
                if (round.isOver()) return Progress.OVER;
            }
        }
        if (round == null) return Progress.NONE;
        Progress progress = Progress.NONE;
        if (held != null) {
            // The stroke's wait runs on the room's clock before the ball is hit.
            heldLeft -= elapsed * timeScale;
            if (heldLeft > 0) return progress;
            startOnlineStroke();
            return progress;
        }
        if (animator != null) {
            animator.advance(elapsed, timeScale);
            if (!animator.isFinished()) return progress;
            minigolf.online.RoomEvent e = rolling;
            animator = null;
            rolling = null;
            lastStroke = e.stroke();
            boolean holeOver = settleOnline(e);
            // The same news as hot seat's, told on the settled game (where the server put the ball).
            say.accept(StrokeNews.of(lastStroke, game.player(e.seat()), game.players().get(e.seat()).name(),
                    game.players().size() > 1, round.hole().par(), world.hole().position().x(), world.hole().position().y()));
            if (holeOver) return Progress.OVER;
            progress = Progress.STROKE_ENDED;
        }
        minigolf.online.RoomEvent e = online.nextEvent();
        if (e != null && e.isPickUp()) {
            if (settleOnline(e)) return Progress.OVER;
        } else if (e != null) {
            held = e;
            heldLeft = e.waitSeconds();
            if (heldLeft <= 0) startOnlineStroke();
        } else if (!script.isEmpty() && online.canShoot()) {
            double[] v = script.poll();
            hit(v[0], v[1], v.length > 2 ? v[2] : 0);
        }
        return progress;
    }

    /** Animates the held server stroke from its start, at the course clock the server hit it at. */
    private void startOnlineStroke() {
        minigolf.online.RoomEvent e = held;
        held = null;
        ShotRecord r = e.stroke();
        TrajectoryListener listener = feedback == null ? null
                : feedback.stroke(game.world(), game.player(e.seat()).total() == 0, e.seat());
        animator = new StrokeAnimator(new minigolf.physics.Stroke(game.world(), game.settings(), r.startX(), r.startY(),
                r.vx(), r.vy(), r.vz(), r.clock(), listener, false), game.settings().dt());
        rolling = e;
        if (feedback != null) feedback.hit(Math.sqrt(r.vx() * r.vx() + r.vy() * r.vy() + r.vz() * r.vz()),
                game.world().physics().maxSpeed());
    }

    /** Settles a server event on the round shown; true when it ended the hole (its card is due). */
    private boolean settleOnline(minigolf.online.RoomEvent e) {
        round = online.settle(e);
        game = round.game();
        if (!game.isOver()) return false;
        files.recordScores(round, round.finishHole());
        return true;
    }

    /**
     * The course clock a stroke hit now would start at (moving obstacles: the aim guide shows that
     * stroke): the game's; online the room's clock as this client reckons it (the server hits the
     * stroke at its own reading when the shot arrives).
     */
    double shotClock() {
        if (online != null) return online.roomClock();
        return game == null ? 0 : game.clock();
    }

    /**
     * The course clock the 3D view shows (moving obstacles): the rolling stroke's; online, a held
     * stroke's clock less its wait yet, else the room's clock once everything the server sent is
     * shown; else the game's, or the session's time with no game.
     */
    double viewClock() {
        if (animator != null) return animator.clock();
        if (online != null) {
            if (held != null) return held.stroke().clock() - Math.max(0, heldLeft);
            if (online.caughtUp()) return online.roomClock();
        }
        return game == null ? idleClock() : game.clock();
    }

    /** The view's course clock when no game is played (seconds since the session began). */
    double idleClock() {
        return (System.nanoTime() - idleStart) * 1e-9;
    }

    /** Seconds until a bot's planned shot is hit, or NaN when none waits. */
    double botWaitLeft() {
        return botShot == null || game == null ? Double.NaN : Math.max(0, botMoment - game.clock());
    }

    /** Stops the bot thinking now (its Cancel button); the bots of this hole are asked afresh. */
    void cancelBot() {
        if (botTurn != null) botTurn.cancel();
        // A cancelled worker may still be ending: its bot must not be asked again.
        botSeats.clear();
    }

    /** The round's current hole is what is played and shown. */
    private void showHole() {
        game = round.game();
        world = game.world();
        coursePath = null;
    }

    /** A saved stroke still rolling goes on rolling. */
    private void resumeStroke() {
        animator = game.isShotInFlight() ? new StrokeAnimator(game.activeStroke(), game.settings().dt()) : null;
    }

    /** The bot thinking now stops and the rolling animation is dropped, a server's stroke still waiting too. */
    private void stopPlay() {
        cancelBot();
        botTurn = null;
        botShot = null;
        animator = null;
        rolling = null;
        held = null;
    }
}
