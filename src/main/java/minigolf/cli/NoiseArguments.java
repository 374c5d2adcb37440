package minigolf.cli;

import java.util.ArrayList;
import java.util.List;
import minigolf.bot.NoiseModel;

/** {@code --noise-position} and {@code --noise-velocity}: one value, or a comma list on experiment. */
final class NoiseArguments {
    private NoiseArguments() {
    }

    static NoiseModel model(double position, double velocity) {
        check("--noise-position", position);
        check("--noise-velocity", velocity);
        return new NoiseModel(position, velocity);
    }

    /** A comma list of standard deviations, in the order given, repeats dropped. */
    static List<Double> list(String option, String text) {
        List<Double> values = new ArrayList<>();
        for (String part : text.split(",", -1)) {
            String t = part.trim();
            double v;
            try {
                v = Double.parseDouble(t);
            } catch (NumberFormatException e) {
                throw new UserError(option + ": not a number: '" + t + "'");
            }
            check(option, v);
            v += 0.0; // -0 is 0: one cell, the same fingerprint
            if (!values.contains(v)) values.add(v);
        }
        return values;
    }

    private static void check(String option, double sigma) {
        if (!(sigma >= 0 && sigma <= NoiseModel.MAX_SIGMA)) {
            throw new UserError(option + ": must be a standard deviation from 0 to " + NoiseModel.MAX_SIGMA + ", got " + sigma);
        }
    }
}
