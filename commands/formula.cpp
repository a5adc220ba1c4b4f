// FORMULE's expressions: a recursive-descent reader of Python's expression grammar (its precedence
// levels, from 'a if c else b' down to '**' and calls), building closures evaluated without Python.
#include "commands/formula.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>

#include "catalog/lookup.hpp"

namespace lunaster::cmd {

namespace {

using Node = std::function<double(const double*)>;

enum class TokenKind { Number, Name, Op, End };

struct FormulaToken {
  TokenKind kind = TokenKind::End;
  std::string text;
  double number = 0;
  std::size_t offset = 0;
};

std::vector<FormulaToken> tokenize_formula(const std::string& s) {
  std::vector<FormulaToken> out;
  std::size_t i = 0;
  const std::size_t n = s.size();
  while (i < n) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isspace(c) || c == '\\') {  // a formula may run over several lines, as in a triple-quoted text
      ++i;
      continue;
    }
    FormulaToken t;
    t.offset = i;
    if (std::isdigit(c) || (c == '.' && i + 1 < n && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      std::size_t k = i;
      std::string digits;
      auto take = [&] {
        while (k < n && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '_')) {
          if (s[k] != '_') digits += s[k];
          ++k;
        }
      };
      take();
      if (k < n && s[k] == '.') {
        digits += s[k++];
        take();
      }
      if (k < n && (s[k] == 'e' || s[k] == 'E')) {
        std::size_t e = k + 1;
        if (e < n && (s[e] == '+' || s[e] == '-')) ++e;
        if (e < n && std::isdigit(static_cast<unsigned char>(s[e]))) {
          digits += 'e';
          if (s[k + 1] == '-' || s[k + 1] == '+') digits += s[k + 1];
          k = e;
          take();
        }
      }
      t.kind = TokenKind::Number;
      t.text = s.substr(i, k - i);
      t.number = std::strtod(digits.c_str(), nullptr);
      out.push_back(t);
      i = k;
      continue;
    }
    if (std::isalpha(c) || c == '_') {
      std::size_t k = i;
      while (k < n && (std::isalnum(static_cast<unsigned char>(s[k])) || s[k] == '_')) ++k;
      t.kind = TokenKind::Name;
      t.text = s.substr(i, k - i);
      out.push_back(t);
      i = k;
      continue;
    }
    static const char* const two[] = {"**", "//", "<=", ">=", "==", "!="};
    t.kind = TokenKind::Op;
    for (const char* op : two)
      if (s.compare(i, 2, op) == 0) t.text = op;
    if (t.text.empty() && std::string("+-*/%<>(),.").find(static_cast<char>(c)) != std::string::npos) t.text = std::string(1, s[i]);
    if (t.text.empty())
      throw FormulaError{"unexpected character '" + std::string(1, s[i]) + "'", i,
                         {"a formula is an expression of numbers, names, operators and calls"}};
    out.push_back(t);
    i += t.text.size();
  }
  FormulaToken end;
  end.offset = n;
  out.push_back(end);
  return out;
}

double domain(bool ok, double value, const char* what) {
  if (!ok) throw FormulaDomainError{std::string("math domain error in ") + what};
  return value;
}

/// math's functions (and Python's abs, min, max, pow): their argument counts and values.
struct Builtin {
  int min_args, max_args;  ///< max -1: any number (min, max, hypot)
  std::function<double(const std::vector<double>&)> fn;
};

const std::map<std::string, Builtin>& builtins() {
  using V = const std::vector<double>&;
  static const std::map<std::string, Builtin> b = {
      {"sqrt", {1, 1, [](V x) { return domain(x[0] >= 0, std::sqrt(x[0]), "sqrt (a negative value)"); }}},
      {"exp", {1, 1, [](V x) { return std::exp(x[0]); }}},
      {"log", {1, 2, [](V x) {
         domain(x[0] > 0 && (x.size() == 1 || (x[1] > 0 && x[1] != 1)), 0, "log (a value <= 0)");
         return x.size() == 1 ? std::log(x[0]) : std::log(x[0]) / std::log(x[1]);
       }}},
      {"log10", {1, 1, [](V x) { return domain(x[0] > 0, std::log10(x[0]), "log10 (a value <= 0)"); }}},
      {"log2", {1, 1, [](V x) { return domain(x[0] > 0, std::log2(x[0]), "log2 (a value <= 0)"); }}},
      {"sin", {1, 1, [](V x) { return std::sin(x[0]); }}},
      {"cos", {1, 1, [](V x) { return std::cos(x[0]); }}},
      {"tan", {1, 1, [](V x) { return std::tan(x[0]); }}},
      {"asin", {1, 1, [](V x) { return domain(std::fabs(x[0]) <= 1, std::asin(x[0]), "asin (a value outside [-1, 1])"); }}},
      {"acos", {1, 1, [](V x) { return domain(std::fabs(x[0]) <= 1, std::acos(x[0]), "acos (a value outside [-1, 1])"); }}},
      {"atan", {1, 1, [](V x) { return std::atan(x[0]); }}},
      {"atan2", {2, 2, [](V x) { return std::atan2(x[0], x[1]); }}},
      {"sinh", {1, 1, [](V x) { return std::sinh(x[0]); }}},
      {"cosh", {1, 1, [](V x) { return std::cosh(x[0]); }}},
      {"tanh", {1, 1, [](V x) { return std::tanh(x[0]); }}},
      {"fabs", {1, 1, [](V x) { return std::fabs(x[0]); }}},
      {"abs", {1, 1, [](V x) { return std::fabs(x[0]); }}},
      {"floor", {1, 1, [](V x) { return std::floor(x[0]); }}},
      {"ceil", {1, 1, [](V x) { return std::ceil(x[0]); }}},
      {"trunc", {1, 1, [](V x) { return std::trunc(x[0]); }}},
      {"int", {1, 1, [](V x) { return std::trunc(x[0]); }}},
      {"float", {1, 1, [](V x) { return x[0]; }}},
      {"fmod", {2, 2, [](V x) { return domain(x[1] != 0, std::fmod(x[0], x[1]), "fmod (by zero)"); }}},
      {"hypot", {1, -1, [](V x) {
         double s = 0;
         for (double v : x) s += v * v;
         return std::sqrt(s);
       }}},
      {"degrees", {1, 1, [](V x) { return x[0] * 180.0 / M_PI; }}},
      {"radians", {1, 1, [](V x) { return x[0] * M_PI / 180.0; }}},
      {"copysign", {2, 2, [](V x) { return std::copysign(x[0], x[1]); }}},
      {"pow", {2, 2, [](V x) {
         return domain(!(x[0] < 0 && std::trunc(x[1]) != x[1]) && !(x[0] == 0 && x[1] < 0), std::pow(x[0], x[1]),
                       "pow (a negative value to a fractional power, or 0 to a negative one)");
       }}},
      {"min", {1, -1, [](V x) { return *std::min_element(x.begin(), x.end()); }}},
      {"max", {1, -1, [](V x) { return *std::max_element(x.begin(), x.end()); }}},
  };
  return b;
}

const std::map<std::string, double>& math_constants() {
  static const std::map<std::string, double> c = {{"pi", M_PI},
                                                  {"e", std::exp(1.0)},
                                                  {"tau", 2 * M_PI},
                                                  {"inf", std::numeric_limits<double>::infinity()},
                                                  {"nan", std::numeric_limits<double>::quiet_NaN()},
                                                  {"True", 1.0},
                                                  {"False", 0.0}};
  return c;
}

class FormulaReader {
 public:
  FormulaReader(const std::string& text, const std::vector<std::string>& parameters,
                const std::map<std::string, double>& reals,
                const std::map<std::string, std::shared_ptr<const RealFunction>>& functions)
      : tokens_(tokenize_formula(text)), parameters_(parameters), reals_(reals), functions_(functions) {}

  Node read() {
    if (peek().kind == TokenKind::End) throw FormulaError{"an empty formula", 0, {"write the expression in VALE"}};
    Node node = ternary();
    if (peek().kind != TokenKind::End) fail("unexpected '" + peek().text + "' after a complete expression");
    return node;
  }

 private:
  std::vector<FormulaToken> tokens_;
  std::size_t at_ = 0;
  const std::vector<std::string>& parameters_;
  const std::map<std::string, double>& reals_;
  const std::map<std::string, std::shared_ptr<const RealFunction>>& functions_;

  const FormulaToken& peek() const { return tokens_[at_]; }
  bool is(const char* text) const { return peek().kind != TokenKind::Number && peek().text == text; }
  bool accept(const char* text) {
    if (!is(text)) return false;
    ++at_;
    return true;
  }
  [[noreturn]] void fail(std::string what, std::vector<std::string> hints = {}) const {
    throw FormulaError{std::move(what), peek().offset, std::move(hints)};
  }
  void expect(const char* text) {
    if (!accept(text))
      fail("expected '" + std::string(text) + "', got " +
           (peek().kind == TokenKind::End ? std::string("the end of the formula") : "'" + peek().text + "'"));
  }

  Node ternary() {
    Node value = disjunction();
    if (!accept("if")) return value;
    Node condition = disjunction();
    expect("else");
    Node otherwise = ternary();
    return [value, condition, otherwise](const double* v) { return condition(v) != 0 ? value(v) : otherwise(v); };
  }
  Node disjunction() {
    Node left = conjunction();
    while (accept("or")) {
      Node right = conjunction();
      left = [left, right](const double* v) {
        const double a = left(v);
        return a != 0 ? a : right(v);
      };
    }
    return left;
  }
  Node conjunction() {
    Node left = negation();
    while (accept("and")) {
      Node right = negation();
      left = [left, right](const double* v) {
        const double a = left(v);
        return a == 0 ? a : right(v);
      };
    }
    return left;
  }
  Node negation() {
    if (accept("not")) {
      Node operand = negation();
      return [operand](const double* v) { return operand(v) == 0 ? 1.0 : 0.0; };
    }
    return comparison();
  }
  Node comparison() {
    Node first = arithmetic();
    std::vector<std::pair<std::string, Node>> chain;
    for (;;) {
      const std::string op = peek().kind == TokenKind::Op ? peek().text : "";
      if (op != "<" && op != "<=" && op != ">" && op != ">=" && op != "==" && op != "!=") break;
      ++at_;
      chain.emplace_back(op, arithmetic());
    }
    if (chain.empty()) return first;
    return [first, chain](const double* v) {  // a < b < c: each pair compared, as Python chains them
      double left = first(v);
      for (const auto& [op, node] : chain) {
        const double right = node(v);
        const bool ok = op == "<" ? left < right : op == "<=" ? left <= right : op == ">" ? left > right
                        : op == ">=" ? left >= right : op == "==" ? left == right : left != right;
        if (!ok) return 0.0;
        left = right;
      }
      return 1.0;
    };
  }
  Node arithmetic() {
    Node left = term();
    for (;;) {
      if (accept("+")) {
        Node right = term();
        left = [left, right](const double* v) { return left(v) + right(v); };
      } else if (accept("-")) {
        Node right = term();
        left = [left, right](const double* v) { return left(v) - right(v); };
      } else {
        return left;
      }
    }
  }
  Node term() {
    Node left = unary();
    for (;;) {
      std::string op = peek().kind == TokenKind::Op ? peek().text : "";
      if (op != "*" && op != "/" && op != "//" && op != "%") return left;
      ++at_;
      Node right = unary();
      if (op == "*") left = [left, right](const double* v) { return left(v) * right(v); };
      else if (op == "/")
        left = [left, right](const double* v) {
          const double d = right(v);
          if (d == 0) throw FormulaDomainError{"division by zero"};
          return left(v) / d;
        };
      else
        left = [left, right, floor_division = op == "//"](const double* v) {
          const double a = left(v), b = right(v);
          if (b == 0) throw FormulaDomainError{floor_division ? "integer division by zero" : "modulo by zero"};
          const double q = std::floor(a / b);
          return floor_division ? q : a - b * q;  // Python's: the remainder takes the divisor's sign
        };
    }
  }
  Node unary() {
    if (accept("-")) {
      Node operand = unary();
      return [operand](const double* v) { return -operand(v); };
    }
    if (accept("+")) return unary();
    return power();
  }
  Node power() {
    Node base = call();
    if (!accept("**")) return base;
    Node exponent = unary();  // right-associative, and binds tighter than a unary minus on its left
    return [base, exponent](const double* v) {
      const double a = base(v), b = exponent(v);
      if (a < 0 && std::trunc(b) != b) throw FormulaDomainError{"a negative number to a fractional power"};
      if (a == 0 && b < 0) throw FormulaDomainError{"0 to a negative power"};
      return std::pow(a, b);
    };
  }
  std::vector<Node> arguments() {
    std::vector<Node> args;
    if (accept(")")) return args;
    for (;;) {
      args.push_back(ternary());
      if (accept(")")) return args;
      expect(",");
      if (accept(")")) return args;
    }
  }
  Node call() {
    const FormulaToken t = peek();
    if (t.kind == TokenKind::Number) {
      ++at_;
      const double x = t.number;
      return [x](const double*) { return x; };
    }
    if (accept("(")) {
      Node inner = ternary();
      expect(")");
      return inner;
    }
    if (t.kind != TokenKind::Name) {
      if (t.kind == TokenKind::End) fail("the formula ends where a value was expected");
      fail("unexpected '" + t.text + "' where a value was expected");
    }
    ++at_;
    std::string name = t.text;
    if (name == "math" && accept(".")) {  // math.sqrt, math.pi
      if (peek().kind != TokenKind::Name) fail("expected a name of math after 'math.'");
      name = peek().text;
      ++at_;
      if (!builtins().count(name) && !math_constants().count(name)) fail("math has no '" + name + "'");
    }
    if (is("(")) {
      ++at_;
      const std::size_t where = t.offset;
      std::vector<Node> args = arguments();
      return function_call(name, std::move(args), where);
    }
    const auto p = std::find(parameters_.begin(), parameters_.end(), name);
    if (p != parameters_.end()) {
      const std::size_t i = static_cast<std::size_t>(p - parameters_.begin());
      return [i](const double* v) { return v[i]; };
    }
    if (auto r = reals_.find(name); r != reals_.end()) {
      const double x = r->second;
      return [x](const double*) { return x; };
    }
    if (auto c = math_constants().find(name); c != math_constants().end()) {
      const double x = c->second;
      return [x](const double*) { return x; };
    }
    if (functions_.count(name) || builtins().count(name))
      throw FormulaError{"'" + name + "' is a function: call it, " + name + "(...)", t.offset, {}};
    throw FormulaError{"unknown name '" + name + "'", t.offset, unknown_hints(name)};
  }

  std::vector<std::string> unknown_hints(const std::string& name) const {
    std::vector<std::string> names = parameters_;
    for (const auto& [n, x] : reals_) names.push_back(n);
    for (const auto& [n, f] : functions_) names.push_back(n);
    std::string list;
    for (const auto& n : parameters_) list += (list.empty() ? "" : ", ") + n;
    std::vector<std::string> hints = {"the parameters (NOM_PARA) are " + list +
                                      "; any other name is given as a keyword: FORMULE(VALE=..., NOM_PARA=..., " + name +
                                      "=" + name + ")"};
    const std::string close = catalog::closest_name(name, names);
    if (!close.empty()) hints.insert(hints.begin(), "did you mean '" + close + "'?");
    return hints;
  }

  Node function_call(const std::string& name, std::vector<Node> args, std::size_t where) {
    const int n = static_cast<int>(args.size());
    auto evaluate_args = [args](const double* v) {
      std::vector<double> x;
      x.reserve(args.size());
      for (const auto& a : args) x.push_back(a(v));
      return x;
    };
    if (auto f = functions_.find(name); f != functions_.end()) {
      const auto function = f->second;
      const auto params = function->parameters();
      if (!params.empty() && params.size() != args.size())
        throw FormulaError{"'" + name + "' takes " + std::to_string(params.size()) + " value(s), given " + std::to_string(n),
                           where, {}};
      return [function, evaluate_args](const double* v) { return function->evaluate(evaluate_args(v)); };
    }
    auto b = builtins().find(name);
    if (b == builtins().end()) {
      if (std::find(parameters_.begin(), parameters_.end(), name) != parameters_.end() || reals_.count(name))
        throw FormulaError{"'" + name + "' is a number, not a function", where, {}};
      throw FormulaError{"unknown function '" + name + "'", where, unknown_hints(name)};
    }
    const Builtin& builtin = b->second;
    if (n < builtin.min_args || (builtin.max_args >= 0 && n > builtin.max_args))
      throw FormulaError{"'" + name + "' takes " +
                             (builtin.min_args == builtin.max_args ? std::to_string(builtin.min_args)
                                                                   : std::to_string(builtin.min_args) + " or more") +
                             " value(s), given " + std::to_string(n),
                         where, {}};
    const auto fn = builtin.fn;
    return [fn, evaluate_args](const double* v) { return fn(evaluate_args(v)); };
  }
};

}  // namespace

CompiledFormula compile_formula(const std::string& text, const std::vector<std::string>& parameters,
                                const std::map<std::string, double>& reals,
                                const std::map<std::string, std::shared_ptr<const RealFunction>>& functions) {
  Node node = FormulaReader(text, parameters, reals, functions).read();
  return [node](const std::vector<double>& values) { return node(values.data()); };
}

}  // namespace lunaster::cmd
