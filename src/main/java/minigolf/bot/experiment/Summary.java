package minigolf.bot.experiment;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** Per course and bot: success rate, median and 90th-percentile simulations, median time and strokes. */
public final class Summary {
    /** One cell of the report's table. */
    public record Line(String course, String bot, int runs, double successRate, double holeInOneRate,
                       double medianSimulations, double p90Simulations, double medianMs, double medianStrokes) {
    }

    private Summary() {
    }

    public static List<Line> lines(List<RunRecord> records) {
        Map<String, List<RunRecord>> groups = new LinkedHashMap<>();
        for (RunRecord r : records) groups.computeIfAbsent(r.course() + "\u0000" + r.bot(), k -> new ArrayList<>()).add(r);
        List<Line> lines = new ArrayList<>();
        for (List<RunRecord> g : groups.values()) {
            int runs = g.size();
            double holed = g.stream().filter(RunRecord::holed).count();
            double aces = g.stream().filter(RunRecord::holeInOne).count();
            double[] sims = g.stream().mapToDouble(RunRecord::simulations).toArray();
            double[] ms = g.stream().mapToDouble(RunRecord::wallMs).toArray();
            double[] strokes = g.stream().mapToDouble(RunRecord::strokes).toArray();
            lines.add(new Line(g.get(0).course(), g.get(0).bot(), runs, holed / runs, aces / runs,
                    percentile(sims, 50), percentile(sims, 90), percentile(ms, 50), percentile(strokes, 50)));
        }
        return lines;
    }

    /** Nearest-rank percentile (p in 0..100) of the values. */
    public static double percentile(double[] values, double p) {
        if (values.length == 0) return Double.NaN;
        double[] sorted = values.clone();
        java.util.Arrays.sort(sorted);
        int rank = (int) Math.ceil(p / 100 * sorted.length);
        return sorted[Math.max(0, Math.min(sorted.length - 1, rank - 1))];
    }

    public static String markdown(List<Line> lines, int seeds, long budget, int maxStrokes) {
        StringBuilder md = new StringBuilder();
        md.append("# Bot experiment\n\n");
        md.append(String.format(Locale.ROOT, "%d seed(s) per course and bot; budget %d simulations per game; "
                + "at most %d strokes. Simulations count every simulated shot (probes, particles, look-ahead). "
                + "Holed = holed within the strokes; strokes include penalty strokes.%n%n", seeds, budget, maxStrokes));
        md.append("| course | bot | holed | hole-in-one | median sims | p90 sims | median ms | median strokes |\n");
        md.append("|---|---|---:|---:|---:|---:|---:|---:|\n");
        for (Line l : lines) {
            md.append(String.format(Locale.ROOT, "| %s | %s | %.0f%% | %.0f%% | %.0f | %.0f | %.1f | %.0f |%n",
                    l.course(), l.bot(), 100 * l.successRate(), 100 * l.holeInOneRate(), l.medianSimulations(),
                    l.p90Simulations(), l.medianMs(), l.medianStrokes()));
        }
        return md.toString();
    }
}
