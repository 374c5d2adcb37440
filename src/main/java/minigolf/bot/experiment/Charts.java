package minigolf.bot.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.ToDoubleFunction;
import minigolf.io.AtomicFile;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.style.Styler;

/**
 * The experiment's PNG charts (XChart, drawn with AWT off-screen: the JVM must run headless, and
 * never in the game's GL process).
 */
public final class Charts {
    private Charts() {
    }

    /**
     * Writes simulations.png (median simulations, log scale) and success.png (success rate) for the
     * first noise cell, and noise-holed.png and noise-strokes.png ({@link NoiseCharts}).
     */
    public static List<Path> write(List<Summary.Line> all, Path directory) throws IOException {
        System.setProperty("java.awt.headless", "true");
        List<Path> files = new ArrayList<>();
        // The bar charts have one bar per course and bot: the first noise cell's (no noise, usually).
        Summary.Line firstCell = all.get(0);
        List<Summary.Line> lines = all.stream().filter(l -> l.noisePosition() == firstCell.noisePosition()
                && l.noiseVelocity() == firstCell.noiseVelocity()).toList();
        // XChart's bar charts refuse a logarithmic axis here, so the bars show log10 directly.
        files.add(save(chart("Median simulations per course and bot, as log10(1 + n): 1 = 9, 2 = 99, 3 = 999",
                "log10(1 + median simulations)", lines, l -> Math.log10(1 + l.medianSimulations())),
                directory.resolve("simulations.png")));
        files.add(save(chart("Success rate per course and bot", "holed (%)", lines, l -> 100 * l.successRate()),
                directory.resolve("success.png")));
        files.addAll(NoiseCharts.write(NoiseSummary.cells(all), directory));
        return files;
    }

    private static CategoryChart chart(String title, String yTitle, List<Summary.Line> lines,
                                       ToDoubleFunction<Summary.Line> value) {
        Set<String> courses = new LinkedHashSet<>(), bots = new LinkedHashSet<>();
        for (Summary.Line l : lines) {
            courses.add(l.course());
            bots.add(l.bot());
        }
        CategoryChart chart = new CategoryChartBuilder().width(1400).height(700).title(title)
                .xAxisTitle("course").yAxisTitle(yTitle).build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setXAxisLabelRotation(20);
        chart.getStyler().setAvailableSpaceFill(0.9);
        List<String> courseList = new ArrayList<>(courses);
        for (String bot : bots) {
            List<Double> ys = new ArrayList<>();
            for (String course : courseList) {
                double y = 0;
                for (Summary.Line l : lines) {
                    if (l.course().equals(course) && l.bot().equals(bot)) y = value.applyAsDouble(l);
                }
                ys.add(y);
            }
            chart.addSeries(bot, courseList, ys);
        }
        return chart;
    }

    static Path save(org.knowm.xchart.internal.chartpart.Chart<?, ?> chart, Path file) throws IOException {
        byte[] png = BitmapEncoder.getBitmapBytes(chart, BitmapEncoder.BitmapFormat.PNG);
        AtomicFile.write(file, png);
        return file;
    }
}
