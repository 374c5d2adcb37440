package minigolf.bot.experiment;

/** One bot playing one course with one seed: a row of results.csv. */
public record RunRecord(String course, String bot, long seed, boolean holed, int strokes, boolean holeInOne,
                        long simulations, double wallMs) {
    public static final String CSV_HEADER = "course,bot,seed,holed,strokes,hole_in_one,simulations,wall_ms";

    public String csvRow() {
        return String.format(java.util.Locale.ROOT, "%s,%s,%d,%b,%d,%b,%d,%.3f",
                csv(course), csv(bot), seed, holed, strokes, holeInOne, simulations, wallMs);
    }

    private static String csv(String text) {
        if (text.contains(",") || text.contains("\"")) return "\"" + text.replace("\"", "\"\"") + "\"";
        return text;
    }
}
