package minigolf.expr;

/**
 * Splits source text into tokens on demand, so the first offending character is the one reported.
 * Only ASCII letters, digits, the operators, parentheses, commas and whitespace are accepted.
 */
final class Lexer {

    enum Kind { NUMBER, NAME, PLUS, MINUS, STAR, SLASH, CARET, OPEN, CLOSE, COMMA, END }

    /** {@code column} is 1-based; {@code value} is set for numbers only. */
    record Token(Kind kind, String text, int column, double value) {
        String describe() {
            return kind == Kind.END ? "end of input" : "'" + Lexer.abbreviate(text) + "'";
        }
    }

    private static final int MAX_SHOWN_LENGTH = 40;

    private final String source;
    private int position;

    Lexer(String source) {
        this.source = source;
    }

    /** Whether the next non-blank character is '(' (tells function calls from plain names). */
    boolean nextIsOpenParenthesis() {
        int at = position;
        while (at < source.length() && isBlank(source.charAt(at))) {
            at++;
        }
        return at < source.length() && source.charAt(at) == '(';
    }

    Token next() {
        while (position < source.length() && isBlank(source.charAt(position))) {
            position++;
        }
        int start = position;
        if (start >= source.length()) {
            return new Token(Kind.END, "", start + 1, 0);
        }
        char c = source.charAt(start);
        if (isDigit(c) || (c == '.' && start + 1 < source.length() && isDigit(source.charAt(start + 1)))) {
            return number(start);
        }
        if (isLetter(c)) {
            position++;
            while (position < source.length()
                    && (isLetter(source.charAt(position)) || isDigit(source.charAt(position)))) {
                position++;
            }
            return new Token(Kind.NAME, source.substring(start, position), start + 1, 0);
        }
        Kind kind = symbolKind(c);
        if (kind == null) {
            throw new ExpressionException("unexpected character " + quoteCharacter(c), start + 1,
                    "allowed: numbers, x, y, pi, e, + - * / ^, functions, parentheses and commas");
        }
        position++;
        return new Token(kind, String.valueOf(c), start + 1, 0);
    }

    private Token number(int start) {
        skipDigits();
        if (position < source.length() && source.charAt(position) == '.') {
            position++;
            skipDigits();
        }
        if (position < source.length() && (source.charAt(position) == 'e' || source.charAt(position) == 'E')) {
            position++;
            if (position < source.length() && (source.charAt(position) == '+' || source.charAt(position) == '-')) {
                position++;
            }
            if (position >= source.length() || !isDigit(source.charAt(position))) {
                throw new ExpressionException("malformed number '" + abbreviate(source.substring(start, position)) + "'",
                        position + 1, "an exponent needs digits, as in 1e-3");
            }
            skipDigits();
        }
        String text = source.substring(start, position);
        // The text matches Java's decimal syntax, so parseDouble cannot fail; overflow gives Infinity.
        double value = Double.parseDouble(text);
        if (Double.isInfinite(value)) {
            throw new ExpressionException("number out of range '" + abbreviate(text) + "'", start + 1,
                    "largest allowed is about 1.7e308");
        }
        return new Token(Kind.NUMBER, text, start + 1, value);
    }

    private void skipDigits() {
        while (position < source.length() && isDigit(source.charAt(position))) {
            position++;
        }
    }

    private static Kind symbolKind(char c) {
        switch (c) {
            case '+': return Kind.PLUS;
            case '-': return Kind.MINUS;
            case '*': return Kind.STAR;
            case '/': return Kind.SLASH;
            case '^': return Kind.CARET;
            case '(': return Kind.OPEN;
            case ')': return Kind.CLOSE;
            case ',': return Kind.COMMA;
            default: return null;
        }
    }

    private static boolean isBlank(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** ASCII only: other alphabets could hide look-alike names. */
    private static boolean isLetter(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    }

    /** Shows printable ASCII as itself and anything else as a \\u escape, so messages stay readable. */
    static String quoteCharacter(char c) {
        if (c >= 0x20 && c < 0x7f) {
            return "'" + c + "'";
        }
        return String.format("'\\u%04x'", (int) c);
    }

    /** Keeps attacker-sized names and numbers out of error messages. */
    static String abbreviate(String text) {
        return text.length() <= MAX_SHOWN_LENGTH ? text : text.substring(0, MAX_SHOWN_LENGTH) + "...";
    }
}
