package minigolf.expr;

import java.util.List;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * Emits one method body: every step's value into a local, and with {@code gradient} also its
 * derivatives by x and y (forward-mode dual numbers). Derivatives known to be zero, such as those of
 * constants or of terms without y, are tracked as constants and cost no code.
 * <p>
 * Value arithmetic is emitted literally so it matches {@link Evaluator} bit for bit. Derivative
 * arithmetic drops neutral terms the way {@link Simplifier} does and uses the formulas of
 * {@link Differentiator}, so compiled and symbolic derivatives agree as well.
 */
final class StepEmitter {
    private static final int X_SLOT = 1;
    private static final int Y_SLOT = 3;
    private static final int DIRECTIONS = 2;
    private static final String MATH = "java/lang/Math";

    private final MethodVisitor code;
    private final boolean gradient;
    private int nextFreeSlot;
    private Operand[] values;
    /** derivatives[direction][step]; direction 0 is x, 1 is y. */
    private Operand[][] derivatives;

    StepEmitter(MethodVisitor code, boolean gradient, int firstFreeSlot) {
        this.code = code;
        this.gradient = gradient;
        this.nextFreeSlot = firstFreeSlot;
    }

    /** Emits the steps in order; each step's operands come before it. */
    void emitAll(List<Step> steps) {
        values = new Operand[steps.size()];
        derivatives = new Operand[DIRECTIONS][steps.size()];
        for (int i = 0; i < steps.size(); i++) {
            emit(steps.get(i), i);
        }
    }

    Operand result() {
        return values[values.length - 1];
    }

    Operand resultDerivative(int direction) {
        return derivatives[direction][values.length - 1];
    }

    private void emit(Step step, int index) {
        Node node = step.node();
        Operand a = step.first() >= 0 ? values[step.first()] : null;
        Operand b = step.second() >= 0 ? values[step.second()] : null;
        if (node instanceof Node.Constant constant) {
            values[index] = Operand.constant(constant.value());
        } else if (node instanceof Node.Variable variable) {
            values[index] = Operand.local(variable.name() == 'x' ? X_SLOT : Y_SLOT);
        } else if (node instanceof Node.Negate) {
            values[index] = negateExactly(a);
        } else if (node instanceof Node.Binary binary) {
            values[index] = binaryValue(binary.operator(), a, b);
        } else {
            values[index] = callMath(((Node.Call) node).function(), a, b);
        }
        for (int direction = 0; direction < DIRECTIONS; direction++) {
            derivatives[direction][index] = Operand.ZERO;
        }
        if (gradient) {
            emitDerivatives(step, index, a, b);
        }
    }

    // ---- values: literal arithmetic, the same operations Evaluator performs ----

    private Operand binaryValue(BinaryOperator operator, Operand a, Operand b) {
        switch (operator) {
            case ADD:
                return arithmetic(Opcodes.DADD, a, b);
            case SUBTRACT:
                return arithmetic(Opcodes.DSUB, a, b);
            case MULTIPLY:
                return arithmetic(Opcodes.DMUL, a, b);
            case DIVIDE:
                return divide(a, b);
            case POWER:
                return b.isConstant() ? constantPower(a, b.constant()) : callMath(MathFunction.POW, a, b);
            default:
                throw new AssertionError(operator);
        }
    }

    private Operand arithmetic(int opcode, Operand a, Operand b) {
        load(a);
        load(b);
        code.visitInsn(opcode);
        return storeInNewSlot();
    }

    private Operand negateExactly(Operand a) {
        load(a);
        code.visitInsn(Opcodes.DNEG);
        return storeInNewSlot();
    }

    /**
     * Division by a power of two becomes multiplication by its reciprocal: both are one correctly
     * rounded operation on the same real number, so the result is identical, and DMUL is faster.
     */
    private Operand divide(Operand a, Operand b) {
        if (b.isConstant() && hasExactReciprocal(b.constant())) {
            return arithmetic(Opcodes.DMUL, a, Operand.constant(1 / b.constant()));
        }
        return arithmetic(Opcodes.DDIV, a, b);
    }

    private static boolean hasExactReciprocal(double c) {
        long mantissa = Double.doubleToRawLongBits(c) & 0x000F_FFFF_FFFF_FFFFL;
        int exponent = Math.getExponent(c);
        return mantissa == 0 && exponent > Double.MIN_EXPONENT && exponent < Double.MAX_EXPONENT;
    }

    /** The same cases as {@link Powers#constantPower}, unrolled into multiplications. */
    private Operand constantPower(Operand base, double exponent) {
        if (base.isConstant()) {
            return Operand.constant(Powers.constantPower(base.constant(), exponent));
        }
        if (exponent == 1) {
            return base; // Math.pow(u, 1) is u
        }
        if (exponent == 0) {
            return Operand.ONE; // Math.pow(u, 0) is 1, even for NaN
        }
        if (exponent == 2) {
            return arithmetic(Opcodes.DMUL, base, base);
        }
        if (exponent == 3) {
            return arithmetic(Opcodes.DMUL, arithmetic(Opcodes.DMUL, base, base), base);
        }
        if (exponent == 4) {
            Operand square = arithmetic(Opcodes.DMUL, base, base);
            return arithmetic(Opcodes.DMUL, square, square);
        }
        if (exponent == -1) {
            return arithmetic(Opcodes.DDIV, Operand.ONE, base);
        }
        if (exponent == -2) {
            return arithmetic(Opcodes.DDIV, Operand.ONE, arithmetic(Opcodes.DMUL, base, base));
        }
        return callMath(MathFunction.POW, base, Operand.constant(exponent));
    }

    private Operand callMath(MathFunction function, Operand a, Operand b) {
        if (a.isConstant() && (b == null || b.isConstant())) {
            return Operand.constant(function.apply(a.constant(), b == null ? 0 : b.constant()));
        }
        load(a);
        if (function.arity == 2) {
            load(b);
        }
        code.visitMethodInsn(Opcodes.INVOKESTATIC, MATH, function.functionName,
                function.arity == 2 ? "(DD)D" : "(D)D", false);
        return storeInNewSlot();
    }

    // ---- derivatives: forward mode, mirroring Differentiator ----

    private void emitDerivatives(Step step, int index, Operand a, Operand b) {
        Node node = step.node();
        Operand r = values[index];
        Operand[] da = step.first() >= 0 ? derivativesOf(step.first()) : null;
        Operand[] db = step.second() >= 0 ? derivativesOf(step.second()) : null;
        Operand[] result = new Operand[DIRECTIONS];
        if (node instanceof Node.Constant) {
            return;
        }
        if (node instanceof Node.Variable variable) {
            derivatives[0][index] = variable.name() == 'x' ? Operand.ONE : Operand.ZERO;
            derivatives[1][index] = variable.name() == 'y' ? Operand.ONE : Operand.ZERO;
            return;
        }
        if (allZero(da) && allZero(db)) {
            return; // a constant part: no derivative code at all
        }
        if (node instanceof Node.Negate) {
            for (int d = 0; d < DIRECTIONS; d++) {
                result[d] = negate(da[d]);
            }
        } else if (node instanceof Node.Binary binary) {
            binaryDerivative(binary.operator(), r, a, b, da, db, result);
        } else {
            callDerivative(((Node.Call) node).function(), r, a, b, da, db, result);
        }
        for (int d = 0; d < DIRECTIONS; d++) {
            derivatives[d][index] = result[d];
        }
    }

    private void binaryDerivative(BinaryOperator operator, Operand r, Operand a, Operand b,
            Operand[] da, Operand[] db, Operand[] result) {
        switch (operator) {
            case ADD:
                for (int d = 0; d < DIRECTIONS; d++) {
                    result[d] = add(da[d], db[d]);
                }
                return;
            case SUBTRACT:
                for (int d = 0; d < DIRECTIONS; d++) {
                    result[d] = subtract(da[d], db[d]);
                }
                return;
            case MULTIPLY:
                for (int d = 0; d < DIRECTIONS; d++) {
                    result[d] = add(multiply(da[d], b), multiply(a, db[d]));
                }
                return;
            case DIVIDE:
                for (int d = 0; d < DIRECTIONS; d++) {
                    result[d] = divideDerivative(subtract(da[d], multiply(r, db[d])), b);
                }
                return;
            case POWER:
                powerDerivative(r, a, b, da, db, result);
                return;
            default:
                throw new AssertionError(operator);
        }
    }

    private void powerDerivative(Operand r, Operand a, Operand b, Operand[] da, Operand[] db, Operand[] result) {
        if (b.isConstant()) {
            // c * u^(c-1) * u'
            Operand factor = multiply(b, constantPower(a, b.constant() - 1));
            for (int d = 0; d < DIRECTIONS; d++) {
                result[d] = multiply(factor, da[d]);
            }
            return;
        }
        // w * u^(w-1) * u' + u^w * ln(u) * w', each factor only when its derivative can be non-zero
        Operand baseFactor = allZero(da) ? Operand.ZERO
                : multiply(b, callMath(MathFunction.POW, a, subtract(b, Operand.ONE)));
        Operand exponentFactor = allZero(db) ? Operand.ZERO : multiply(r, callMath(MathFunction.LOG, a, null));
        for (int d = 0; d < DIRECTIONS; d++) {
            result[d] = add(multiply(baseFactor, da[d]), multiply(exponentFactor, db[d]));
        }
    }

    private void callDerivative(MathFunction function, Operand r, Operand a, Operand b,
            Operand[] da, Operand[] db, Operand[] result) {
        Operand factor;
        switch (function) {
            case SIN:
                factor = callMath(MathFunction.COS, a, null);
                scale(factor, da, result);
                return;
            case COS:
                factor = callMath(MathFunction.SIN, a, null);
                for (int d = 0; d < DIRECTIONS; d++) {
                    result[d] = negate(multiply(factor, da[d]));
                }
                return;
            case TAN:
                scale(add(Operand.ONE, multiply(r, r)), da, result);
                return;
            case ASIN:
            case ACOS: {
                Operand root = callMath(MathFunction.SQRT, subtract(Operand.ONE, multiply(a, a)), null);
                for (int d = 0; d < DIRECTIONS; d++) {
                    Operand quotient = divideDerivative(da[d], root);
                    result[d] = function == MathFunction.ASIN ? quotient : negate(quotient);
                }
                return;
            }
            case ATAN:
                divideAll(da, add(Operand.ONE, multiply(a, a)), result);
                return;
            case ATAN2: {
                Operand sumOfSquares = add(multiply(a, a), multiply(b, b));
                for (int d = 0; d < DIRECTIONS; d++) {
                    result[d] = divideDerivative(subtract(multiply(b, da[d]), multiply(a, db[d])), sumOfSquares);
                }
                return;
            }
            case EXP:
                scale(r, da, result);
                return;
            case LOG:
                divideAll(da, a, result);
                return;
            case SQRT:
                divideAll(da, multiply(Operand.constant(2), r), result);
                return;
            case ABS:
                scale(sign(a, r), da, result);
                return;
            case MIN:
                pickDerivative(a, b, da, db, result, true);
                return;
            case MAX:
                pickDerivative(a, b, da, db, result, false);
                return;
            default:
                throw new AssertionError(function);
        }
    }

    private void scale(Operand factor, Operand[] da, Operand[] result) {
        for (int d = 0; d < DIRECTIONS; d++) {
            result[d] = multiply(factor, da[d]);
        }
    }

    private void divideAll(Operand[] da, Operand divisor, Operand[] result) {
        for (int d = 0; d < DIRECTIONS; d++) {
            result[d] = divideDerivative(da[d], divisor);
        }
    }

    /**
     * -1, 1, or for zero and NaN the symbolic form u / max(|u|, MIN_VALUE) (0 or NaN); branching
     * avoids a division in the common case and gives exactly the symbolic result.
     */
    private Operand sign(Operand u, Operand absU) {
        int slot = allocateSlot();
        Label notPositive = new Label();
        Label zeroOrNaN = new Label();
        Label done = new Label();
        load(u);
        code.visitInsn(Opcodes.DCONST_0);
        code.visitInsn(Opcodes.DCMPL); // NaN gives -1: not positive
        code.visitJumpInsn(Opcodes.IFLE, notPositive);
        storeConstant(1, slot);
        code.visitJumpInsn(Opcodes.GOTO, done);
        code.visitLabel(notPositive);
        load(u);
        code.visitInsn(Opcodes.DCONST_0);
        code.visitInsn(Opcodes.DCMPG); // NaN gives 1: not negative
        code.visitJumpInsn(Opcodes.IFGE, zeroOrNaN);
        storeConstant(-1, slot);
        code.visitJumpInsn(Opcodes.GOTO, done);
        code.visitLabel(zeroOrNaN);
        load(u);
        load(absU);
        load(Operand.constant(Double.MIN_VALUE));
        code.visitMethodInsn(Opcodes.INVOKESTATIC, MATH, "max", "(DD)D", false);
        code.visitInsn(Opcodes.DDIV);
        code.visitVarInsn(Opcodes.DSTORE, slot);
        code.visitLabel(done);
        return Operand.local(slot);
    }

    /**
     * The derivative of min (or max): the first argument's where it is the smaller (larger) one or
     * tied, else the second's, and NaN when the comparison is undecided, as in the symbolic form.
     */
    private void pickDerivative(Operand a, Operand b, Operand[] da, Operand[] db, Operand[] result,
            boolean minimum) {
        int[] slots = new int[DIRECTIONS];
        for (int d = 0; d < DIRECTIONS; d++) {
            // A direction in which neither argument changes stays a known zero (slot -1: no code).
            boolean bothZero = da[d].is(0) && db[d].is(0);
            slots[d] = bothZero ? -1 : allocateSlot();
            result[d] = bothZero ? Operand.ZERO : Operand.local(slots[d]);
        }
        Label second = new Label();
        Label undecided = new Label();
        Label done = new Label();
        load(a);
        load(b);
        // min keeps the first when a <= b; DCMPG puts NaN on the "greater" side, so NaN goes on.
        // max keeps the first when a >= b; DCMPL puts NaN on the "less" side.
        code.visitInsn(minimum ? Opcodes.DCMPG : Opcodes.DCMPL);
        code.visitJumpInsn(minimum ? Opcodes.IFGT : Opcodes.IFLT, second);
        copyInto(da, slots);
        code.visitJumpInsn(Opcodes.GOTO, done);
        code.visitLabel(second);
        load(a);
        load(b);
        // Strictly the other way round means the second argument wins; otherwise one was NaN.
        code.visitInsn(minimum ? Opcodes.DCMPL : Opcodes.DCMPG);
        code.visitJumpInsn(minimum ? Opcodes.IFLE : Opcodes.IFGE, undecided);
        copyInto(db, slots);
        code.visitJumpInsn(Opcodes.GOTO, done);
        code.visitLabel(undecided);
        for (int d = 0; d < DIRECTIONS; d++) {
            if (slots[d] >= 0) {
                storeConstant(Double.NaN, slots[d]);
            }
        }
        code.visitLabel(done);
    }

    private void copyInto(Operand[] sources, int[] slots) {
        for (int d = 0; d < DIRECTIONS; d++) {
            if (slots[d] < 0) {
                continue;
            }
            load(sources[d]);
            code.visitVarInsn(Opcodes.DSTORE, slots[d]);
        }
    }

    // ---- derivative arithmetic: folds constants and drops neutral terms like Simplifier ----

    private Operand add(Operand a, Operand b) {
        if (a.isConstant() && b.isConstant()) {
            return Operand.constant(a.constant() + b.constant());
        }
        if (a.is(0)) {
            return b;
        }
        if (b.is(0)) {
            return a;
        }
        return arithmetic(Opcodes.DADD, a, b);
    }

    private Operand subtract(Operand a, Operand b) {
        if (a.isConstant() && b.isConstant()) {
            return Operand.constant(a.constant() - b.constant());
        }
        if (b.is(0)) {
            return a;
        }
        if (a.is(0)) {
            return negate(b);
        }
        return arithmetic(Opcodes.DSUB, a, b);
    }

    private Operand multiply(Operand a, Operand b) {
        if (a.isConstant() && b.isConstant()) {
            return Operand.constant(a.constant() * b.constant());
        }
        if (a.is(0) || b.is(0)) {
            return Operand.ZERO;
        }
        if (a.is(1)) {
            return b;
        }
        if (b.is(1)) {
            return a;
        }
        if (a.is(-1)) {
            return negate(b);
        }
        if (b.is(-1)) {
            return negate(a);
        }
        return arithmetic(Opcodes.DMUL, a, b);
    }

    private Operand divideDerivative(Operand a, Operand b) {
        if (a.isConstant() && b.isConstant()) {
            return Operand.constant(a.constant() / b.constant());
        }
        if (a.is(0)) {
            return Operand.ZERO;
        }
        if (b.is(1)) {
            return a;
        }
        if (b.is(-1)) {
            return negate(a);
        }
        return divide(a, b);
    }

    private Operand negate(Operand a) {
        return a.isConstant() ? Operand.constant(-a.constant()) : negateExactly(a);
    }

    // ---- plumbing ----

    private Operand[] derivativesOf(int step) {
        Operand[] result = new Operand[DIRECTIONS];
        for (int d = 0; d < DIRECTIONS; d++) {
            result[d] = derivatives[d][step];
        }
        return result;
    }

    private static boolean allZero(Operand[] derivative) {
        if (derivative == null) {
            return true;
        }
        for (Operand component : derivative) {
            if (!component.is(0)) {
                return false;
            }
        }
        return true;
    }

    void load(Operand operand) {
        if (!operand.isConstant()) {
            code.visitVarInsn(Opcodes.DLOAD, operand.slot());
        } else if (Double.doubleToRawLongBits(operand.constant()) == 0L) {
            code.visitInsn(Opcodes.DCONST_0);
        } else if (operand.constant() == 1) {
            code.visitInsn(Opcodes.DCONST_1);
        } else {
            code.visitLdcInsn(operand.constant());
        }
    }

    private void storeConstant(double value, int slot) {
        load(Operand.constant(value));
        code.visitVarInsn(Opcodes.DSTORE, slot);
    }

    private Operand storeInNewSlot() {
        int slot = allocateSlot();
        code.visitVarInsn(Opcodes.DSTORE, slot);
        return Operand.local(slot);
    }

    /** A double takes two local-variable slots. */
    private int allocateSlot() {
        int slot = nextFreeSlot;
        nextFreeSlot += 2;
        return slot;
    }
}
