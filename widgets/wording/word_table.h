#pragma once
// The tables an area words its ids with: one row per id, the English source in
// QT_TRANSLATE_NOOP3 (so lupdate finds it, with the id as its disambiguation) and
// the names of the arguments that fill %1, %2, … in order. A row whose sentence
// depends on a count names that argument as its numerus: the source then has
// "%Ln" for it (tr's plural forms: "1 well", "2 wells"; Chinese has one form).
//
//   const ui::words::Row kRows[] = {
//       {"pattern.not_above", QT_TRANSLATE_NOOP3("ui::words::PatternWords", "must be above %1 (got %2)", "pattern.not_above"),
//        "min,value"},
//   };
//
// The id doubles as the disambiguation so every row is its own entry in the .ts
// (two ids with the same English may read differently in Chinese), and a
// translator sees which message a sentence belongs to.
#include "motion/message.h"

#include <QString>

#include <cstddef>
#include <string>

namespace ui::words {

/// What QT_TRANSLATE_NOOP3 expands to: {source, disambiguation}.
struct Source {
    const char* text;
    const char* disambiguation;
};

struct Row {
    const char* id;
    Source source;
    const char* args = "";      ///< comma-separated argument names for %1, %2, …
    const char* numerus = "";   ///< the argument whose value is tr's n ("%Ln"); "" for none
};

struct TermRow {
    const char* id;
    Source source;
};

/// The sentence for `m` from `rows` in the current language, or a null QString
/// when no row has its id. `context` is the rows' translation context.
QString fromRows(const char* context, const Row* rows, std::size_t count, const motion::msg::Message& m);
template <std::size_t N>
QString fromRows(const char* context, const Row (&rows)[N], const motion::msg::Message& m)
{
    return fromRows(context, rows, N, m);
}

/// A term from `rows`, or a null QString.
QString fromTerms(const char* context, const TermRow* rows, std::size_t count, const std::string& id);
template <std::size_t N>
QString fromTerms(const char* context, const TermRow (&rows)[N], const std::string& id)
{
    return fromTerms(context, rows, N, id);
}

/// Every id a table words, for the tests that check an area's ids are all worded.
template <std::size_t N>
bool hasRow(const Row (&rows)[N], const std::string& id)
{
    for (const Row& r : rows)
        if (id == r.id)
            return true;
    return false;
}

/// Replaces %1 … %99 in `pattern` with `values` in one pass (an argument that
/// itself holds "%1", such as a file name, is left as it is).
QString fill(const QString& pattern, const QStringList& values);

} // namespace ui::words
