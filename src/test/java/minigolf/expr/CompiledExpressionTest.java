package minigolf.expr;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

class CompiledExpressionTest {
    private static final double RELATIVE_TOLERANCE = 1e-12;

    static Stream<TestExpressions.Case> smoothCases() {
        return TestExpressions.SMOOTH.stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("smoothCases")
    void compiledMatchesEvaluationAndSymbolicDerivative(TestExpressions.Case c) {
        Expression h = Expression.parse(c.source());
        Expression dx = h.derivative('x');
        Expression dy = h.derivative('y');
        CompiledExpression compiled = h.compile();
        Random random = new Random(1234);
        double[] out = new double[3];
        for (int i = 0; i < 1000; i++) {
            double[] p = c.randomPoint(random);
            double x = p[0];
            double y = p[1];
            double expected = h.evaluate(x, y);
            assertEquals(expected, compiled.value(x, y), 0.0, () -> c + " value at " + x + ", " + y);
            compiled.valueAndGradient(x, y, out);
            assertEquals(expected, out[0], 0.0, () -> c + " value in valueAndGradient at " + x + ", " + y);
            assertClose(dx.evaluate(x, y), out[1], c + " d/dx at " + x + ", " + y);
            assertClose(dy.evaluate(x, y), out[2], c + " d/dy at " + x + ", " + y);
        }
    }

    private static void assertClose(double expected, double actual, String where) {
        assertTrue(Math.abs(expected - actual) <= RELATIVE_TOLERANCE * Math.max(1e-300, Math.abs(expected)),
                () -> where + ": expected " + expected + " but was " + actual);
    }

    @Test
    void lakeGradientMatchesHandFormula() {
        CompiledExpression lake = Expression.parse(TestExpressions.LAKE).compile();
        double[] out = new double[3];
        Random random = new Random(99);
        for (int i = 0; i < 1000; i++) {
            double x = -8 + 16 * random.nextDouble();
            double y = -8 + 16 * random.nextDouble();
            double g = Math.exp(-(x * x + y * y) / 8);
            lake.valueAndGradient(x, y, out);
            assertEquals(0.4 * (0.9 - g), out[0], 1e-15);
            assertEquals(0.4 * g * x / 4, out[1], 1e-15);
            assertEquals(0.4 * g * y / 4, out[2], 1e-15);
        }
    }

    @Test
    void cubeHasExactGradient() {
        double[] out = new double[3];
        Expression.parse("x^3").compile().valueAndGradient(2, 5, out);
        assertArrayEquals(new double[] {8, 12, 0}, out, 0.0);
        Expression.parse("x^2").compile().valueAndGradient(-3, 0, out);
        assertArrayEquals(new double[] {9, -6, 0}, out, 0.0);
    }

    @Test
    void kinksPickTheSameSideAsTheSymbolicDerivative() {
        double[] out = new double[3];
        Expression.parse("abs(x-0.5)").compile().valueAndGradient(0.5, 0, out);
        assertArrayEquals(new double[] {0, 0, 0}, out, 0.0);
        Expression.parse("abs(x-0.5)").compile().valueAndGradient(0.25, 0, out);
        assertArrayEquals(new double[] {0.25, -1, 0}, out, 0.0);
        Expression.parse("max(x, y)").compile().valueAndGradient(2, 2, out);
        assertArrayEquals(new double[] {2, 1, 0}, out, 0.0);
        Expression.parse("max(x, y)").compile().valueAndGradient(1, 2, out);
        assertArrayEquals(new double[] {2, 0, 1}, out, 0.0);
        Expression.parse("min(x, y)").compile().valueAndGradient(2, 2, out);
        assertArrayEquals(new double[] {2, 1, 0}, out, 0.0);
        Expression.parse("min(x, y)").compile().valueAndGradient(3, 2, out);
        assertArrayEquals(new double[] {2, 0, 1}, out, 0.0);
    }

    @ParameterizedTest
    @ValueSource(strings = {"abs(x)", "max(x, y)", "min(y, x)", "x^y", "log(x)", "sqrt(x)", "x/y"})
    void specialValuesAgreeWithSymbolicDerivative(String source) {
        Expression h = Expression.parse(source);
        CompiledExpression compiled = h.compile();
        double[] specials = {0, -0.0, 1, -1, Double.NaN, Double.MIN_VALUE, 1e300};
        double[] out = new double[3];
        for (double x : specials) {
            for (double y : specials) {
                compiled.valueAndGradient(x, y, out);
                String where = source + " at " + x + ", " + y;
                assertEquals(h.evaluate(x, y), out[0], 0.0, where);
                assertSameOrBothNaN(h.derivative('x').evaluate(x, y), out[1], where);
                assertSameOrBothNaN(h.derivative('y').evaluate(x, y), out[2], where);
            }
        }
    }

    /** Equal as numbers (so 0.0 and -0.0 match), or both NaN. */
    private static void assertSameOrBothNaN(double expected, double actual, String where) {
        assertTrue(expected == actual || (Double.isNaN(expected) && Double.isNaN(actual)),
                () -> where + ": expected " + expected + " but was " + actual);
    }

    @Test
    void constantsAndPlainVariables() {
        double[] out = new double[3];
        Expression.parse("2*pi").compile().valueAndGradient(1, 2, out);
        assertArrayEquals(new double[] {2 * Math.PI, 0, 0}, out, 0.0);
        Expression.parse("y").compile().valueAndGradient(1, 2, out);
        assertArrayEquals(new double[] {2, 0, 1}, out, 0.0);
        assertEquals(1.0, Expression.parse("x").compile().value(1, 2), 0.0);
    }

    @Test
    void isDeterministic() {
        Random random = new Random(5);
        for (TestExpressions.Case c : TestExpressions.SMOOTH) {
            CompiledExpression first = Expression.parse(c.source()).compile();
            CompiledExpression second = Expression.parse(c.source()).compile();
            Expression reference = Expression.parse(c.source());
            double[] a = new double[3];
            double[] b = new double[3];
            for (int i = 0; i < 100; i++) {
                double[] p = c.randomPoint(random);
                first.valueAndGradient(p[0], p[1], a);
                second.valueAndGradient(p[0], p[1], b);
                for (int k = 0; k < 3; k++) {
                    assertEquals(Double.doubleToRawLongBits(a[k]), Double.doubleToRawLongBits(b[k]), c::toString);
                }
                assertEquals(Double.doubleToRawLongBits(reference.evaluate(p[0], p[1])),
                        Double.doubleToRawLongBits(Expression.parse(c.source()).evaluate(p[0], p[1])), c::toString);
            }
        }
    }

    @Test
    void describesItself() {
        assertEquals("compiled x+y", Expression.parse("x+y").compile().toString());
    }
}
