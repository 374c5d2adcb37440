package minigolf.online;

import java.util.ArrayList;
import java.util.List;
import minigolf.game.Game;
import minigolf.game.GameState;
import minigolf.game.PlayerState;
import minigolf.game.RoundGame;
import minigolf.game.ShotRecord;

/**
 * Brings a round up to date with the server's events without simulating them: the seat's ball and
 * count become what the event says, its stroke joins the hole's history, and a finished hole goes
 * on the card as the server's does. The clients settle every stroke this way and the server
 * rebuilds its rooms from the database this way, so a restored room cannot drift from the one
 * that was played, whatever engine version replays it.
 */
public final class RoundSync {
    private RoundSync() {
    }

    /** The round after {@code event}; {@code round} itself is left as it was. */
    public static RoundGame apply(RoundGame round, RoomEvent event) {
        RoundGame out = applyOnly(round, event);
        advance(out);
        return out;
    }

    /**
     * As {@link #apply} but a hole the event finishes stays open (not yet on the card): the game
     * window shows the hole's card first and starts the next hole when the player goes on.
     */
    public static RoundGame applyOnly(RoundGame round, RoomEvent event) {
        if (round.isOver()) throw new IllegalStateException("the round is over; event " + event.seq() + " does not fit");
        if (event.hole() != round.holeIndex()) {
            throw new IllegalStateException("event " + event.seq() + " is on hole " + (event.hole() + 1) + ", the round is on hole "
                    + (round.holeIndex() + 1));
        }
        Game game = round.game();
        GameState s = game.state();
        if (!s.states().get(event.seat()).isPlaying()) {
            throw new IllegalStateException("event " + event.seq() + ": seat " + event.seat() + " is no longer playing");
        }
        List<PlayerState> states = new ArrayList<>(s.states());
        states.set(event.seat(), event.after());
        List<ShotRecord> history = new ArrayList<>(s.history());
        if (event.stroke() != null) history.add(event.stroke());
        // The course clock where the server's stands after the stroke (a client does not simulate it).
        double clock = event.stroke() != null ? event.clockAfter() : s.clock();
        Game next = Game.restore(game.world(), new GameState(s.settings(), s.players(), s.strokeLimit(), states, history,
                null, s.noise(), s.noiseSeed(), clock, s.botSeed()));
        for (int i = 0; i < s.players().size(); i++) next.passOver(i, game.isPassedOver(i));
        List<List<ShotRecord>> done = new ArrayList<>();
        for (int h = 0; h < round.holesFinished(); h++) done.add(round.holeStrokes(h));
        return RoundGame.restore(round.round(), round.finishedScores(), done, next);
    }

    /** A round of its own in the same state: its games new, its courses (and the round's holes) shared. */
    public static RoundGame copy(RoundGame round) {
        Game game = round.game();
        Game g = Game.restore(game.world(), game.state());
        for (int i = 0; i < game.players().size(); i++) g.passOver(i, game.isPassedOver(i));
        List<List<ShotRecord>> done = new ArrayList<>();
        for (int h = 0; h < round.holesFinished(); h++) done.add(round.holeStrokes(h));
        return RoundGame.restore(round.round(), round.finishedScores(), done, g);
    }

    /** Puts a finished hole on the card and starts the next one, as the server does after every event. */
    public static void advance(RoundGame round) {
        if (round.isHoleOver()) {
            round.finishHole();
            round.nextHole();
        }
    }
}
