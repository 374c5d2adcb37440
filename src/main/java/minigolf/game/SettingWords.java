package minigolf.game;

import com.fasterxml.jackson.databind.JsonNode;
import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The settings in a player's words: the name a player knows each setting by and what it may be,
 * in the units the game shows (ms, cm, pixels, true/false), so a broken setting reads "The expert
 * setting "dt" (the physics step) is almost 0 ms; it must be 1 to 33 ms (1/1000 to 1/30 of a second)." where the file's own
 * line (for the terminal) says "dt: must be 1/1000 to 1/30 s (0.001 to 0.0333), got 4.9E-324".
 * No raw doubles and no file paths.
 */
final class SettingWords {
    /** How a player knows one setting: its name, what it may be, and how a number of it is shown. */
    private record Words(String name, String allowed, double scale, String unit) {
    }

    private static final String ON_OFF = "true (on) or false (off)";
    private static final Map<String, Words> WORDS = Map.ofEntries(
            // Physics is no player's setting (the editor's and the command line's): named as the file has
            // it, so a player who edited the file finds it, and called expert, since Settings never shows it.
            Map.entry("integrator", new Words("The expert setting \"integrator\" (the physics method)", "euler, rk2 or rk4", 1, "")),
            Map.entry("dt", new Words("The expert setting \"dt\" (the physics step)", "1 to 33 ms (1/1000 to 1/30 of a second)", 1000, " ms")),
            Map.entry("vsync", new Words("Vsync", ON_OFF, 1, "")),
            Map.entry("frameLimit", new Words("The frame limit", "a whole number from 0 (no limit) to 1000 frames a second", 1, "")),
            Map.entry("fullscreen", new Words("Full screen", ON_OFF, 1, "")),
            Map.entry("mouseSpeed", new Words("The mouse speed", "0.1 to 10 times the normal speed", 1, " times the normal speed")),
            Map.entry("strokeLimit", new Words("The stroke limit",
                    "a whole number from 1 to " + Game.MAX_STROKE_LIMIT + " strokes a hole", 1, "")),
            Map.entry("heightColours", new Words("Height colours", ON_OFF, 1, "")),
            Map.entry("playerNames", new Words("The player names list", "1 to " + Game.MAX_PLAYERS + " names of 1 to "
                    + Player.MAX_NAME_LENGTH + " characters", 1, "")),
            Map.entry("noisePosition", new Words("Realistic play's spread of a stroke's start",
                    "0 to " + amount(UserSettings.MAX_NOISE_POSITION * 100) + " cm", 100, " cm")),
            Map.entry("noiseVelocity", new Words("Realistic play's spread of a stroke's pace",
                    "0 to " + amount(UserSettings.MAX_NOISE_VELOCITY) + " m/s", 1, " m/s")),
            Map.entry("hideFrictionFromBots", new Words("Hide friction from bots", ON_OFF, 1, "")),
            Map.entry("aimGuide", new Words("The aim guide", ON_OFF, 1, "")),
            Map.entry("antiAliasing", new Words("Smooth edges", ON_OFF, 1, "")),
            Map.entry("graphics", new Words("The graphics quality", "auto, high or low", 1, "")),
            Map.entry("windowWidth", new Words("The window size",
                    "640 to 16384 by 480 to 16384 pixels, or 0 x 0 for the default 1280 x 720", 1, "")),
            Map.entry("practice", new Words("Practice mode", ON_OFF, 1, "")),
            Map.entry("classicFolder", new Words("The classic tracks folder",
                    "a folder name of at most " + UserSettings.MAX_FOLDER_LENGTH + " characters", 1, "")));
    private static final Pattern WHERE = Pattern.compile("at (line \\d+, column \\d+)");

    private SettingWords() {
    }

    /** "The frame limit is 2000; it must be a whole number from 0 (no limit) to 1000 frames a second." */
    static String sentence(String field, String shownValue) {
        Words w = words(field);
        return w.name() + " is " + shownValue + "; it must be " + w.allowed() + ".";
    }

    /** A number of the setting as a player reads it, in the setting's unit ("almost 0 ms", "8.33 ms", "over a million"). */
    static String shown(String field, double value) {
        Words w = words(field);
        return amount(value * w.scale()) + w.unit();
    }

    /** A value from the settings file as a player reads it. */
    static String shown(String field, JsonNode v) {
        if (v == null || v.isNull()) return "empty (null)";
        if (v.isBoolean()) return String.valueOf(v.booleanValue());
        if (v.isNumber()) return shown(field, v.doubleValue());
        if (v.isTextual()) {
            // A folder is a path: its length says what is wrong without showing where it is.
            return field.equals("classicFolder") ? "a name of " + v.textValue().length() + " characters" : JsonFields.shown(v.textValue());
        }
        if (v.isArray() && field.equals("playerNames")) return names(v);
        return v.isArray() ? "a list" : "a group of values";
    }

    /**
     * What is wrong with the settings file, in a player's words, from the file's own error and its
     * parsed text (null when it did not parse): one sentence that names the setting, what it may be
     * and what the file has, or what is wrong with the file as a whole.
     */
    static String explain(SaveGameException e, JsonNode root) {
        String path = e.path(), problem = e.problem();
        if (path == null || root == null) return fileProblem(problem);
        String field = path.replaceFirst("\\[\\d+]$", "");
        if (problem.startsWith("unknown field")) return "It has a setting this game does not know: " + JsonFields.shown(field) + ".";
        if (!WORDS.containsKey(field) && !field.equals("windowHeight")) return fileProblem(problem);
        JsonNode value = path.equals(field) ? root.get(field) : root.path(field).get(Integer.parseInt(path.replaceAll("\\D", "")));
        if (field.startsWith("window")) return sentence("windowWidth", windowSize(root));
        if (!path.equals(field)) return words(field).name() + " holds " + shown(field, value) + "; it must be " + words(field).allowed() + ".";
        return sentence(field, shown(field, value));
    }

    /** The window size in the file, "300 x 200 pixels" (a side the file leaves out is 0, the default's). */
    static String windowSize(JsonNode root) {
        return side(root.get("windowWidth")) + " x " + side(root.get("windowHeight")) + " pixels";
    }

    private static String side(JsonNode v) {
        return v == null ? "0" : v.isNumber() ? amount(v.doubleValue()) : shown("windowWidth", v);
    }

    /** The first thing wrong with a list of names: none, too many, an empty or a too long one. */
    private static String names(JsonNode a) {
        if (a.isEmpty()) return "empty";
        if (a.size() > Game.MAX_PLAYERS) return a.size() + " names";
        for (JsonNode n : a) {
            if (n.isTextual() && n.textValue().isBlank()) return "a list with an empty name";
            if (n.isTextual() && n.textValue().length() > Player.MAX_NAME_LENGTH) {
                return "a list with a name of " + n.textValue().length() + " characters";
            }
        }
        return a.size() + " names";
    }

    /** A problem with the file as a whole: it could not be read, is not JSON, or holds no settings object. */
    private static String fileProblem(String problem) {
        if (problem.startsWith("cannot read: ")) return "It could not be read (" + problem.substring("cannot read: ".length()) + ").";
        if (problem.startsWith("not valid JSON")) {
            Matcher where = WHERE.matcher(problem);
            if (where.find()) return "Its text is broken at " + where.group(1) + " (it is not valid JSON).";
            if (problem.contains("empty") || problem.contains("whitespace")) return "It is empty.";
            return "Its text is not valid JSON.";
        }
        if (problem.startsWith("must be an object")) return "It holds no settings (its text must be one JSON object, { ... }).";
        return "It could not be read (" + problem + ").";
    }

    private static Words words(String field) {
        Words w = WORDS.get(field);
        if (w == null) throw new IllegalArgumentException("no words for the setting " + field);
        return w;
    }

    /**
     * A number for a player: whole from 1000 on, else at most three significant digits; no exponent,
     * "almost 0" and "over a million" at the ends.
     */
    static String amount(double x) {
        if (x == 0) return "0";
        if (Double.isNaN(x)) return "not a number";
        if (Math.abs(x) < 0.01) return "almost 0";
        if (Math.abs(x) >= 1e6) return x > 0 ? "over a million" : "below minus a million";
        if (Math.abs(x) >= 1000) return Long.toString(Math.round(x));
        return new BigDecimal(x).round(new MathContext(3)).stripTrailingZeros().toPlainString();
    }
}
