// FORMULE's expressions: Python's precedence and operators, named reals and functions, math's names,
// and the errors (an unknown name with its place, a wrong number of values, a math domain error).
#include <gtest/gtest.h>

#include <cmath>

#include "commands/formula.hpp"

using namespace lunaster::cmd;

namespace {

double eval(const std::string& text, const std::vector<std::string>& params, const std::vector<double>& values,
            const std::map<std::string, double>& reals = {},
            const std::map<std::string, std::shared_ptr<const RealFunction>>& functions = {}) {
  return compile_formula(text, params, reals, functions)(values);
}

}  // namespace

TEST(Formula, PythonsPrecedenceAndOperators) {
  EXPECT_DOUBLE_EQ(eval("-2**2", {}, {}), -4.0);
  EXPECT_DOUBLE_EQ(eval("2**-1", {}, {}), 0.5);
  EXPECT_DOUBLE_EQ(eval("2**3**2", {}, {}), 512.0);
  EXPECT_DOUBLE_EQ(eval("7 // 2 + 7 % 3 * 2", {}, {}), 5.0);
  EXPECT_DOUBLE_EQ(eval("-7 // 2", {}, {}), -4.0);      // floor division
  EXPECT_DOUBLE_EQ(eval("-7 % 3", {}, {}), 2.0);        // the divisor's sign
  EXPECT_DOUBLE_EQ(eval("1 < X < 3", {"X"}, {2.0}), 1.0);
  EXPECT_DOUBLE_EQ(eval("1 < X < 3", {"X"}, {3.0}), 0.0);
  EXPECT_DOUBLE_EQ(eval("X if X > 0 else -X", {"X"}, {-3.0}), 3.0);
  EXPECT_DOUBLE_EQ(eval("0 or X and 5", {"X"}, {2.0}), 5.0);
  EXPECT_DOUBLE_EQ(eval("not X", {"X"}, {0.0}), 1.0);
  EXPECT_DOUBLE_EQ(eval("1.5e2 + .5 + 1_000", {}, {}), 1150.5);
}

TEST(Formula, ParametersNamedValuesFunctionsAndMath) {
  EXPECT_DOUBLE_EQ(eval("p0*sqrt(1.0-(x/a)*(x/a))", {"x"}, {0.3}, {{"p0", 2.0}, {"a", 0.5}}), 2.0 * std::sqrt(1 - 0.36));
  EXPECT_DOUBLE_EQ(eval("atan2(Y, X) + math.pi + e", {"X", "Y"}, {1.0, 1.0}), M_PI / 4 + M_PI + std::exp(1.0));
  EXPECT_DOUBLE_EQ(eval("max(X, 2, Y) + min(X, Y) + abs(-X) + pow(2, 3) + log(8, 2)", {"X", "Y"}, {1.0, 3.0}),
                   3 + 1 + 1 + 8 + 3);
  auto square = std::make_shared<Formule>();
  square->nom_para = {"T"};
  square->compiled = compile_formula("T*T", {"T"}, {}, {});
  EXPECT_DOUBLE_EQ(eval("F(INST) + 1", {"INST"}, {3.0}, {}, {{"F", square}}), 10.0);
}

TEST(Formula, ErrorsNameWhatAndWhere) {
  try {
    compile_formula("X*2 + Zeta", {"X"}, {{"Zeta0", 1.0}}, {});
    FAIL() << "an unknown name was accepted";
  } catch (const FormulaError& e) {
    EXPECT_EQ(e.what, "unknown name 'Zeta'");
    EXPECT_EQ(e.offset, 6u);
    ASSERT_FALSE(e.hints.empty());
    EXPECT_EQ(e.hints[0], "did you mean 'Zeta0'?");
  }
  EXPECT_THROW(compile_formula("sqrt(X, 2)", {"X"}, {}, {}), FormulaError);
  EXPECT_THROW(compile_formula("X +", {"X"}, {}, {}), FormulaError);
  EXPECT_THROW(compile_formula("X $ 2", {"X"}, {}, {}), FormulaError);
  EXPECT_THROW(compile_formula("sqrt", {"X"}, {}, {}), FormulaError);
  const auto f = compile_formula("sqrt(X) + 1/(X - 4)", {"X"}, {}, {});
  EXPECT_THROW(f({-1.0}), FormulaDomainError);
  EXPECT_THROW(f({4.0}), FormulaDomainError);
  EXPECT_DOUBLE_EQ(f({1.0}), 1.0 - 1.0 / 3.0);
}
