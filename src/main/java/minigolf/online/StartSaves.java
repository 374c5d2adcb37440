package minigolf.online;

import java.util.LinkedHashMap;
import java.util.Map;
import minigolf.course.CourseException;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.game.SavedRounds;
import minigolf.physics.World;

/**
 * Rounds as they start (a saved round's text, with every hole's course), read once per program
 * and handed out as copies: reading one builds every hole's course (about 0.1 s for nine holes),
 * while a room's clients and a restarting server's rooms on the same round share the text. The
 * courses (worlds) are shared, the round and its games are each caller's own.
 *
 * <p>Rooms on the same course have different texts (their players' names), so each hole's world
 * is also kept by its definition's text: a server's 250 rooms on one round, or a benchmark's
 * 1,000 clients in one program, hold its nine worlds once instead of 2,250 or 9,000 times (a
 * world's terrain grid and collision cells are about 0.4 MB; 9,000 of them kept the benchmark's
 * clients in back-to-back garbage collections). Worlds are immutable. The sources given here are
 * labels (a room's code), so models resolve in the working folder whichever room reads first.
 */
public final class StartSaves {
    private static final int KEPT = 32;
    private static final Map<String, RoundGame> READ = recentlyUsed(KEPT);

    private static final int KEPT_WORLDS = 64;
    private static final Map<String, World> WORLDS = recentlyUsed(KEPT_WORLDS);

    private StartSaves() {
    }

    /** A map that keeps only its {@code kept} most recently used entries (callers synchronise on it). */
    private static <V> Map<String, V> recentlyUsed(int kept) {
        return new LinkedHashMap<>(16, 0.75f, true) {
            @Override
            protected boolean removeEldestEntry(Map.Entry<String, V> eldest) {
                return size() > kept;
            }
        };
    }

    /** The round {@code text} holds, as a round of its own (its games fresh, its courses shared). */
    public static RoundGame read(String text, String source) throws SaveGameException {
        RoundGame r;
        synchronized (READ) {
            r = READ.get(text);
        }
        if (r == null) {
            r = SavedRounds.parse(text, source, StartSaves::world);
            synchronized (READ) {
                READ.put(text, r);
            }
        }
        return RoundSync.copy(r);
    }

    /** The world a hole's definition describes, read once for every round that holds the same definition. */
    static World world(String definition, String source) throws CourseException {
        World w;
        synchronized (WORLDS) {
            w = WORLDS.get(definition);
        }
        if (w == null) {
            w = World.parse(definition, source);
            synchronized (WORLDS) {
                WORLDS.put(definition, w);
            }
        }
        return w;
    }
}
