package minigolf.bot.experiment;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** Per bot and noise cell, over every course of the suite: the rows of the noise tables and charts. */
public final class NoiseSummary {
    /** One bot under one noise cell, all courses together (each course weighs by its runs). */
    public record Cell(String bot, double noisePosition, double noiseVelocity, int runs, double successRate,
                       double meanStrokes) {
    }

    private NoiseSummary() {
    }

    public static List<Cell> cells(List<Summary.Line> lines) {
        Map<String, List<Summary.Line>> groups = new LinkedHashMap<>();
        for (Summary.Line l : lines) {
            groups.computeIfAbsent(l.bot() + "\u0000" + l.noisePosition() + "\u0000" + l.noiseVelocity(),
                    k -> new ArrayList<>()).add(l);
        }
        List<Cell> cells = new ArrayList<>();
        for (List<Summary.Line> g : groups.values()) {
            int runs = 0;
            double holed = 0, strokes = 0;
            for (Summary.Line l : g) {
                runs += l.runs();
                holed += l.successRate() * l.runs();
                strokes += l.meanStrokes() * l.runs();
            }
            Summary.Line first = g.get(0);
            cells.add(new Cell(first.bot(), first.noisePosition(), first.noiseVelocity(), runs, holed / runs, strokes / runs));
        }
        return cells;
    }

    public static String markdown(List<Cell> cells) {
        StringBuilder md = new StringBuilder("## Noise: every course together\n\n");
        md.append("Mean strokes include penalty strokes; a game not holed counts the strokes it took.\n\n");
        md.append("| bot | noise m | noise m/s | runs | holed | mean strokes |\n|---|---:|---:|---:|---:|---:|\n");
        for (Cell c : cells) {
            md.append(String.format(Locale.ROOT, "| %s | %s | %s | %d | %.1f%% | %.2f |%n", c.bot(), c.noisePosition(),
                    c.noiseVelocity(), c.runs(), 100 * c.successRate(), c.meanStrokes()));
        }
        return md.toString();
    }
}
