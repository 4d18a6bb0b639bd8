// Words for the file.*, json.* ids (docs/files.md): one row per id, the
// English source with %1, %2 … for the arguments named beside it (word_table.h).
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"file.unreadable", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot read %1: %2", "file.unreadable"), "file,detail"},
    {"file.cannot_open", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot open %1: %2", "file.cannot_open"), "file,detail"},
    {"file.cannot_read", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot read %1: %2", "file.cannot_read"), "file,detail"},
    {"file.cannot_write", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot write %1: %2", "file.cannot_write"), "file,detail"},
    {"file.too_large", QT_TRANSLATE_NOOP3("ui::words::FileWords", "%1 is %2 MiB, more than the %3 MiB a BenchPilot file may be", "file.too_large"), "file,size,max"},
    {"file.cannot_make_folder", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot make the folder %1", "file.cannot_make_folder"), "folder"},
    {"file.json_syntax", QT_TRANSLATE_NOOP3("ui::words::FileWords", "not valid JSON: %1", "file.json_syntax"), "detail"},
    {"file.json_field", QT_TRANSLATE_NOOP3("ui::words::FileWords", "%1", "file.json_field"), "detail"},
    {"file.csv.unterminated_quote", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a quoted field is not closed", "file.csv.unterminated_quote")},
    {"file.csv.text_after_quote", QT_TRANSLATE_NOOP3("ui::words::FileWords", "text after a closing quote", "file.csv.text_after_quote")},
    {"file.csv.semicolons", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the file is separated by semicolons; BenchPilot reads commas and '.' as the decimal point", "file.csv.semicolons")},
    {"file.json.too_large", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the text is larger than %1 MiB", "file.json.too_large"), "max"},
    {"file.json.text_after_end", QT_TRANSLATE_NOOP3("ui::words::FileWords", "unexpected text after the end of the document", "file.json.text_after_end")},
    {"file.json.too_deep", QT_TRANSLATE_NOOP3("ui::words::FileWords", "nested deeper than %1 levels", "file.json.too_deep"), "max"},
    {"file.json.comment", QT_TRANSLATE_NOOP3("ui::words::FileWords", "comments are not allowed in JSON", "file.json.comment")},
    {"file.json.expected_value", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected a value, found %1", "file.json.expected_value"), "found"},
    {"file.json.leading_zero", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a number may not have leading zeros", "file.json.leading_zero")},
    {"file.json.expected_digit", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected a digit, found %1", "file.json.expected_digit"), "found"},
    {"file.json.expected_fraction_digit", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected a digit after the decimal point, found %1", "file.json.expected_fraction_digit"), "found"},
    {"file.json.expected_exponent_digit", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected a digit in the exponent, found %1", "file.json.expected_exponent_digit"), "found"},
    {"file.json.number_too_large", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the number is too large for a double", "file.json.number_too_large")},
    {"file.json.malformed_number", QT_TRANSLATE_NOOP3("ui::words::FileWords", "malformed number", "file.json.malformed_number")},
    {"file.json.bad_unicode_escape", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected four hex digits after \\u", "file.json.bad_unicode_escape")},
    {"file.json.invalid_utf8_byte", QT_TRANSLATE_NOOP3("ui::words::FileWords", "invalid UTF-8 byte %1", "file.json.invalid_utf8_byte"), "byte"},
    {"file.json.truncated_utf8", QT_TRANSLATE_NOOP3("ui::words::FileWords", "truncated UTF-8 character", "file.json.truncated_utf8")},
    {"file.json.invalid_utf8", QT_TRANSLATE_NOOP3("ui::words::FileWords", "invalid UTF-8 sequence", "file.json.invalid_utf8")},
    {"file.json.unterminated_string", QT_TRANSLATE_NOOP3("ui::words::FileWords", "unterminated string", "file.json.unterminated_string")},
    {"file.json.line_break_in_string", QT_TRANSLATE_NOOP3("ui::words::FileWords", "unterminated string (a line break inside quotes)", "file.json.line_break_in_string")},
    {"file.json.control_character", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a control character inside a string must be escaped", "file.json.control_character")},
    {"file.json.lone_high_surrogate", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a \\u escape of a high surrogate must be followed by a low surrogate", "file.json.lone_high_surrogate")},
    {"file.json.lone_low_surrogate", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a lone low surrogate in a \\u escape", "file.json.lone_low_surrogate")},
    {"file.json.unknown_escape", QT_TRANSLATE_NOOP3("ui::words::FileWords", "unknown escape \\%1", "file.json.unknown_escape"), "found"},
    {"file.json.trailing_comma", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a trailing comma before '%1' is not allowed", "file.json.trailing_comma"), "bracket"},
    {"file.json.expected_array_comma", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected ',' or ']' in an array, found %1", "file.json.expected_array_comma"), "found"},
    {"file.json.expected_member_name", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected a quoted member name, found %1", "file.json.expected_member_name"), "found"},
    {"file.json.expected_colon", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected ':' after the member name \"%1\", found %2", "file.json.expected_colon"), "member,found"},
    {"file.json.expected_object_comma", QT_TRANSLATE_NOOP3("ui::words::FileWords", "expected ',' or '}' in an object, found %1", "file.json.expected_object_comma"), "found"},
    {"file.json.duplicate_member", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the member \"%1\" appears twice", "file.json.duplicate_member"), "member"},
    {"file.json.found_end", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the end of the text", "file.json.found_end")},
    {"file.json.found_byte", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a byte %1", "file.json.found_byte"), "byte"},
    {"file.json.found_char", QT_TRANSLATE_NOOP3("ui::words::FileWords", "'%1'", "file.json.found_char"), "char"},
    {"file.json.missing", QT_TRANSLATE_NOOP3("ui::words::FileWords", "is missing", "file.json.missing")},
    {"file.json.wrong_type", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be %1, not %2", "file.json.wrong_type"), "expected,actual"},
    {"file.json.number_or_null", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be a number or null, not %1", "file.json.number_or_null"), "actual"},
    {"file.json.out_of_range", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be from %1 to %2 (got %3)", "file.json.out_of_range"), "min,max,value"},
    {"file.json.below_min", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be at least %1 (got %2)", "file.json.below_min"), "min,value"},
    {"file.json.above_max", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be at most %1 (got %2)", "file.json.above_max"), "max,value"},
    {"file.json.not_whole", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be a whole number (got %1)", "file.json.not_whole"), "value"},
    {"file.json.not_one_of", QT_TRANSLATE_NOOP3("ui::words::FileWords", "\"%1\" is not one of %2", "file.json.not_one_of"), "value,allowed"},
    {"file.json.unknown_field", QT_TRANSLATE_NOOP3("ui::words::FileWords", "unknown field", "file.json.unknown_field")},
    {"file.json.unknown_field_suggest", QT_TRANSLATE_NOOP3("ui::words::FileWords", "unknown field; did you mean \"%1\"?", "file.json.unknown_field_suggest"), "suggestion"},
    {"file.json.array_of_numbers", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be an array of %1 numbers", "file.json.array_of_numbers"), "count"},
    {"file.json.document_not_object", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the document must be an object, not %1", "file.json.document_not_object"), "actual"},
    {"file.json.schema_missing", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must name the file's kind: \"schema\": \"%1\"", "file.json.schema_missing"), "schema"},
    {"file.json.schema_wrong", QT_TRANSLATE_NOOP3("ui::words::FileWords", "is \"%1\", expected \"%2\"", "file.json.schema_wrong"), "value,schema"},
    {"file.json.version_invalid", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be a whole number from 1", "file.json.version_invalid")},
    {"file.json.version_newer", QT_TRANSLATE_NOOP3("ui::words::FileWords", "is %1: written by a newer BenchPilot (this one reads up to %2)", "file.json.version_newer"), "value,newest"},
    {"file.log.bad_sha256", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be 64 lower-case hex digits (the image's SHA-256)", "file.log.bad_sha256")},
    {"file.log.image_without_sha256", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a tile's \"image\" and \"sha256\" come together: one without the other is not a line this program wrote", "file.log.image_without_sha256")},
    {"file.log.bad_image_name", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must name a file in the run's folder (no folder, no \"..\")", "file.log.bad_image_name")},
    {"file.log.bad_fingerprint", QT_TRANSLATE_NOOP3("ui::words::FileWords", "must be 16 lower-case hex digits", "file.log.bad_fingerprint")},
    {"file.log.empty", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the log is empty: it has no header line", "file.log.empty")},
    {"file.log.no_header", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the log has no \"run\" header", "file.log.no_header")},
    {"file.log.no_header_first", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the log must begin with its \"run\" header", "file.log.no_header_first")},
    {"file.log.second_header", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a second run header: one log holds one run and its resumptions", "file.log.second_header")},
    {"file.log.op_beyond", QT_TRANSLATE_NOOP3("ui::words::FileWords", "op %1 is beyond the %2 ops of the header", "file.log.op_beyond"), "op,count"},
    {"file.log.op_restarted", QT_TRANSLATE_NOOP3("ui::words::FileWords", "op %1 starts again after it was done: the log is not trustworthy", "file.log.op_restarted"), "op"},
    {"file.log.pump_before_start", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a pump line for op %1, which has not started", "file.log.pump_before_start"), "op"},
    {"file.log.done_not_started", QT_TRANSLATE_NOOP3("ui::words::FileWords", "op %1 is done but was not under way", "file.log.done_not_started"), "op"},
    {"file.log.skip_not_interrupted", QT_TRANSLATE_NOOP3("ui::words::FileWords", "only an interrupted op can be skipped (op %1)", "file.log.skip_not_interrupted"), "op"},
    {"file.log.cannot_open", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot open the run log %1: %2", "file.log.cannot_open"), "file,detail"},
    {"file.log.cannot_write", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot write the run log %1: %2", "file.log.cannot_write"), "file,detail"},
    {"file.log.cannot_sync", QT_TRANSLATE_NOOP3("ui::words::FileWords", "cannot sync the run log %1 to disk: %2", "file.log.cannot_sync"), "file,detail"},
    {"file.log.not_open", QT_TRANSLATE_NOOP3("ui::words::FileWords", "the run log is not open", "file.log.not_open")},
};

const TermRow kTerms[] = {
    {"json.type.null", QT_TRANSLATE_NOOP3("ui::words::FileWords", "null", "json.type.null")},
    {"json.type.bool", QT_TRANSLATE_NOOP3("ui::words::FileWords", "true or false", "json.type.bool")},
    {"json.type.number", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a number", "json.type.number")},
    {"json.type.string", QT_TRANSLATE_NOOP3("ui::words::FileWords", "a string", "json.type.string")},
    {"json.type.array", QT_TRANSLATE_NOOP3("ui::words::FileWords", "an array", "json.type.array")},
    {"json.type.object", QT_TRANSLATE_NOOP3("ui::words::FileWords", "an object", "json.type.object")},
};
// clang-format on

} // namespace

QString file(const motion::msg::Message& m) { return fromRows("ui::words::FileWords", kRows, m); }
QString fileTerm(const std::string& id) { return fromTerms("ui::words::FileWords", kTerms, id); }

} // namespace ui::words::areas
