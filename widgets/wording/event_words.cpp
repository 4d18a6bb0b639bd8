// Words for the device.why.* ids: why a device raised an event, from the reason it sent
// (docs/protocol.md, "Event reasons"; device/backends/benchpilot/event_reason.cpp).
// One row per id, the English source with %1, %2 … for the arguments named beside it.
#include "widgets/wording/areas.h"
#include "widgets/wording/word_table.h"

#include <QCoreApplication>

namespace ui::words::areas {
namespace {

// clang-format off
const Row kRows[] = {
    {"device.why.already_there", QT_TRANSLATE_NOOP3("ui::words::EventWords", "already there: nothing moved", "device.why.already_there")},
    {"device.why.outside_window", QT_TRANSLATE_NOOP3("ui::words::EventWords", "arrived outside the in-position window", "device.why.outside_window")},
    {"device.why.home_switch", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 hit its home switch", "device.why.home_switch"), "axis"},
    {"device.why.limit_switch", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 hit its limit switch", "device.why.limit_switch"), "axis"},
    {"device.why.home_switch_not_found", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 found no home switch over its whole travel", "device.why.home_switch_not_found"), "axis"},
    {"device.why.all_halted", QT_TRANSLATE_NOOP3("ui::words::EventWords", "all motion halted", "device.why.all_halted")},
    {"device.why.jog_not_refreshed", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 heard no jog for %2, so it stopped", "device.why.jog_not_refreshed"), "axis,seconds"},
    {"device.why.stop_request", QT_TRANSLATE_NOOP3("ui::words::EventWords", "stopped on request", "device.why.stop_request")},
    {"device.why.with_coupled_axis", QT_TRANSLATE_NOOP3("ui::words::EventWords", "stopped with the axis it moves with", "device.why.with_coupled_axis")},
    {"device.why.homing_other_failed", QT_TRANSLATE_NOOP3("ui::words::EventWords", "homing cancelled: another axis found no home switch", "device.why.homing_other_failed")},
    {"device.why.homing_earlier_failed", QT_TRANSLATE_NOOP3("ui::words::EventWords", "homing cancelled: an axis homed before this one did not reach home", "device.why.homing_earlier_failed")},
    {"device.why.homing_stopped", QT_TRANSLATE_NOOP3("ui::words::EventWords", "homing stopped before this axis' turn", "device.why.homing_stopped")},
    {"device.why.waited_move_stopped", QT_TRANSLATE_NOOP3("ui::words::EventWords", "cancelled: the move it waited for was stopped", "device.why.waited_move_stopped")},
    {"device.why.waited_move_hit_switch", QT_TRANSLATE_NOOP3("ui::words::EventWords", "cancelled: a switch stopped the move it waited for", "device.why.waited_move_hit_switch")},
    {"device.why.off_command", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1's encoder is %2 off the command", "device.why.off_command"), "axis,error"},
    {"device.why.cleared", QT_TRANSLATE_NOOP3("ui::words::EventWords", "E-stop and faults cleared", "device.why.cleared")},
    {"device.why.test_settled", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 settled after %3", "device.why.test_settled"), "axis,test,seconds"},
    {"device.why.test_completed", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 completed in %3", "device.why.test_completed"), "axis,test,seconds"},
    {"device.why.test_excursion", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 stopped after %5: its excursion reached %4, past the limit of %3; the axis stopped at %6", "device.why.test_excursion"), "axis,test,limit,value,seconds,at"},
    {"device.why.test_following_error", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 stopped after %5: its following error reached %4, past the limit of %3; the axis stopped at %6", "device.why.test_following_error"), "axis,test,limit,value,seconds,at"},
    {"device.why.test_duration", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 stopped at its time limit of %3; the axis stopped at %4", "device.why.test_duration"), "axis,test,limit,at"},
    {"device.why.test_on_request", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 stopped on request", "device.why.test_on_request"), "axis,test"},
    {"device.why.test_estop", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 ended by the E-stop", "device.why.test_estop"), "axis,test"},
    {"device.why.test_host_silent", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 ended: nothing came from BenchPilot for %3, so the axis stopped", "device.why.test_host_silent"), "axis,test,seconds"},
    {"device.why.test_fault", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 %2 ended by a fault", "device.why.test_fault"), "axis,test"},
    {"device.why.gains_set", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 gains per control period: kp %2, ki %3, kd %4", "device.why.gains_set"), "axis,kp,ki,kd"},
    {"device.why.gains_set_kept", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 gains per control period: kp %2, ki %3, kd %4, kept as its power-up gains", "device.why.gains_set_kept"), "axis,kp,ki,kd"},
    {"device.why.gains_fell_back", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1 is back on the gains in force before the set that tripped the test: kp %2, ki %3, kd %4", "device.why.gains_fell_back"), "axis,kp,ki,kd"},
    {"device.why.comp_installed_table", QT_TRANSLATE_N_NOOP3("ui::words::EventWords", "axis %1: a compensation table of %Ln points installed, not yet enabled", "device.why.comp_installed_table"), "axis", "points"},
    {"device.why.comp_installed_table_per_direction", QT_TRANSLATE_N_NOOP3("ui::words::EventWords", "axis %1: a compensation table of %Ln points per direction installed, not yet enabled", "device.why.comp_installed_table_per_direction"), "axis", "points"},
    {"device.why.comp_installed_polynomial", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1: a compensation polynomial of order %2 over %3 to %4 installed, not yet enabled", "device.why.comp_installed_polynomial"), "axis,order,from,to"},
    {"device.why.comp_enabled", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1: compensation enabled", "device.why.comp_enabled"), "axis"},
    {"device.why.comp_enabled_kept", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1: compensation enabled and kept for power-up", "device.why.comp_enabled_kept"), "axis"},
    {"device.why.comp_disabled", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1: compensation disabled", "device.why.comp_disabled"), "axis"},
    {"device.why.comp_disabled_kept", QT_TRANSLATE_NOOP3("ui::words::EventWords", "axis %1: compensation disabled, and kept so for power-up", "device.why.comp_disabled_kept"), "axis"},
    {"device.why.path_underrun", QT_TRANSLATE_NOOP3("ui::words::EventWords", "the queue ran dry: at rest until more segments arrive", "device.why.path_underrun")},
    {"device.why.path_held", QT_TRANSLATE_NOOP3("ui::words::EventWords", "held: %1", "device.why.path_held"), "reason"},
    {"device.why.path_ended", QT_TRANSLATE_NOOP3("ui::words::EventWords", "ended: %1", "device.why.path_ended"), "reason"},
};
// clang-format on

} // namespace

QString deviceEvent(const motion::msg::Message& m) { return fromRows("ui::words::EventWords", kRows, m); }

} // namespace ui::words::areas
