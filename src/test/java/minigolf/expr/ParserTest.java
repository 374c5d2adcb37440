package minigolf.expr;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.function.DoubleBinaryOperator;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

class ParserTest {

    static Stream<Arguments> constantExpressions() {
        return Stream.of(
                Arguments.of("2^3^2", 512.0),
                Arguments.of("(2^3)^2", 64.0),
                Arguments.of("-2^2", -4.0),
                Arguments.of("(-2)^2", 4.0),
                Arguments.of("2*-3", -6.0),
                Arguments.of("1-2-3", -4.0),
                Arguments.of("1-(2-3)", 2.0),
                Arguments.of("8/4/2", 1.0),
                Arguments.of("8/(4/2)", 4.0),
                Arguments.of("2+3*4", 14.0),
                Arguments.of("(2+3)*4", 20.0),
                Arguments.of("2^-1", 0.5),
                Arguments.of("2^+1", 2.0),
                Arguments.of("-2^-2", -0.25),
                Arguments.of("--3", 3.0),
                Arguments.of("+-+3", -3.0),
                Arguments.of("2*3^2", 18.0),
                Arguments.of("-3*2", -6.0),
                Arguments.of("pi", Math.PI),
                Arguments.of("e", Math.E),
                Arguments.of("2*pi*e", 2 * Math.PI * Math.E),
                Arguments.of("1e-3", 1e-3),
                Arguments.of("1.5E+2", 150.0),
                Arguments.of("2.5e2", 250.0),
                Arguments.of(".5", 0.5),
                Arguments.of("2.", 2.0),
                Arguments.of("007", 7.0),
                Arguments.of("1e-999", 0.0),
                Arguments.of("1.7976931348623157e308", Double.MAX_VALUE),
                Arguments.of(" \t1 +\n2 \r", 3.0),
                Arguments.of("pow(2, 10)", 1024.0),
                Arguments.of("max(1, 2) - min(1, 2)", 1.0));
    }

    @ParameterizedTest(name = "{0} = {1}")
    @MethodSource("constantExpressions")
    void evaluatesConstantExpressions(String source, double expected) {
        assertEquals(expected, Expression.parse(source).evaluate(0, 0), 0.0);
    }

    static Stream<Arguments> functions() {
        return Stream.of(
                Arguments.of("sin(x)", (DoubleBinaryOperator) (x, y) -> Math.sin(x)),
                Arguments.of("cos(x)", (DoubleBinaryOperator) (x, y) -> Math.cos(x)),
                Arguments.of("tan(x)", (DoubleBinaryOperator) (x, y) -> Math.tan(x)),
                Arguments.of("asin(y)", (DoubleBinaryOperator) (x, y) -> Math.asin(y)),
                Arguments.of("acos(y)", (DoubleBinaryOperator) (x, y) -> Math.acos(y)),
                Arguments.of("atan(x)", (DoubleBinaryOperator) (x, y) -> Math.atan(x)),
                Arguments.of("atan2(y, x)", (DoubleBinaryOperator) (x, y) -> Math.atan2(y, x)),
                Arguments.of("exp(x)", (DoubleBinaryOperator) (x, y) -> Math.exp(x)),
                Arguments.of("log(x)", (DoubleBinaryOperator) (x, y) -> Math.log(x)),
                Arguments.of("sqrt(x)", (DoubleBinaryOperator) (x, y) -> Math.sqrt(x)),
                Arguments.of("abs(y)", (DoubleBinaryOperator) (x, y) -> Math.abs(y)),
                Arguments.of("min(x, y)", (DoubleBinaryOperator) Math::min),
                Arguments.of("max(x, y)", (DoubleBinaryOperator) Math::max),
                Arguments.of("pow(x, y)", (DoubleBinaryOperator) Math::pow),
                Arguments.of("x^y", (DoubleBinaryOperator) Math::pow),
                Arguments.of("x*y - x/y", (DoubleBinaryOperator) (x, y) -> x * y - x / y));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("functions")
    void everyFunctionMatchesJavaLangMath(String source, DoubleBinaryOperator reference) {
        Expression expression = Expression.parse(source);
        double[][] points = {{1.7, 0.3}, {0.25, -0.8}, {3.0, 0.99}};
        for (double[] p : points) {
            assertEquals(reference.applyAsDouble(p[0], p[1]), expression.evaluate(p[0], p[1]), 0.0, source);
        }
    }

    @Test
    void unaryMinusBindsLooserThanPower() {
        assertEquals(-9.0, Expression.parse("-x^2").evaluate(3, 0), 0.0);
        assertEquals(9.0, Expression.parse("(-x)^2").evaluate(3, 0), 0.0);
    }

    @Test
    void squareOfNegativeBaseIsDefined() {
        assertEquals(4.0, Expression.parse("x^2").evaluate(-2, 0), 0.0);
        assertEquals(-8.0, Expression.parse("x^3").evaluate(-2, 0), 0.0);
    }

    @Test
    void keepsSourceAndPrintsMinimalParseableForm() {
        Expression expression = Expression.parse("  2 ^ 3 ^ 2 ");
        assertEquals("  2 ^ 3 ^ 2 ", expression.source());
        assertEquals("2.0^3.0^2.0", expression.toString());
        assertEquals("(2.0^3.0)^2.0", Expression.parse("(2^3)^2").toString());
        assertEquals("1.0 - (2.0 - 3.0)", Expression.parse("1-(2-3)").toString());
        assertEquals("1.0 - 2.0 - 3.0", Expression.parse("1-2-3").toString());
        assertEquals("-x^2.0", Expression.parse("-x^2").toString());
        assertEquals("(-x)^2.0", Expression.parse("(-x)^2").toString());
        assertEquals("x*-3.0", Expression.parse("x*-3").toString());
        assertEquals("x - -y", Expression.parse("x--y").toString());
        assertEquals("atan2(y, x + 10.0)", Expression.parse("atan2(y,x+10)").toString());
        assertEquals("x^2.0", Expression.parse("pow(x,2)").toString());
    }

    @ParameterizedTest
    @ValueSource(strings = {"0.4*(0.9-exp(-(x^2+y^2)/8))", "x+(y+1)", "(x+y)+1", "2^-x", "-(x*y)", "-x*y",
            "x/(y/3)", "(x-y)^(x+y)", "--x", "-(-x)", "sin(cos(x))^2", "1e-300*x", "1/3*x", "x^y^2"})
    void printedFormParsesBackToTheSameValues(String source) {
        Expression original = Expression.parse(source);
        Expression reparsed = Expression.parse(original.toString());
        assertEquals(original.toString(), reparsed.toString());
        for (double x = -2; x <= 2; x += 0.37) {
            for (double y = -2; y <= 2; y += 0.41) {
                assertEquals(Double.doubleToLongBits(original.evaluate(x, y)),
                        Double.doubleToLongBits(reparsed.evaluate(x, y)), source);
            }
        }
    }
}
