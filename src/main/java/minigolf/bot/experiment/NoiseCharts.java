package minigolf.bot.experiment;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.function.ToDoubleFunction;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;

/**
 * noise-holed.png and noise-strokes.png: one line per bot against the velocity noise (or against
 * the position noise when only that varies). With several values of the other noise, each bot has
 * one line per value ("robust, 0.01 m").
 */
final class NoiseCharts {
    private NoiseCharts() {
    }

    static List<Path> write(List<NoiseSummary.Cell> cells, Path directory) throws IOException {
        boolean byVelocity = new TreeSet<>(cells.stream().map(NoiseSummary.Cell::noiseVelocity).toList()).size() > 1
                || new TreeSet<>(cells.stream().map(NoiseSummary.Cell::noisePosition).toList()).size() == 1;
        List<Path> files = new ArrayList<>();
        files.add(Charts.save(chart("Holed (%) against noise, all courses", "holed (%)", cells, byVelocity,
                c -> 100 * c.successRate()), directory.resolve("noise-holed.png")));
        files.add(Charts.save(chart("Mean strokes against noise, all courses", "mean strokes", cells, byVelocity,
                NoiseSummary.Cell::meanStrokes), directory.resolve("noise-strokes.png")));
        return files;
    }

    private static XYChart chart(String title, String yTitle, List<NoiseSummary.Cell> cells, boolean byVelocity,
                                 ToDoubleFunction<NoiseSummary.Cell> value) {
        XYChart chart = new XYChartBuilder().width(1000).height(600).title(title)
                .xAxisTitle(byVelocity ? "velocity noise (m/s, per component)" : "position noise (m, per axis)")
                .yAxisTitle(yTitle).build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        boolean severalOthers = new TreeSet<>(cells.stream()
                .map(c -> byVelocity ? c.noisePosition() : c.noiseVelocity()).toList()).size() > 1;
        Map<String, List<double[]>> series = new LinkedHashMap<>();
        for (NoiseSummary.Cell c : cells) {
            double other = byVelocity ? c.noisePosition() : c.noiseVelocity();
            String name = severalOthers ? c.bot() + ", " + other + (byVelocity ? " m" : " m/s") : c.bot();
            series.computeIfAbsent(name, k -> new ArrayList<>())
                    .add(new double[]{byVelocity ? c.noiseVelocity() : c.noisePosition(), value.applyAsDouble(c)});
        }
        for (Map.Entry<String, List<double[]>> e : series.entrySet()) {
            List<double[]> points = e.getValue();
            points.sort((a, b) -> Double.compare(a[0], b[0]));
            chart.addSeries(e.getKey(), points.stream().mapToDouble(p -> p[0]).toArray(),
                    points.stream().mapToDouble(p -> p[1]).toArray());
        }
        return chart;
    }
}
