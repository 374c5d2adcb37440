package minigolf.expr;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.objectweb.asm.ClassTooLargeException;
import org.objectweb.asm.ClassWriter;
import org.objectweb.asm.MethodTooLargeException;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * Turns a folded expression tree into a hidden JVM class implementing {@link CompiledExpression}.
 * <p>
 * Equal subtrees are merged first, so each distinct sub-result is computed once into a local
 * variable, in an order where operands come before their users. The generated code is straight-line
 * arithmetic (DADD, DSUB, DMUL, DDIV, DNEG) plus static java.lang.Math calls, which the JIT turns
 * into register code; only abs, min and max branch, to pick a derivative.
 */
final class BytecodeCompiler {
    private static final String CLASS_NAME = "minigolf/expr/CompiledHeightFunction";
    private static final String INTERFACE_NAME = "minigolf/expr/CompiledExpression";
    private static final int MAX_DESCRIPTION_LENGTH = 200;

    /** Identity of a step for merging: the operation plus the indices of its operand steps. */
    private record StepKey(Object operation, long constantBits, int first, int second) {
    }

    private final List<Step> steps = new ArrayList<>();
    private final Map<StepKey, Integer> stepByKey = new HashMap<>();
    private final Map<Node, Integer> stepByNode = new IdentityHashMap<>();

    private BytecodeCompiler() {
    }

    /** @param folded a tree that has been through {@link ConstantFolder} */
    static CompiledExpression compile(Node folded, String source) {
        BytecodeCompiler compiler = new BytecodeCompiler();
        compiler.addSteps(folded);
        byte[] classBytes;
        try {
            classBytes = compiler.generateClass(source);
        } catch (MethodTooLargeException | ClassTooLargeException tooLarge) {
            throw new ExpressionException("expression too large to compile", 1,
                    "the generated code exceeds the JVM's 64 KiB method limit");
        }
        return instantiate(classBytes);
    }

    private int addSteps(Node node) {
        Integer known = stepByNode.get(node);
        if (known != null) {
            return known;
        }
        StepKey key;
        int first = -1;
        int second = -1;
        if (node instanceof Node.Constant constant) {
            key = new StepKey("constant", Double.doubleToRawLongBits(constant.value()), -1, -1);
        } else if (node instanceof Node.Variable variable) {
            key = new StepKey(variable.name(), 0, -1, -1);
        } else if (node instanceof Node.Negate negate) {
            first = addSteps(negate.operand());
            key = new StepKey("negate", 0, first, -1);
        } else if (node instanceof Node.Binary binary) {
            first = addSteps(binary.left());
            second = addSteps(binary.right());
            key = new StepKey(binary.operator(), 0, first, second);
        } else {
            Node.Call call = (Node.Call) node;
            first = addSteps(call.argument(0));
            second = call.function().arity == 2 ? addSteps(call.argument(1)) : -1;
            key = new StepKey(call.function(), 0, first, second);
        }
        Integer index = stepByKey.get(key);
        if (index == null) {
            index = steps.size();
            steps.add(new Step(node, first, second));
            stepByKey.put(key, index);
        }
        stepByNode.put(node, index);
        return index;
    }

    private byte[] generateClass(String source) {
        ClassWriter writer = new ClassWriter(ClassWriter.COMPUTE_FRAMES | ClassWriter.COMPUTE_MAXS);
        writer.visit(Opcodes.V17, Opcodes.ACC_PUBLIC | Opcodes.ACC_FINAL | Opcodes.ACC_SUPER, CLASS_NAME, null,
                "java/lang/Object", new String[] {INTERFACE_NAME});

        MethodVisitor constructor = writer.visitMethod(Opcodes.ACC_PUBLIC, "<init>", "()V", null, null);
        constructor.visitCode();
        constructor.visitVarInsn(Opcodes.ALOAD, 0);
        constructor.visitMethodInsn(Opcodes.INVOKESPECIAL, "java/lang/Object", "<init>", "()V", false);
        constructor.visitInsn(Opcodes.RETURN);
        constructor.visitMaxs(0, 0);
        constructor.visitEnd();

        MethodVisitor value = writer.visitMethod(Opcodes.ACC_PUBLIC, "value", "(DD)D", null, null);
        value.visitCode();
        StepEmitter valueEmitter = new StepEmitter(value, false, 5);
        valueEmitter.emitAll(steps);
        valueEmitter.load(valueEmitter.result());
        value.visitInsn(Opcodes.DRETURN);
        value.visitMaxs(0, 0);
        value.visitEnd();

        MethodVisitor gradient = writer.visitMethod(Opcodes.ACC_PUBLIC, "valueAndGradient", "(DD[D)V", null, null);
        gradient.visitCode();
        StepEmitter gradientEmitter = new StepEmitter(gradient, true, 6);
        gradientEmitter.emitAll(steps);
        Operand[] results = {gradientEmitter.result(), gradientEmitter.resultDerivative(0),
                gradientEmitter.resultDerivative(1)};
        for (int i = 0; i < results.length; i++) {
            gradient.visitVarInsn(Opcodes.ALOAD, 5);
            gradient.visitLdcInsn(i);
            gradientEmitter.load(results[i]);
            gradient.visitInsn(Opcodes.DASTORE);
        }
        gradient.visitInsn(Opcodes.RETURN);
        gradient.visitMaxs(0, 0);
        gradient.visitEnd();

        MethodVisitor toString = writer.visitMethod(Opcodes.ACC_PUBLIC, "toString", "()Ljava/lang/String;", null, null);
        toString.visitCode();
        // Bounded, since a constant-pool string may not exceed 64 KiB.
        toString.visitLdcInsn("compiled " + (source.length() <= MAX_DESCRIPTION_LENGTH
                ? source : source.substring(0, MAX_DESCRIPTION_LENGTH) + "..."));
        toString.visitInsn(Opcodes.ARETURN);
        toString.visitMaxs(0, 0);
        toString.visitEnd();

        writer.visitEnd();
        return writer.toByteArray();
    }

    /**
     * A hidden class in this package: it is reachable only through the returned instance and is
     * unloaded with it, and defining it needs no class loader of our own.
     */
    private static CompiledExpression instantiate(byte[] classBytes) {
        try {
            MethodHandles.Lookup lookup = MethodHandles.lookup().defineHiddenClass(classBytes, true);
            return (CompiledExpression) lookup.findConstructor(lookup.lookupClass(), MethodType.methodType(void.class))
                    .invoke();
        } catch (Throwable failure) {
            throw new IllegalStateException("generated expression class was rejected", failure);
        }
    }
}
