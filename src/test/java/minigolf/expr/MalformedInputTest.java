package minigolf.expr;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class MalformedInputTest {

    static Stream<Arguments> malformedInputs() {
        return Stream.of(
                Arguments.of("2*", "expected a number, x, y, a function or '(' but found end of input", 3),
                Arguments.of("(x", "expected ')' at column 3 (found end of input)", 3),
                Arguments.of("sin(x", "expected ')'", 6),
                Arguments.of("x)", "unexpected ')' at column 2 (no matching '(')", 2),
                Arguments.of("foo(x)", "unknown function 'foo' at column 1 (allowed: sin, cos", 1),
                Arguments.of("1 + foo (x)", "unknown function 'foo' at column 5", 5),
                Arguments.of("x(1)", "unknown function 'x'", 1),
                Arguments.of("sin(x,y)", "too many arguments for 'sin' at column 6 (sin takes 1 argument)", 6),
                Arguments.of("max(x,y,1)", "too many arguments for 'max'", 8),
                Arguments.of("max(x)", "too few arguments for 'max' at column 6 (max takes 2 arguments)", 6),
                Arguments.of("sin()", "too few arguments for 'sin'", 5),
                Arguments.of("sin", "function 'sin' needs arguments", 4),
                Arguments.of("", "empty expression", 1),
                Arguments.of(" \t ", "empty expression", 1),
                Arguments.of("x y", "unexpected 'y' at column 3", 3),
                Arguments.of("2x", "unexpected 'x'", 2),
                Arguments.of("1..2", "unexpected '.2'", 3),
                Arguments.of("1,2", "unexpected ','", 2),
                Arguments.of("z", "unknown name 'z' at column 1 (allowed: x, y, pi, e)", 1),
                Arguments.of("X", "unknown name 'X'", 1),
                Arguments.of("PI", "unknown name 'PI'", 1),
                Arguments.of("x1", "unknown name 'x1'", 1),
                Arguments.of("java.lang.System.exit(0)", "unknown name 'java'", 1),
                Arguments.of("java.lang.Runtime", "unknown name 'java'", 1),
                Arguments.of("x.getClass()", "unexpected character '.'", 2),
                Arguments.of("x;", "unexpected character ';'", 2),
                Arguments.of("\"a\"", "unexpected character '\"'", 1),
                Arguments.of("x$", "unexpected character '$'", 2),
                Arguments.of("x = 1", "unexpected character '='", 3),
                Arguments.of("\u00e9", "unexpected character '\\u00e9'", 1),
                Arguments.of("x\u0000", "unexpected character '\\u0000'", 2),
                Arguments.of("1e999", "number out of range '1e999'", 1),
                Arguments.of("x + 2e400", "number out of range", 5),
                Arguments.of("1e", "malformed number '1e'", 3),
                Arguments.of("1e+", "malformed number", 4),
                Arguments.of("x+*y", "expected a number", 3),
                Arguments.of("()", "expected a number", 2),
                Arguments.of("x^", "expected a number", 3),
                Arguments.of("--", "expected a number", 3),
                Arguments.of("(".repeat(100_000) + "x" + ")".repeat(100_000), "expression too long", 100_001),
                Arguments.of("(".repeat(50_000) + "x", "expression nested too deeply", 201),
                Arguments.of("-".repeat(99_999) + "x", "expression nested too deeply", 201),
                Arguments.of("2^".repeat(300) + "2", "expression nested too deeply", 401),
                Arguments.of("sin(".repeat(300) + "x", "expression nested too deeply", 801),
                Arguments.of("1+".repeat(2_000) + "1", "expression too complex", 600),
                Arguments.of("x".repeat(1_000), "unknown name 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'", 1));
    }

    @ParameterizedTest(name = "[{index}] column {2}: {1}")
    @MethodSource("malformedInputs")
    void rejectsWithMessageAndColumn(String source, String messageFragment, int column) {
        ExpressionException error = assertThrows(ExpressionException.class, () -> Expression.parse(source));
        assertTrue(error.getMessage().contains(messageFragment),
                () -> "message '" + error.getMessage() + "' lacks '" + messageFragment + "'");
        assertEquals(column, error.column(), error.getMessage());
        assertTrue(error.getMessage().contains("at column " + column), error.getMessage());
    }

    @Test
    void rejectsNull() {
        assertThrows(ExpressionException.class, () -> Expression.parse(null));
    }

    @Test
    void acceptsNestingJustInsideTheLimit() {
        String source = "(".repeat(Parser.MAX_NESTING - 1) + "x" + ")".repeat(Parser.MAX_NESTING - 1);
        assertEquals(0.5, Expression.parse(source).evaluate(0.5, 0), 0.0);
    }

    @Test
    void longestAcceptedChainStillDifferentiatesAndCompiles() {
        Expression chain = Expression.parse("x*".repeat(Parser.MAX_HEIGHT - 1) + "x");
        double expected = Parser.MAX_HEIGHT * Math.pow(1.0001, Parser.MAX_HEIGHT - 1);
        assertEquals(expected, chain.derivative('x').evaluate(1.0001, 0), 1e-9 * expected);
        double[] out = new double[3];
        chain.compile().valueAndGradient(1.0001, 0, out);
        assertEquals(expected, out[1], 1e-9 * expected);
    }

    @Test
    void derivativeBlowUpIsAnExpressionException() {
        Expression quotients = Expression.parse("x/".repeat(Parser.MAX_HEIGHT - 1) + "x");
        Expression first = quotients.derivative('x');
        ExpressionException error = assertThrows(ExpressionException.class, () -> first.derivative('x'));
        assertTrue(error.getMessage().contains("derivative too complex"), error.getMessage());
    }

    @Test
    void tooLargeToCompileIsAnExpressionException() {
        StringBuilder source = new StringBuilder();
        for (int group = 0; group < 30; group++) {
            source.append(group == 0 ? "(" : "+(");
            for (int term = 0; term < 200; term++) {
                source.append(term == 0 ? "" : "+").append("sin(x*").append(group * 200 + term).append("+y)");
            }
            source.append(')');
        }
        Expression huge = Expression.parse(source.toString());
        ExpressionException error = assertThrows(ExpressionException.class, huge::compile);
        assertTrue(error.getMessage().contains("too large to compile"), error.getMessage());
    }

    /** Random garbage must either parse or fail with an ExpressionException, never anything else. */
    @Test
    void randomInputNeverThrowsAnythingElse() {
        String alphabet = "xy0123456789.eE+-*/^(),pisnoctaqrbmwl $;\"'_";
        Random random = new Random(20240601L);
        int accepted = 0;
        for (int i = 0; i < 30_000; i++) {
            int length = random.nextInt(25);
            StringBuilder source = new StringBuilder();
            for (int j = 0; j < length; j++) {
                source.append(alphabet.charAt(random.nextInt(alphabet.length())));
            }
            try {
                Expression expression = Expression.parse(source.toString());
                accepted++;
                Expression reparsed = Expression.parse(expression.toString());
                assertEquals(Double.doubleToLongBits(expression.evaluate(0.7, -1.3)),
                        Double.doubleToLongBits(reparsed.evaluate(0.7, -1.3)), source::toString);
            } catch (ExpressionException expected) {
                assertTrue(expected.column() >= 1 && expected.column() <= length + 1, source::toString);
            } catch (Throwable other) {
                fail("'" + source + "' threw " + other, other);
            }
        }
        assertTrue(accepted > 100, "the generator should also produce valid expressions, got " + accepted);
    }
}
