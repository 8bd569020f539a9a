#pragma once
// Reading of CSV files with named columns (kinematics import, track irregularities, ...):
//   * lines starting with '#' and empty lines are ignored anywhere in the file;
//   * the first other line is the header: comma-separated column names (surrounding blanks trimmed), any order,
//     unknown columns ignored;
//   * every further line: as many comma-separated decimal numbers (C locale, exponent allowed) as header names.
// Errors name the file and line (InputError "<file>:<line>: ...").
#include <string>
#include <vector>

namespace conforma {

// Text helpers of the format (also used by writers and other readers).
std::string TrimCsvCell(const std::string& s);                // blanks, tabs and '\r' removed at both ends
std::vector<std::string> SplitCsvCells(const std::string& line);  // cells of one line, trimmed
// A finite number filling the whole cell, else InputError naming column, file and line.
double ParseCsvNumber(const std::string& cell, const std::string& column, const std::string& path, int line);

// The named columns of a whole file: values[c][row] for column names[c]; present[c] false for an optional column
// the file does not have (values[c] empty then); line[row] is the file line of each row.
struct CsvColumns {
  std::vector<std::vector<double>> values;
  std::vector<bool> present;
  std::vector<int> line;
  size_t rows() const { return line.size(); }
};
// The first `required` names must be present (InputError naming the missing one); the others are optional.
CsvColumns ReadCsvColumns(const std::string& path, const std::vector<std::string>& names, size_t required);

}  // namespace conforma
