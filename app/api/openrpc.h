#pragma once
// rpc.discover: the OpenRPC document of the API, generated from the CLI's command table
// (command_methods.h) and the API's own methods, so what a client is told and what the
// server does cannot drift. docs/api.md's method list is made from the same table
// (tests/integration/api_docs_test.cpp checks it).
#include "command_methods.h"

#include <QJsonObject>
#include <QVector>

namespace app::api {

QJsonObject openRpcDocument(const QVector<CommandMethod>& methods);
/// The JSON Schema of a parameter type.
QJsonObject paramSchema(app::cli::ParamType type, const QStringList& choices);
/// "control", "read", "compute", "safety": what a method needs (docs/api.md, "Control").
QString accessName(app::cli::Access access, bool readsWithoutArguments);

} // namespace app::api
