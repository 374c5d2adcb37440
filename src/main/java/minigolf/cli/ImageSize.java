package minigolf.cli;

import java.util.Locale;

/** A {@code WxH} option such as 1280x720, checked to lie between 16x16 and 8192x8192. */
record ImageSize(int width, int height) {
    static ImageSize parse(String option, String text) {
        String[] parts = text.toLowerCase(Locale.ROOT).split("x", -1);
        int w, h;
        try {
            if (parts.length != 2) throw new NumberFormatException();
            w = Integer.parseInt(parts[0].trim());
            h = Integer.parseInt(parts[1].trim());
        } catch (NumberFormatException e) {
            throw new UserError(option + ": expected WxH such as 1280x720, got '" + text + "'");
        }
        if (w < 16 || h < 16 || w > 8192 || h > 8192) {
            throw new UserError(option + ": expected WxH between 16x16 and 8192x8192, got '" + text + "'");
        }
        return new ImageSize(w, h);
    }
}
