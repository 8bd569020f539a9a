#pragma once
// `conforma contact --fields DIR [--fields-format csv|npy]`: the per-element fields of every patch (pressure,
// traction, micro-slip, adhesion/slip flag, wear index, with their coordinates; the columns of VisitCellFields,
// conforma/wheel_contact_fields.hpp), one file per wheel and patch: DIR/<side>_patch<j>.csv (long format, one row
// per element, a header row of the column names with their units) or .npy (a NumPy structured array, one float64
// field per column, named as the CSV columns; NPY format 1.0).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

struct ContactFieldsArgs {
  std::string folder;          // --fields; empty: no export
  std::string format = "csv";  // --fields-format: csv or npy
  void add_to(CLI::App* app);
  bool enabled() const { return !folder.empty(); }
  // Creates the folder and checks that a file can be written in it; InputError naming --fields otherwise. Called
  // before solving.
  void check_writable() const;
  // Writes the patches of one wheel that have cells (the options' keep_fields), returns the files written; a patch
  // without cells (no tangential solution) is named on `notes`.
  std::vector<std::string> write(const WheelContactReport& report, std::ostream& notes) const;
};

// The NPY file of a table of float64 columns as a structured array (exposed for the test).
void WriteNpyTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& rows);

}  // namespace conforma::cli
