package minigolf.bot.experiment;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * One bot playing one course with one seed under one noise cell: a row of results.csv. The noise
 * columns are the standard deviations (position in m, velocity in m/s), written in Java's shortest
 * exact form so that a row read back matches its run exactly.
 */
public record RunRecord(String course, String bot, long seed, double noisePosition, double noiseVelocity, boolean holed,
                        int strokes, boolean holeInOne, long simulations, double wallMs) {
    public static final String CSV_HEADER =
            "course,bot,seed,noise_position,noise_velocity,holed,strokes,hole_in_one,simulations,wall_ms";
    private static final int FIELDS = 10;

    /** A run without noise. */
    public RunRecord(String course, String bot, long seed, boolean holed, int strokes, boolean holeInOne,
                     long simulations, double wallMs) {
        this(course, bot, seed, 0, 0, holed, strokes, holeInOne, simulations, wallMs);
    }

    public String csvRow() {
        return String.format(Locale.ROOT, "%s,%s,%d,%s,%s,%b,%d,%b,%d,%.3f",
                csv(course), csv(bot), seed, Double.toString(noisePosition), Double.toString(noiseVelocity), holed,
                strokes, holeInOne, simulations, wallMs);
    }

    /**
     * The inverse of {@link #csvRow()}: csvRow(parse(row)) == row for every row csvRow wrote.
     *
     * @throws IllegalArgumentException saying what is wrong with the row
     */
    public static RunRecord parse(String row) {
        List<String> f = split(row);
        if (f.size() != FIELDS) throw new IllegalArgumentException("expected " + FIELDS + " fields, found " + f.size());
        try {
            return new RunRecord(f.get(0), f.get(1), Long.parseLong(f.get(2)), Double.parseDouble(f.get(3)),
                    Double.parseDouble(f.get(4)), bool(f.get(5)), Integer.parseInt(f.get(6)), bool(f.get(7)),
                    Long.parseLong(f.get(8)), Double.parseDouble(f.get(9)));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("not a number: " + e.getMessage());
        }
    }

    private static boolean bool(String text) {
        if (text.equals("true")) return true;
        if (text.equals("false")) return false;
        throw new IllegalArgumentException("expected true or false, found '" + text + "'");
    }

    private static String csv(String text) {
        if (text.contains(",") || text.contains("\"")) return "\"" + text.replace("\"", "\"\"") + "\"";
        return text;
    }

    /** Splits a row at commas outside double quotes; "" inside quotes is one quote. */
    static List<String> split(String row) {
        List<String> fields = new ArrayList<>();
        StringBuilder field = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < row.length(); i++) {
            char c = row.charAt(i);
            if (quoted) {
                if (c != '"') {
                    field.append(c);
                } else if (i + 1 < row.length() && row.charAt(i + 1) == '"') {
                    field.append('"');
                    i++;
                } else {
                    quoted = false;
                }
            } else if (c == '"' && field.length() == 0) {
                quoted = true;
            } else if (c == ',') {
                fields.add(field.toString());
                field.setLength(0);
            } else {
                field.append(c);
            }
        }
        if (quoted) throw new IllegalArgumentException("a quoted field is not closed");
        fields.add(field.toString());
        return fields;
    }
}
