#pragma once
// CSV as the accuracy files use it (RFC 4180: comma-separated, fields with a comma,
// quote or line break in double quotes, "" for a quote), read with the line and
// column where every cell began so a reader can point at the one at fault.
// Plain C++, so the fuzzer drives it.
#include "device/files/accuracy/file_problem.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::files::accuracy {

struct CsvCell {
    std::string text;   ///< unquoted; an unquoted cell is trimmed of spaces and tabs
    int column = 1;     ///< 1-based, in characters, where the cell began
};

struct CsvRow {
    int line = 1;
    std::vector<CsvCell> cells;
};

struct CsvTable {
    std::vector<CsvRow> rows;   ///< blank lines left out
    motion::msg::Problems problems;      ///< file.csv.unterminated_quote, file.csv.text_after_quote
};

/// A UTF-8 byte-order mark at the start is skipped (spreadsheets write one).
CsvTable parseCsv(std::string_view text, std::string_view file);

/// A decimal number as CSV files write it: digits, '.', an exponent, a leading
/// sign ('+' too, as gauges print it). Not the locale's: a decimal comma is not a
/// number here. "nan" and "inf" are read (and refused as not finite by the caller).
std::optional<double> parseNumber(std::string_view text);

/// A–Z to a–z, nothing else.
std::string asciiLower(std::string_view s);

/// The header's column of that name (case-insensitive), or -1.
int findColumn(const CsvRow& header, std::string_view name);

/// A length column: named stem + "_" + unit, the unit one of mm, um (µm), nm, m,
/// in; toMm converts its values. index −1 when there is none (accuracy.csv.
/// missing_column, naming `usualName`), −2 for a unit it cannot read
/// (accuracy.csv.unknown_unit) or two such columns (accuracy.csv.duplicate_column).
struct LengthColumn {
    int index = -1;
    double toMm = 1;
};
LengthColumn findLengthColumn(const CsvRow& header, const std::string& stem, const std::string& usualName, std::string_view file, motion::msg::Problems& out);

/// The column of that name, or −1 with accuracy.csv.missing_column.
int findRequiredColumn(const CsvRow& header, const char* name, std::string_view file, motion::msg::Problems& out);

/// A header written for semicolons (a spreadsheet in a decimal-comma locale): one
/// cell that contains ';'. Readers refuse it with file.csv.semicolons.
bool looksSemicolonSeparated(const CsvRow& header);

/// One CSV field for a writer, quoted when it needs to be.
std::string csvField(const std::string& text);

/// A number for a writer: the shortest text that reads back to the same double.
std::string csvNumber(double v);

} // namespace dev::files::accuracy
