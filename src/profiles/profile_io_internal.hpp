#pragma once
// Private helpers shared by the profile file readers (src/profile_io_*.cpp).
#include <string>
#include <vector>

#include "conforma/profile_io.hpp"

namespace conforma::profile_io {

std::string lower(std::string s);
std::string trim(const std::string& s);
std::string extension_of(const std::string& path);  // lower case, without the dot
std::vector<std::string> read_lines(const std::string& path);  // throws InputError if unreadable
// Strict number parsing: the whole token must be a finite number.
bool parse_number(const std::string& token, double& value);
// Splits on whitespace, commas and semicolons.
std::vector<std::string> split_fields(const std::string& line);

// Format readers: points in our convention [m] in file order (not yet normalised).
ProfilePoints read_simpack(const std::string& path, const ProfileReadOptions& options);
ProfilePoints read_miniprof(const std::string& path, const ProfileReadOptions& options);
ProfilePoints read_columns(const std::string& path, const ProfileReadOptions& options);

// Common post-processing: ordering from small to large y (sorting unordered clouds when function_of_y; a curve
// that folds back keeps its order), removal of repeated points, self-intersection check with file line numbers.
void finish_points(ProfilePoints& p, const ProfileFitOptions& fit);

// profile_checks.cpp: validation shared by every reader (docs/profiles-and-formats.md §3).
// A last data line cut short: the file does not end with a line break and a number of its last data line has
// fewer digits (fraction or exponent) than the same column on the two data lines before it, or fewer columns.
void check_last_line(const std::string& path, const std::vector<int>& data_lines);
// Spacing, reversals, orientation and noise of the finished points (curve order, our convention).
void check_points(ProfilePoints& p, const ProfileReadOptions& options);  // adds a note on the running surface

}  // namespace conforma::profile_io
