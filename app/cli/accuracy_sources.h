#pragma once
// The reading sources `accuracy run --source` names, made for the CLI:
//   readback           the instrument's encoder or grating
//   gauge:PATH         a gauge on serial port PATH (--gauge-baud, --gauge-timeout);
//                      gauge:sim is the in-process simulator's own gauge (with --sim)
//   manual             a person types each reading on stdin (prompts on stderr)
//   interferometer     readings imported afterwards (accuracy import)
//   camera[:SOURCE]    the camera reads a glass line scale (camera_cli.h; camera is camera:sim)
#include "command.h"
#include "device/jobs/accuracy/reading_source.h"

#include <QObject>

#include <memory>

namespace app::cli {

class CliSession;
// Unqualified in the declarator: lupdate takes a qualified return type for the
// function's class and would file the strings below under that context.
using ReadingSource = dev::jobs::ReadingSource;

/// The source, owned by `owner`; nullptr after reporting why (exit Usage).
ReadingSource* makeSource(Invocation& inv, CliSession& session, const QString& spec, int axis, QObject* owner);

/// Answers a ManualSource's prompts from stdin, one reading a line ("10.0012", "10.0012 mm",
/// "12.3 um"; for two axes "x y"); "q" aborts. Ends when the source is gone.
void attachStdinPrompter(Invocation& inv, dev::jobs::ReadingSource* source, const std::function<void()>& onQuit);

} // namespace app::cli
