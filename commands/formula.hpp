#pragma once
/// FORMULE's expressions: the Python expression language of code_aster's formulas (numbers, named
/// parameters, named reals and functions, + - * / // % **, comparisons, and/or/not, 'a if c else b',
/// math's functions and constants), read once and evaluated without Python.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "commands/concepts.hpp"

namespace lunaster::cmd {

/// A formula that cannot be read: what is wrong, where (0-based character offset), and hints.
struct FormulaError {
  std::string what;
  std::size_t offset = 0;
  std::vector<std::string> hints;
};

/// A value the formula cannot take (sqrt of a negative number, division by zero): the message.
struct FormulaDomainError {
  std::string what;
};

using CompiledFormula = std::function<double(const std::vector<double>&)>;

/// Reads `text` as an expression of `parameters` (given in this order at evaluation), of the named
/// `reals` and of the named `functions` (called with their parameters in order). Throws FormulaError.
CompiledFormula compile_formula(const std::string& text, const std::vector<std::string>& parameters,
                                const std::map<std::string, double>& reals,
                                const std::map<std::string, std::shared_ptr<const RealFunction>>& functions);

}  // namespace lunaster::cmd
