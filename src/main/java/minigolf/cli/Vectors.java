package minigolf.cli;

/** Parses vectors typed on the command line, such as {@code 3.2,-0.5}. */
final class Vectors {
    private Vectors() {
    }

    static double[] parse(String option, String text, int components) {
        String[] parts = text.split(",", -1);
        if (parts.length != components) {
            throw new UserError(option + ": expected " + components + " comma-separated numbers, got '" + text + "'");
        }
        double[] values = new double[components];
        for (int i = 0; i < components; i++) {
            try {
                values[i] = Double.parseDouble(parts[i].trim());
            } catch (NumberFormatException e) {
                throw new UserError(option + ": '" + parts[i].trim() + "' is not a number");
            }
            if (!Double.isFinite(values[i])) {
                throw new UserError(option + ": components must be finite numbers, got '" + parts[i].trim() + "'");
            }
        }
        return values;
    }
}
