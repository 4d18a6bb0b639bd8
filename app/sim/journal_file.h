#pragma once
// benchpilot-sim --journal FILE: the firmware's own record of what it executed
// (dev::sim::Firmware::journal()) written out when the simulator stops, one JSON object a
// line, so a test that drives the simulator through real programs on a pty can judge a
// run by what the device did — as the in-process hostile tests do — not by what the
// host printed.
//   {"t": 12.5, "type": 16, "seq": 301, "payload": "<hex>", "commanded": [x, y, z, p]}
// t: machine seconds; type: dev::proto::MsgType; commanded: each axis's commanded position
// (axis units) before the request ran. The last line, {"end": true, "commanded": […]},
// is where the machine was left. Read back by tests/integration/hostile_pty_support.h.
#include "device/sim/firmware.h"

#include <QString>

namespace app::sim {

/// false with `error` set when the file cannot be written.
bool writeJournal(const dev::sim::Firmware& firmware, const QString& path, QString* error);

} // namespace app::sim
