#pragma once
// The API's methods that are benchpilot-cli's commands (docs/api.md): read from the
// CLI's own command table (app/cli/command.h), so a command added there is a method
// here with the same parameters and the same JSON result, and neither can drift.
//
// A call's JSON params become the command's words (`{"targets":{"X":10}, "speed":2}`
// → `move --speed=2 --json -- X=10`) and run through the CLI's own parser and code;
// what the command prints with --json is the result.
#include "app/cli/command.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <QVector>

namespace app::api {

struct CommandMethod {
    QString method;                   ///< "device.move"
    QString path;                     ///< the command's words: "move", "recipe run"
    const app::cli::Command* command = nullptr;
};

/// Every command the API offers, in the order the CLI's help lists them.
QVector<CommandMethod> commandMethods();
const CommandMethod* findMethod(const QVector<CommandMethod>& methods, const QString& method);

/// One parameter of a method: declared in the command's ApiSpec, made from one of its
/// options, or common to the methods that need it (instrument, timeout, lease).
struct MethodParam {
    QString name;                 ///< JSON name
    app::cli::ParamType type = app::cli::ParamType::Text;
    QString description;
    bool required = false;
    QString option;               ///< the CLI option it fills; empty for a positional word
    QStringList choices;
    QString defaultValue;         ///< the option's default, as the CLI shows it
    bool common = false;          ///< instrument, timeout, lease
};
QVector<MethodParam> methodParams(const CommandMethod& m);

/// Whether a method needs the control lease (Control), or only when given positional
/// words (limits, gains), as docs/api.md and rpc.discover say it.
bool needsLease(const CommandMethod& m, bool hasPositionalWords);

struct ParamProblem {
    QString field;    ///< "targets.X", "speed"
    QString message;  ///< "expected a number, got a string"
};

/// The JSON params (without `lease`) as the command's words after its path; false with
/// the first problem.
bool toWords(const CommandMethod& m, const QJsonObject& params, QStringList* words, bool* positional, ParamProblem* problem);

/// A message the command wrote for a person at a terminal ("--speed needs a positive
/// number") said the API's way ("speed needs a positive number").
QString apiWording(const CommandMethod& m, const QString& message);

} // namespace app::api
