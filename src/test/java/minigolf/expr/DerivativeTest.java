package minigolf.expr;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class DerivativeTest {
    private static final double STEP = 1e-6;
    private static final double TOLERANCE = 1e-6;

    static Stream<TestExpressions.Case> smoothCases() {
        return TestExpressions.SMOOTH.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("smoothCases")
    void matchesCentralFiniteDifferences(TestExpressions.Case c) {
        Expression h = Expression.parse(c.source());
        Expression dx = h.derivative('x');
        Expression dy = h.derivative('y');
        Random random = new Random(c.source().hashCode());
        int checked = 0;
        while (checked < 300) {
            double[] p = c.randomPoint(random);
            double x = p[0];
            double y = p[1];
            if (TestExpressions.nearKink(c, x, y)) {
                continue;
            }
            double numericX = (h.evaluate(x + STEP, y) - h.evaluate(x - STEP, y)) / (2 * STEP);
            double numericY = (h.evaluate(x, y + STEP) - h.evaluate(x, y - STEP)) / (2 * STEP);
            assertClose(numericX, dx.evaluate(x, y), c + " d/dx at " + x + ", " + y);
            assertClose(numericY, dy.evaluate(x, y), c + " d/dy at " + x + ", " + y);
            checked++;
        }
    }

    private static void assertClose(double expected, double actual, String where) {
        assertTrue(Math.abs(expected - actual) <= TOLERANCE * Math.max(1, Math.abs(expected)),
                () -> where + ": expected " + expected + " but was " + actual);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("smoothCases")
    void derivativePrintsInParseableForm(TestExpressions.Case c) {
        Expression dx = Expression.parse(c.source()).derivative('x');
        Expression reparsed = Expression.parse(dx.toString());
        assertEquals(dx.toString(), dx.source());
        Random random = new Random(7);
        for (int i = 0; i < 50; i++) {
            double[] p = c.randomPoint(random);
            assertEquals(Double.doubleToLongBits(dx.evaluate(p[0], p[1])),
                    Double.doubleToLongBits(reparsed.evaluate(p[0], p[1])), dx.toString());
        }
    }

    @Test
    void cubeHasExactDerivative() {
        assertEquals(12.0, Expression.parse("x^3").derivative('x').evaluate(2, 0), 0.0);
        assertEquals(0.0, Expression.parse("x^3").derivative('y').evaluate(2, 0), 0.0);
    }

    @Test
    void lakeGradientMatchesHandFormula() {
        Expression lake = Expression.parse(TestExpressions.LAKE);
        Expression dx = lake.derivative('x');
        Expression dy = lake.derivative('y');
        Random random = new Random(42);
        for (int i = 0; i < 1000; i++) {
            double x = -8 + 16 * random.nextDouble();
            double y = -8 + 16 * random.nextDouble();
            // h = 0.4*(0.9 - exp(-r²/8))  =>  dh/dx = 0.4 * exp(-r²/8) * x/4
            double g = Math.exp(-(x * x + y * y) / 8);
            assertEquals(0.4 * g * x / 4, dx.evaluate(x, y), 1e-15);
            assertEquals(0.4 * g * y / 4, dy.evaluate(x, y), 1e-15);
        }
    }

    static Stream<Arguments> simplifiedForms() {
        return Stream.of(
                Arguments.of("3*x+2", 'x', "3.0"),
                Arguments.of("x*y", 'x', "y"),
                Arguments.of("x*y", 'y', "x"),
                Arguments.of("y^2", 'x', "0.0"),
                Arguments.of("x^2", 'x', "2.0*x"),
                Arguments.of("x^3", 'x', "3.0*x^2.0"),
                Arguments.of("sin(x)", 'x', "cos(x)"),
                Arguments.of("cos(x)", 'x', "-sin(x)"),
                Arguments.of("exp(x)", 'x', "exp(x)"),
                Arguments.of("-x", 'x', "(-1.0)"),
                Arguments.of("x - y", 'y', "(-1.0)"),
                Arguments.of("x/4", 'x', "0.25"),
                Arguments.of("log(x)", 'x', "1.0/x"),
                Arguments.of("2*pi", 'x', "0.0"),
                Arguments.of("abs(x)", 'x', "x/max(abs(x), 4.9E-324)"),
                Arguments.of("max(x, 1)", 'x', "1.0 - min(x - 1.0, 0.0)/min(x - 1.0, (-4.9E-324))"));
    }

    @ParameterizedTest(name = "d/d{1} {0} = {2}")
    @MethodSource("simplifiedForms")
    void derivativesAreSimplified(String source, char variable, String expected) {
        assertEquals(expected, Expression.parse(source).derivative(variable).toString());
    }

    @Test
    void squareOfNegativeBaseHasDerivative() {
        assertEquals(-6.0, Expression.parse("x^2").derivative('x').evaluate(-3, 0), 0.0);
        assertTrue(Double.isNaN(Expression.parse("pow(x, 1.5)").derivative('x').evaluate(-1, 0)),
                "a fractional power has no real derivative below zero");
    }

    @Test
    void kinksPickDocumentedSide() {
        Expression abs = Expression.parse("abs(x-0.5)");
        assertEquals(0.0, abs.derivative('x').evaluate(0.5, 0), 0.0);
        assertEquals(1.0, abs.derivative('x').evaluate(0.75, 0), 0.0);
        assertEquals(-1.0, abs.derivative('x').evaluate(1e-300, 0), 0.0);
        Expression max = Expression.parse("max(x, y)");
        assertEquals(1.0, max.derivative('x').evaluate(2, 2), 0.0, "ties pick the first argument");
        assertEquals(0.0, max.derivative('y').evaluate(2, 2), 0.0);
        assertEquals(1.0, max.derivative('y').evaluate(2, 2 + 1e-15), 0.0);
        Expression min = Expression.parse("min(x, y)");
        assertEquals(1.0, min.derivative('x').evaluate(2, 2), 0.0, "ties pick the first argument");
        assertEquals(0.0, min.derivative('x').evaluate(2 + 1e-15, 2), 0.0);
        assertEquals(1.0, min.derivative('y').evaluate(2 + 1e-15, 2), 0.0);
    }

    @Test
    void secondDerivativeOfSineIsMinusSine() {
        Expression second = Expression.parse("sin(x)").derivative('x').derivative('x');
        assertEquals(-Math.sin(0.7), second.evaluate(0.7, 0), 0.0);
    }

    @Test
    void onlyXAndYCanBeDifferentiated() {
        assertThrows(IllegalArgumentException.class, () -> Expression.parse("x").derivative('z'));
    }
}
