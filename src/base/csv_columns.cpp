// Named-column CSV reading (csv_columns.hpp).
#include "conforma/csv_columns.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "conforma/error.hpp"

namespace conforma {

std::string TrimCsvCell(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return std::string();
  const size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> SplitCsvCells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(TrimCsvCell(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

double ParseCsvNumber(const std::string& cell, const std::string& column, const std::string& path, int line) {
  if (cell.empty()) throw InputError(path, line, "empty cell in column '" + column + "'");
  char* end = nullptr;  // ERANGE on underflow is fine (subnormals round-trip); overflow gives inf, caught below
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size())
    throw InputError(path, line, "column '" + column + "': '" + cell + "' is not a number");
  if (!std::isfinite(v)) throw InputError(path, line, "column '" + column + "': value must be finite");
  return v;
}

CsvColumns ReadCsvColumns(const std::string& path, const std::vector<std::string>& names, size_t required) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open file");
  CsvColumns table;
  table.values.assign(names.size(), {});
  table.present.assign(names.size(), false);
  std::vector<int> index(names.size(), -1);
  size_t header_cells = 0;
  bool have_header = false;
  std::string text;
  int line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    const std::string t = TrimCsvCell(text);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> cells = SplitCsvCells(t);
    if (!have_header) {
      header_cells = cells.size();
      for (size_t k = 0; k < cells.size(); ++k)
        for (size_t c = 0; c < names.size(); ++c)
          if (cells[k] == names[c]) {
            if (index[c] >= 0) throw InputError(path, line_no, "column '" + cells[k] + "' appears twice");
            index[c] = static_cast<int>(k);
          }
      for (size_t c = 0; c < required; ++c)
        if (index[c] < 0) throw InputError(path, line_no, "missing required column '" + names[c] + "'");
      for (size_t c = 0; c < names.size(); ++c) table.present[c] = index[c] >= 0;
      have_header = true;
      continue;
    }
    if (cells.size() != header_cells)
      throw InputError(path, line_no, "expected " + std::to_string(header_cells) + " cells, found " +
                                          std::to_string(cells.size()));
    for (size_t c = 0; c < names.size(); ++c)
      if (index[c] >= 0) table.values[c].push_back(ParseCsvNumber(cells[index[c]], names[c], path, line_no));
    table.line.push_back(line_no);
  }
  if (!have_header) throw InputError(path, line_no, "no header line (column names) found");
  return table;
}

}  // namespace conforma
