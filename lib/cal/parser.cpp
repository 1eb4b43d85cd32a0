#include "cal/parser.h"

#include "cal/lexer.h"

namespace brume::cal {

namespace {

class Parser {
public:
    Parser(std::string_view text, std::string file, int firstLine) : lex_(text, std::move(file), firstLine) {}

    std::vector<Definition> definitions(const std::string& file) {
        std::vector<Definition> defs;
        while (lex_.peek().kind != Token::Kind::End) {
            if (!lex_.peek().is(';')) {
                defs.push_back(definition(file));
                if (lex_.peek().kind == Token::Kind::End) break;
                if (!lex_.peek().is(';')) lex_.fail("';' expected");
            }
            lex_.next();
        }
        return defs;
    }

    Expr wholeExpression() {
        Expr e = sum();
        if (lex_.peek().kind != Token::Kind::End) lex_.fail("unexpected text after the expression");
        return e;
    }

private:
    Definition definition(const std::string& file) {
        Definition d;
        d.where = {file, lex_.peek().line};
        if (lex_.peek().kind == Token::Kind::Channel) lex_.fail("channel assignments are for rcalc, not a renderer");
        if (lex_.peek().kind != Token::Kind::Name) lex_.fail("name of a definition expected");
        d.name = lex_.next().text;
        if (lex_.peek().is('(')) {
            do {
                lex_.next();
                const Token& t = lex_.peek();
                if (t.kind != Token::Kind::Name || t.text.find('`') != std::string_view::npos)
                    lex_.fail("parameter name expected");
                d.params.emplace_back(lex_.next().text);
            } while (lex_.peek().is(','));
            expect(')');
        }
        if (!lex_.peek().is('=') && !lex_.peek().is(':')) lex_.fail("'=' or ':' expected");
        d.constant = lex_.next().is(':');
        d.body = sum();
        return d;
    }

    Expr sum() {
        Nesting nest(*this);
        return chain(Expr::Kind::Sum, '+', '-', &Parser::product);
    }

    Expr product() { return chain(Expr::Kind::Product, '*', '/', &Parser::power); }

    // operand { (op1 | op2) operand } as one node, or just the operand.
    Expr chain(Expr::Kind kind, char op1, char op2, Expr (Parser::*operand)()) {
        Expr first = (this->*operand)();
        if (!lex_.peek().is(op1) && !lex_.peek().is(op2)) return first;
        Expr e = node(kind);
        e.ops.push_back(op1);
        e.kids.push_back(std::move(first));
        while (lex_.peek().is(op1) || lex_.peek().is(op2)) {
            e.ops.push_back(lex_.next().text[0]);
            e.kids.push_back((this->*operand)());
        }
        return e;
    }

    Expr power() {
        Expr base = unary();
        if (!lex_.peek().is('^')) return base;
        Nesting nest(*this);
        Expr e = node(Expr::Kind::Power);
        lex_.next();
        e.kids.push_back(std::move(base));
        e.kids.push_back(power());
        return e;
    }

    Expr unary() {
        if (lex_.peek().is('+')) {
            lex_.next();
            return primary();
        }
        if (!lex_.peek().is('-')) return primary();
        Expr e = node(Expr::Kind::Negate);
        lex_.next();
        Expr operand = primary();
        if (operand.kind == Expr::Kind::Number) {
            operand.number = -operand.number;
            return operand;
        }
        e.kids.push_back(std::move(operand));
        return e;
    }

    Expr primary() {
        const Token& t = lex_.peek();
        Expr e = node(Expr::Kind::Number);
        switch (t.kind) {
            case Token::Kind::Number:
                e.number = lex_.next().number;
                return e;
            case Token::Kind::Channel:
                e.kind = Expr::Kind::Channel;
                e.channel = lex_.next().channel;
                return e;
            case Token::Kind::Name:
                e.kind = Expr::Kind::Name;
                e.name = lex_.next().text;
                if (lex_.peek().is('(')) call(e);
                return e;
            default:
                break;
        }
        if (!t.is('(')) lex_.fail("expression expected");
        lex_.next();
        e = sum();
        expect(')');
        return e;
    }

    void call(Expr& e) {
        e.kind = Expr::Kind::Call;
        do {
            lex_.next();
            e.kids.push_back(sum());
        } while (lex_.peek().is(','));
        expect(')');
    }

    Expr node(Expr::Kind kind) const {
        Expr e;
        e.kind = kind;
        e.line = lex_.peek().line;
        return e;
    }

    void expect(char symbol) {
        if (!lex_.peek().is(symbol)) lex_.fail(std::string("'") + symbol + "' expected");
        lex_.next();
    }

    // Counts the nesting of sums (parentheses, call arguments) and powers.
    struct Nesting {
        explicit Nesting(Parser& p) : p(p) {
            if (++p.depth_ > kMaxNesting) p.lex_.fail("expression nested too deeply");
        }
        ~Nesting() { --p.depth_; }
        Parser& p;
    };

    Lexer lex_;
    int depth_ = 0;
};

}  // namespace

std::vector<Definition> parseDefinitions(std::string_view text, const std::string& file, int firstLine) {
    return Parser(text, file, firstLine).definitions(file);
}

Expr parseExpression(std::string_view text, const SourceLocation& where) {
    return Parser(text, where.file, where.line).wholeExpression();
}

}  // namespace brume::cal
