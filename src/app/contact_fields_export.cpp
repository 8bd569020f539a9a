// contact --fields: per-element fields of the patches as CSV or NPY (contact_fields_export.hpp).
#include "contact_fields_export.hpp"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "cli_checks.hpp"
#include "conforma/error.hpp"
#include "conforma/wheel_contact_fields.hpp"

namespace conforma::cli {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> CellColumns() {
  std::vector<std::string> columns;
  VisitCellFields(ContactCell{}, [&columns](const char* name, const auto&) { columns.emplace_back(name); });
  return columns;
}

std::vector<double> CellRow(const ContactCell& c) {
  std::vector<double> row;
  VisitCellFields(c, [&row](const char*, const auto& value) { row.push_back(static_cast<double>(value)); });
  return row;
}

void WriteCsvTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& rows) {
  std::ofstream out(path);
  for (size_t k = 0; k < columns.size(); ++k) out << (k ? "," : "") << columns[k];
  out << '\n';
  out.precision(17);
  for (const std::vector<double>& row : rows) {
    for (size_t k = 0; k < row.size(); ++k) out << (k ? "," : "") << row[k];
    out << '\n';
  }
  if (!out) throw InputError("option --fields: cannot write '" + path + "'");
}

}  // namespace

// NPY format 1.0 (numpy.lib.format): magic "\x93NUMPY", version 1 0, header length (uint16 little endian), the
// header (a Python dict literal: descr, fortran_order, shape) padded with spaces and ended by '\n' so that the data
// starts at a multiple of 64 bytes, then the data (C order). Here a structured array of little-endian float64.
void WriteNpyTable(const std::string& path, const std::vector<std::string>& columns,
                   const std::vector<std::vector<double>>& rows) {
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  if (first != 1) throw std::runtime_error("NPY output assumes a little-endian machine");
  std::string header = "{'descr': [";
  for (const std::string& c : columns) header += "('" + c + "', '<f8'), ";
  header += "], 'fortran_order': False, 'shape': (" + std::to_string(rows.size()) + ",), }";
  const size_t preamble = 10;  // magic (6) + version (2) + header length (2)
  const size_t total = (preamble + header.size() + 1 + 63) / 64 * 64;
  header.append(total - preamble - header.size() - 1, ' ');
  header += '\n';
  if (header.size() > 65535) throw InputError("option --fields: too many columns for an NPY 1.0 header");
  std::ofstream out(path, std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const std::uint16_t length = static_cast<std::uint16_t>(header.size());
  const unsigned char length_bytes[2] = {static_cast<unsigned char>(length & 0xff),
                                         static_cast<unsigned char>(length >> 8)};
  out.write(reinterpret_cast<const char*>(length_bytes), 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  for (const std::vector<double>& row : rows)
    out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * sizeof(double)));
  if (!out) throw InputError("option --fields: cannot write '" + path + "'");
}

void ContactFieldsArgs::add_to(CLI::App* app) {
  app->add_option("--fields", folder, "write the per-element fields of every patch (pressure, traction, micro-slip, "
                                      "adhesion/slip, wear index, coordinates) to this folder, one file per wheel "
                                      "and patch: <side>_patch<j>.csv or .npy");
  app->add_option("--fields-format", format, "format of --fields: csv (long format, header with units) or npy "
                                             "(NumPy structured array, the same column names)")
      ->check(CLI::IsMember({"csv", "npy"}));
}

void ContactFieldsArgs::check_writable() const {
  if (enabled()) EnsureOutputFolder(folder, "--fields");
}

std::vector<std::string> ContactFieldsArgs::write(const WheelContactReport& report, std::ostream& notes) const {
  std::vector<std::string> files;
  if (!enabled()) return files;
  const std::vector<std::string> columns = CellColumns();
  for (size_t j = 0; j < report.patches.size(); ++j) {
    const PatchReport& p = report.patches[j];
    const std::string name = std::string(to_string(report.side)) + "_patch" + std::to_string(j);
    if (p.cells.empty()) {
      notes << "note: --fields: " << name << " has no fields (tangential status " << p.tangential_status
            << "): no file written\n";
      continue;
    }
    std::vector<std::vector<double>> rows;
    rows.reserve(p.cells.size());
    for (const ContactCell& c : p.cells) rows.push_back(CellRow(c));
    const std::string path = (fs::path(folder) / (name + "." + format)).string();
    if (format == "npy")
      WriteNpyTable(path, columns, rows);
    else
      WriteCsvTable(path, columns, rows);
    files.push_back(path);
  }
  return files;
}

}  // namespace conforma::cli
