package minigolf.game;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/** The scorecard: one line per player in seat order, each with its rank (1 = best; equal scores share a rank). */
public record Scorecard(List<ScoreLine> lines) {
    public Scorecard {
        lines = List.copyOf(lines);
    }

    static Scorecard of(List<Player> players, List<PlayerState> states, int strokeLimit) {
        int n = players.size();
        int[] scores = new int[n];
        for (int i = 0; i < n; i++) {
            PlayerState s = states.get(i);
            scores[i] = s.status() == PlayerStatus.PICKED_UP ? strokeLimit + 1 : s.total();
        }
        List<ScoreLine> lines = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            int rank = 1;
            for (int j = 0; j < n; j++) if (scores[j] < scores[i]) rank++;
            PlayerState s = states.get(i);
            lines.add(new ScoreLine(players.get(i).name(), s.strokes(), s.penalties(), s.status(), scores[i], rank));
        }
        return new Scorecard(lines);
    }

    /** The lines best first (seat order among equals). */
    public List<ScoreLine> ranked() {
        List<ScoreLine> sorted = new ArrayList<>(lines);
        sorted.sort(Comparator.comparingInt(ScoreLine::rank));
        return sorted;
    }

    /** A plain-text table, e.g. for the console or a log. */
    public String toText() {
        StringBuilder sb = new StringBuilder(String.format(Locale.ROOT, "%-4s %-24s %7s %9s %5s  %s%n",
                "rank", "player", "strokes", "penalties", "score", "status"));
        for (ScoreLine l : ranked()) {
            sb.append(String.format(Locale.ROOT, "%-4d %-24s %7d %9d %5d  %s%n",
                    l.rank(), l.name(), l.strokes(), l.penalties(), l.score(), l.status().jsonName()));
        }
        return sb.toString();
    }
}
