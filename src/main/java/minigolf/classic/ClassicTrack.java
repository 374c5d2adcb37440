package minigolf.classic;

import java.util.List;
import java.util.Set;

/**
 * One track of the original game, as its file describes it.
 *
 * @param version    the file's {@code V} line (1, or 2 and later)
 * @param categories from the {@code C} line (V2) or the folder (V1); may be empty
 * @param stats      the {@code I} line, or null when the file has none
 * @param firstBest  the {@code B} line's player, or null
 * @param ratings    the {@code R} line's 11 counts (ratings 0 to 10), or null
 * @param settings   the {@code S} line (6 characters, e.g. {@code fttt14}), or the original's default
 * @param tiles      the 49 x 25 tile codes
 */
public record ClassicTrack(int version, String author, String name, Set<TrackCategory> categories,
                           TrackStats stats, String firstBest, List<Integer> ratings, String settings,
                           TileMap tiles) {
    /** The original's settings when a file has no {@code S} line: mines hidden, magnets shown, teleports coloured, shadows. */
    public static final String DEFAULT_SETTINGS = "fttt14";

    public ClassicTrack {
        categories = Set.copyOf(categories);
        ratings = ratings == null ? null : List.copyOf(ratings);
    }
}
