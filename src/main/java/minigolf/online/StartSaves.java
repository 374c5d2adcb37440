package minigolf.online;

import java.util.LinkedHashMap;
import java.util.Map;
import minigolf.game.RoundGame;
import minigolf.game.SaveGameException;
import minigolf.game.SavedRounds;

/**
 * Rounds as they start (a saved round's text, with every hole's course), read once per program
 * and handed out as copies: reading one builds every hole's course (about 0.1 s for nine holes),
 * while a room's clients and a restarting server's rooms on the same round share the text. The
 * courses (worlds) are shared, the round and its games are each caller's own.
 */
public final class StartSaves {
    private static final int KEPT = 32;
    private static final Map<String, RoundGame> READ = new LinkedHashMap<>(16, 0.75f, true) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, RoundGame> eldest) {
            return size() > KEPT;
        }
    };

    private StartSaves() {
    }

    /** The round {@code text} holds, as a round of its own (its games fresh, its courses shared). */
    public static RoundGame read(String text, String source) throws SaveGameException {
        RoundGame r;
        synchronized (READ) {
            r = READ.get(text);
        }
        if (r == null) {
            r = SavedRounds.parse(text, source);
            synchronized (READ) {
                READ.put(text, r);
            }
        }
        return RoundSync.copy(r);
    }
}
