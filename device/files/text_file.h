#pragma once
// Whole-file reads and all-or-nothing writes for the files people keep.
#include "motion/message.h"

#include <QString>

#include <string>

namespace dev::files {

/// Files larger than this are refused by readText: none of ours come close.
constexpr qint64 kMaxFileBytes = 32ll * 1024 * 1024;

/// Reads a whole file as bytes. False with a sentence naming the file otherwise.
bool readText(const QString& path, std::string* text, QString* error, qint64 maxBytes = kMaxFileBytes);
/// Writes all of `text` or nothing (QSaveFile: a crash or a full disk mid-write
/// leaves the old file as it was). False with a sentence naming the file otherwise.
bool writeAtomically(const QString& path, const std::string& text, QString* error);

/// The same with the reason as a message for the wording layer: file.cannot_open,
/// file.too_large, file.cannot_read, file.cannot_write {file, detail} (detail is
/// Qt's own text). The QString forms above remain for callers not yet on messages.
bool readText(const QString& path, std::string* text, motion::msg::Message* error, qint64 maxBytes = kMaxFileBytes);
bool writeAtomically(const QString& path, const std::string& text, motion::msg::Message* error);

} // namespace dev::files
