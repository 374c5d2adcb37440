package minigolf.game;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A round's card: the par of every hole and each player's score on the holes finished so far.
 * Totals compare with the par of the same holes, so "+1" after three holes means one over the par
 * of those three. Ranks: the lowest total first; equal totals share a rank (and a win).
 */
public record RoundScorecard(String roundName, int[] pars, List<Row> rows, boolean over) {
    /** One player's line: scores of the finished holes in order. */
    public record Row(String name, int[] holes) {
        public int total() {
            int t = 0;
            for (int s : holes) t += s;
            return t;
        }
    }

    public RoundScorecard {
        pars = pars.clone();
        rows = List.copyOf(rows);
    }

    /** Holes on the card. */
    public int holesPlayed() {
        return rows.isEmpty() ? 0 : rows.get(0).holes().length;
    }

    /** The par of the holes played so far. */
    public int parPlayed() {
        int p = 0;
        for (int h = 0; h < holesPlayed(); h++) p += pars[h];
        return p;
    }

    public int totalPar() {
        int p = 0;
        for (int x : pars) p += x;
        return p;
    }

    /** A player's total against the par of the holes played: negative under, positive over. */
    public int toPar(int seat) {
        return rows.get(seat).total() - parPlayed();
    }

    /** Rank of a seat, 1 = best; equal totals share it. */
    public int rank(int seat) {
        int r = 1;
        for (Row o : rows) if (o.total() < rows.get(seat).total()) r++;
        return r;
    }

    /** The seats with the lowest total (several on a tie); empty until the round is over. */
    public List<Integer> winners() {
        List<Integer> w = new ArrayList<>();
        if (!over) return w;
        for (int s = 0; s < rows.size(); s++) if (rank(s) == 1) w.add(s);
        return w;
    }

    /** "E" for even, "-2", "+3". */
    public static String formatToPar(int toPar) {
        return toPar == 0 ? "E" : (toPar > 0 ? "+" : "") + toPar;
    }

    /** A plain-text card: a column per hole, the par row, a row per player with total and to-par. */
    public String toText() {
        StringBuilder sb = new StringBuilder(roundName).append(over ? " (final)" : " (after " + holesPlayed() + " of " + pars.length + ")").append('\n');
        sb.append(String.format(Locale.ROOT, "%-24s", "hole"));
        for (int h = 0; h < pars.length; h++) sb.append(String.format(Locale.ROOT, "%3d", h + 1));
        sb.append("  total  par\n").append(String.format(Locale.ROOT, "%-24s", "par"));
        for (int p : pars) sb.append(String.format(Locale.ROOT, "%3d", p));
        sb.append(String.format(Locale.ROOT, "  %5d%n", totalPar()));
        for (int s = 0; s < rows.size(); s++) {
            Row r = rows.get(s);
            sb.append(String.format(Locale.ROOT, "%-24s", r.name()));
            for (int h = 0; h < pars.length; h++) sb.append(h < r.holes().length ? String.format(Locale.ROOT, "%3d", r.holes()[h]) : "  .");
            sb.append(String.format(Locale.ROOT, "  %5d  %3s%n", r.total(), formatToPar(toPar(s))));
        }
        List<Integer> w = winners();
        if (!w.isEmpty()) {
            sb.append(w.size() == 1 ? "winner: " : "tied: ");
            sb.append(String.join(", ", w.stream().map(s -> rows.get(s).name()).toList())).append('\n');
        }
        return sb.toString();
    }
}
