package minigolf.expr;

import java.util.ArrayList;
import java.util.List;
import minigolf.expr.Lexer.Kind;
import minigolf.expr.Lexer.Token;

/**
 * Recursive-descent parser for the terrain grammar:
 * <pre>
 * sum     := product (('+' | '-') product)*
 * product := unary (('*' | '/') unary)*
 * unary   := ('-' | '+') unary | power
 * power   := primary ('^' unary)?          right-associative; the exponent may carry a sign
 * primary := number | x | y | pi | e | function '(' sum (',' sum)* ')' | '(' sum ')'
 * </pre>
 * Limits keep hostile input from exhausting the stack or memory of the code that walks the tree.
 */
final class Parser {
    static final int MAX_LENGTH = 100_000;
    /** Levels of parentheses, signs, exponents and calls inside one another. */
    static final int MAX_NESTING = 200;
    /** Height of the tree, which long chains like 1+1+1+... grow without nesting. */
    static final int MAX_HEIGHT = 300;

    /** A subtree with its height, tracked while parsing so the limit is checked where it is exceeded. */
    private record Parsed(Node node, int height) {
    }

    private final Lexer lexer;
    private Token current;
    private int nesting;

    private Parser(String source) {
        this.lexer = new Lexer(source);
    }

    static Node parse(String source) {
        if (source == null) {
            throw new ExpressionException("no expression given", 1);
        }
        if (source.length() > MAX_LENGTH) {
            throw new ExpressionException("expression too long (" + source.length() + " characters)",
                    MAX_LENGTH + 1, "limit is " + MAX_LENGTH);
        }
        if (source.isBlank()) {
            throw new ExpressionException("empty expression", 1, "write a formula such as 0.1*sin(x)");
        }
        Parser parser = new Parser(source);
        parser.advance();
        Node result = parser.sum().node;
        if (parser.current.kind() != Kind.END) {
            throw parser.unexpectedAfterExpression();
        }
        return result;
    }

    private ExpressionException unexpectedAfterExpression() {
        if (current.kind() == Kind.CLOSE) {
            return new ExpressionException("unexpected ')'", current.column(), "no matching '('");
        }
        return new ExpressionException("unexpected " + current.describe(), current.column(),
                "expected an operator or end of input");
    }

    private Parsed sum() {
        Parsed left = product();
        while (current.kind() == Kind.PLUS || current.kind() == Kind.MINUS) {
            Token operator = current;
            advance();
            Parsed right = product();
            left = binary(operator, operator.kind() == Kind.PLUS ? BinaryOperator.ADD : BinaryOperator.SUBTRACT,
                    left, right);
        }
        return left;
    }

    private Parsed product() {
        Parsed left = unary();
        while (current.kind() == Kind.STAR || current.kind() == Kind.SLASH) {
            Token operator = current;
            advance();
            Parsed right = unary();
            left = binary(operator,
                    operator.kind() == Kind.STAR ? BinaryOperator.MULTIPLY : BinaryOperator.DIVIDE, left, right);
        }
        return left;
    }

    /** Every level of nesting passes through here, so this is where the nesting limit is enforced. */
    private Parsed unary() {
        if (++nesting > MAX_NESTING) {
            throw new ExpressionException("expression nested too deeply", current.column(),
                    "limit is " + MAX_NESTING + " levels");
        }
        Parsed result;
        if (current.kind() == Kind.MINUS) {
            Token sign = current;
            advance();
            Parsed operand = unary();
            result = withHeight(new Node.Negate(operand.node), operand.height + 1, sign);
        } else if (current.kind() == Kind.PLUS) {
            advance();
            result = unary();
        } else {
            result = power();
        }
        nesting--;
        return result;
    }

    private Parsed power() {
        Parsed base = primary();
        if (current.kind() != Kind.CARET) {
            return base;
        }
        Token caret = current;
        advance();
        Parsed exponent = unary();
        return binary(caret, BinaryOperator.POWER, base, exponent);
    }

    private Parsed primary() {
        Token token = current;
        switch (token.kind()) {
            case NUMBER:
                advance();
                return new Parsed(new Node.Constant(token.value()), 1);
            case NAME:
                return lexer.nextIsOpenParenthesis() ? call(token) : name(token);
            case OPEN: {
                advance();
                Parsed inner = sum();
                expectClosingParenthesis();
                return inner;
            }
            default:
                throw new ExpressionException("expected a number, x, y, a function or '(' but found "
                        + token.describe(), token.column());
        }
    }

    private Parsed name(Token token) {
        Node node;
        switch (token.text()) {
            case "x":
            case "y":
                node = new Node.Variable(token.text().charAt(0));
                break;
            case "pi":
                node = new Node.Constant(Math.PI);
                break;
            case "e":
                node = new Node.Constant(Math.E);
                break;
            default:
                if (MathFunction.byName(token.text()) != null) {
                    throw new ExpressionException("function '" + token.text() + "' needs arguments",
                            token.column() + token.text().length(), "write " + token.text() + "(...)");
                }
                throw new ExpressionException("unknown name '" + Lexer.abbreviate(token.text()) + "'",
                        token.column(), "allowed: x, y, pi, e");
        }
        advance();
        return new Parsed(node, 1);
    }

    private Parsed call(Token nameToken) {
        MathFunction function = MathFunction.byName(nameToken.text());
        if (function == null) {
            throw new ExpressionException("unknown function '" + Lexer.abbreviate(nameToken.text()) + "'",
                    nameToken.column(), "allowed: " + MathFunction.allowedNames());
        }
        advance(); // the name
        advance(); // the '('
        List<Node> arguments = new ArrayList<>();
        int height = 0;
        while (true) {
            if (current.kind() == Kind.CLOSE && arguments.size() < function.arity) {
                throw wrongArgumentCount("too few", function, current);
            }
            Parsed argument = sum();
            arguments.add(argument.node);
            height = Math.max(height, argument.height);
            if (current.kind() != Kind.COMMA) {
                break;
            }
            if (arguments.size() == function.arity) {
                throw wrongArgumentCount("too many", function, current);
            }
            advance();
        }
        if (arguments.size() < function.arity && current.kind() == Kind.CLOSE) {
            throw wrongArgumentCount("too few", function, current);
        }
        expectClosingParenthesis();
        if (function == MathFunction.POW) {
            return withHeight(new Node.Binary(BinaryOperator.POWER, arguments.get(0), arguments.get(1)),
                    height + 1, nameToken);
        }
        return withHeight(new Node.Call(function, arguments), height + 1, nameToken);
    }

    private static ExpressionException wrongArgumentCount(String tooFewOrMany, MathFunction function, Token at) {
        String takes = function.arity == 1 ? "1 argument" : function.arity + " arguments";
        return new ExpressionException(tooFewOrMany + " arguments for '" + function.functionName + "'",
                at.column(), function.functionName + " takes " + takes);
    }

    private void expectClosingParenthesis() {
        if (current.kind() != Kind.CLOSE) {
            throw new ExpressionException("expected ')'", current.column(), "found " + current.describe());
        }
        advance();
    }

    private Parsed binary(Token operator, BinaryOperator kind, Parsed left, Parsed right) {
        return withHeight(new Node.Binary(kind, left.node, right.node),
                Math.max(left.height, right.height) + 1, operator);
    }

    private static Parsed withHeight(Node node, int height, Token at) {
        if (height > MAX_HEIGHT) {
            throw new ExpressionException("expression too complex", at.column(),
                    "more than " + MAX_HEIGHT + " operations chained together");
        }
        return new Parsed(node, height);
    }

    private void advance() {
        current = lexer.next();
    }
}
