package minigolf.cli;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

/**
 * What docs/course-format.md says of the expression limits is what the code does: the JVM's 64 KiB
 * method limit ends a long expression of grouped terms (bench-limits' case), the tree's height
 * limit ends one long chain first.
 */
class LimitCasesTest {
    private static String chain(int n) {
        StringBuilder sb = new StringBuilder("0.1");
        for (int k = 0; k < n; k++) sb.append("+0.001*sin(").append(k).append(".1*x+y)");
        return sb.toString();
    }

    @Test
    void groupedTermsStopAtTheMethodLimitAndAChainAtTheHeightLimit() {
        assertEquals(516, LimitCases.largestCompiling(LimitCases.GROUP));
        assertNull(LimitCases.compileProblem(LimitCases.terms(516, LimitCases.GROUP)));
        assertEquals("expression too large to compile at column 1 (the generated code exceeds the JVM's 64 KiB method limit)",
                LimitCases.compileProblem(LimitCases.terms(517, LimitCases.GROUP)));
        assertEquals(LimitCases.terms(516, LimitCases.GROUP), LimitCases.longestCompilingExpression());
        assertNull(LimitCases.compileProblem(chain(295)));
        assertEquals("expression too complex at column 6089 (more than 300 operations chained together)",
                LimitCases.compileProblem(chain(296)));
    }
}
