#include "engine/core/error.hpp"

namespace lunaster {

Error::Error(ErrorKind kind, std::string message, std::vector<std::string> hints)
    : std::runtime_error(message), kind_(kind), message_(std::move(message)), hints_(std::move(hints)) {
  refresh();
}

void Error::fill_context(const ErrorContext& outer) {
  if (context_.file.empty()) context_.file = outer.file;
  if (context_.line == 0) context_.line = outer.line;
  if (context_.command.empty()) context_.command = outer.command;
  if (context_.keyword_path.empty()) context_.keyword_path = outer.keyword_path;
  refresh();
}

std::string Error::format() const {
  std::string out;
  if (!context_.file.empty()) {
    out += context_.file;
    if (context_.line > 0) {
      out += ':';
      out += std::to_string(context_.line);
    }
    out += ": ";
  }
  if (!context_.command.empty()) out += context_.command + ": ";
  if (!context_.keyword_path.empty()) out += context_.keyword_path + ": ";
  out += message_;
  for (const auto& hint : hints_) out += "\n    " + hint;
  return out;
}

DeckError DeckError::at(std::string keyword_path, const std::string& expected, const std::string& given,
                        std::vector<std::string> hints) {
  DeckError err("expected " + expected + ", got " + given, std::move(hints));
  ErrorContext ctx;
  ctx.keyword_path = std::move(keyword_path);
  err.fill_context(ctx);
  return err;
}

void assertion_failed(const char* expr, const std::string& msg, const char* file, int line) {
  throw InternalError(std::string("assertion '") + expr + "' failed at " + file + ":" + std::to_string(line) +
                      (msg.empty() ? "" : ": " + msg));
}

SolveError SolveError::out_of_memory(const std::string& backend, long long n_equations, const std::string& detail) {
  std::string message = backend;
  message.append(": out of memory factorising ").append(std::to_string(n_equations)).append(" equations (");
  message.append(detail).append(")");
  SolveError e(std::move(message), {"the factors do not fit in this machine's memory: the MUMPS backend (least "
                                    "fill-in on contact systems), a coarser mesh, or a larger machine"});
  e.out_of_memory_ = true;
  e.failure().what = Failure::What::OutOfMemory;
  return e;
}

}  // namespace lunaster
