package minigolf.io;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;

/**
 * A JSON syntax error in our words, one line: where it is and what Jackson found wrong, with the
 * file's own words left out. Jackson quotes a word it does not know whole ("Unrecognized token
 * 'root'"): from a file that is not JSON at all (a system file a hostile round or course names)
 * that would show the file's content.
 */
public final class JsonSyntax {
    private JsonSyntax() {
    }

    /** "not valid JSON at line 3, column 7: Unrecognized token: was expecting ..." */
    public static String problem(JsonProcessingException e) {
        JsonLocation loc = e.getLocation();
        String where = loc != null && loc.getLineNr() > 0 ? " at line " + loc.getLineNr() + ", column " + loc.getColumnNr() : "";
        return "not valid JSON" + where + ": " + withoutContent(firstLine(e.getOriginalMessage()));
    }

    /** Quoted words of two characters or more are dropped, but for JSON's own (null, true, false). */
    static String withoutContent(String message) {
        return message.replaceAll(" ?'(?!(?:null|true|false)')[^']{2,}'", "").replaceAll(" ?\"[^\"]{2,}\"", "");
    }

    private static String firstLine(String s) {
        if (s == null) return "";
        int nl = s.indexOf('\n');
        return (nl >= 0 ? s.substring(0, nl) : s).trim();
    }
}
