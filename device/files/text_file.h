#pragma once
// Whole-file reads and all-or-nothing writes for the files people keep.
#include <QString>

#include <string>

namespace files {

/// Files larger than this are refused by readText: none of ours come close.
constexpr qint64 kMaxFileBytes = 32ll * 1024 * 1024;

/// Reads a whole file as bytes. False with a sentence naming the file otherwise.
bool readText(const QString& path, std::string* text, QString* error, qint64 maxBytes = kMaxFileBytes);
/// Writes all of `text` or nothing (QSaveFile: a crash or a full disk mid-write
/// leaves the old file as it was). False with a sentence naming the file otherwise.
bool writeAtomically(const QString& path, const std::string& text, QString* error);

} // namespace files
