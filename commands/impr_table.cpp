// IMPR_TABLE: writes a table as code_aster's TABLEAU text (aligned columns) or, with a
// SEPARATEUR other than ' ', as unpadded separated values (CSV).
#include <algorithm>
#include <fstream>
#include <sstream>

#include "commands/commands.hpp"
#include "commands/table.hpp"
#include "engine/io/atomic_file.hpp"

namespace lunaster::cmd {

namespace {

std::filesystem::path output_path(const Args& args, const Session& session) {
  if (args.has("FICHIER")) return session.output_file(args.text("FICHIER"));
  return session.unit_output_file(static_cast<int>(args.integer("UNITE")), "tab");
}

std::string trimmed(const std::string& text) {
  const size_t first = text.find_first_not_of(' ');
  return first == std::string::npos ? std::string() : text.substr(first);
}

/// A cell of a separated-values file: quoted when it holds the separator or a quote.
std::string csv_cell(const std::string& text, const std::string& separator) {
  if (text.find(separator) == std::string::npos && text.find('"') == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void write_table(std::ostream& out, const Args& args, const Table& table, const std::vector<int>& cols) {
  const std::string sep = args.text("SEPARATEUR");
  const std::string format_r = args.text("FORMAT_R");
  const bool aligned = sep == " ";
  std::vector<std::vector<std::string>> text(static_cast<size_t>(table.n_rows()) + 1);
  for (int c : cols) text[0].push_back(table.columns[static_cast<size_t>(c)].name);
  for (int r = 0; r < table.n_rows(); ++r)
    for (int c : cols) {
      const Cell& cell = table.columns[static_cast<size_t>(c)].cells[static_cast<size_t>(r)];
      text[static_cast<size_t>(r) + 1].push_back(
          aligned ? format_cell(cell, format_r)
                  : (std::holds_alternative<std::monostate>(cell) ? std::string() : trimmed(format_cell(cell, format_r))));
    }
  std::vector<size_t> width(cols.size(), 0);
  for (const auto& line : text)
    for (size_t k = 0; k < line.size(); ++k) width[k] = std::max(width[k], line[k].size());
  const std::string comment = args.text("COMMENTAIRE");
  out << comment << std::string(79, '-') << '\n';
  out << comment << "TABLE " << (table.user_name.empty() ? "-" : table.user_name) << ": " << table.n_rows()
      << " row(s), " << cols.size() << " parameter(s)\n";
  for (const auto& line : text) {
    for (size_t k = 0; k < line.size(); ++k) {
      if (k) out << sep;
      const std::string pad(width[k] - line[k].size(), ' ');
      if (!aligned) out << csv_cell(line[k], sep);
      else if (table.columns[static_cast<size_t>(cols[k])].type != 'K') out << pad << line[k];  // numbers to the right
      else out << line[k] << (k + 1 == line.size() ? "" : pad);
    }
    out << '\n';
  }
}

}  // namespace

ConceptPtr impr_table(const Args& args, Session& session) {
  auto table = args.concept_as<Table>("TABLE");
  if (!valid_real_format(args.text("FORMAT_R")))
    throw args.error("FORMAT_R", "a Fortran-like real format such as E12.5, F12.3 or G15.8", "'" + args.text("FORMAT_R") + "'");
  std::vector<int> cols;
  if (args.has("NOM_PARA")) {
    for (const auto& name : args.texts("NOM_PARA")) {
      const int c = table->column_index(name);
      if (c < 0)
        throw args.error("NOM_PARA", "a parameter of " + table->label() + " (" + table->parameter_list() + ")",
                         "'" + name + "'");
      cols.push_back(c);
    }
  } else {
    for (size_t c = 0; c < table->columns.size(); ++c) cols.push_back(static_cast<int>(c));
  }
  const std::filesystem::path path = output_path(args, session);
  std::string before;
  if (session.table_files.count(path)) {  // a second table on the same unit follows the first
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    before = content.str();
  }
  engine::write_file_atomically(path, [&](std::ostream& out) {
    out << before;
    write_table(out, args, *table, cols);
  });
  session.table_files.insert(path);
  session.log().info("IMPR_TABLE: " + table->label() + " written to " + path.string());
  return nullptr;
}

}  // namespace lunaster::cmd
