package minigolf.bot.experiment;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Per course, bot and noise cell: success rate, median and 90th-percentile simulations, median
 * time and strokes. The noise columns appear only when some run had noise.
 */
public final class Summary {
    /** One cell of the report's table. */
    public record Line(String course, String bot, double noisePosition, double noiseVelocity, int runs,
                       double successRate, double holeInOneRate, double medianSimulations, double p90Simulations,
                       double medianMs, double medianStrokes, double meanStrokes) {
        public boolean noiseless() {
            return noisePosition == 0 && noiseVelocity == 0;
        }
    }

    private Summary() {
    }

    public static List<Line> lines(List<RunRecord> records) {
        Map<String, List<RunRecord>> groups = new LinkedHashMap<>();
        for (RunRecord r : records) {
            String key = r.course() + "\u0000" + r.bot() + "\u0000" + r.noisePosition() + "\u0000" + r.noiseVelocity();
            groups.computeIfAbsent(key, k -> new ArrayList<>()).add(r);
        }
        List<Line> lines = new ArrayList<>();
        for (List<RunRecord> g : groups.values()) {
            int runs = g.size();
            double holed = g.stream().filter(RunRecord::holed).count();
            double aces = g.stream().filter(RunRecord::holeInOne).count();
            double[] sims = g.stream().mapToDouble(RunRecord::simulations).toArray();
            double[] ms = g.stream().mapToDouble(RunRecord::wallMs).toArray();
            double[] strokes = g.stream().mapToDouble(RunRecord::strokes).toArray();
            RunRecord first = g.get(0);
            lines.add(new Line(first.course(), first.bot(), first.noisePosition(), first.noiseVelocity(), runs,
                    holed / runs, aces / runs, percentile(sims, 50), percentile(sims, 90), percentile(ms, 50),
                    percentile(strokes, 50), java.util.Arrays.stream(strokes).average().orElse(Double.NaN)));
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
        boolean noise = lines.stream().anyMatch(l -> !l.noiseless());
        md.append(noise ? "| course | bot | noise m | noise m/s |" : "| course | bot |")
                .append(" holed | hole-in-one | median sims | p90 sims | median ms | median strokes |\n");
        md.append(noise ? "|---|---|---:|---:|" : "|---|---|").append("---:|---:|---:|---:|---:|---:|\n");
        for (Line l : lines) {
            md.append(String.format(Locale.ROOT, "| %s | %s |", l.course(), l.bot()));
            if (noise) md.append(String.format(Locale.ROOT, " %s | %s |", l.noisePosition(), l.noiseVelocity()));
            md.append(String.format(Locale.ROOT, " %.0f%% | %.0f%% | %.0f | %.0f | %.1f | %.0f |%n",
                    100 * l.successRate(), 100 * l.holeInOneRate(), l.medianSimulations(),
                    l.p90Simulations(), l.medianMs(), l.medianStrokes()));
        }
        if (noise) md.append('\n').append(NoiseSummary.markdown(NoiseSummary.cells(lines)));
        return md.toString();
    }
}
