// The list of benchpilot-cli's commands, in the order the help shows them.
// A new area adds its registration function here (see README.md).
#include "command.h"

namespace app::cli {

const std::vector<Command>& commands()
{
    static const std::vector<Command> list = [] {
        std::vector<Command> l;
        addDeviceCommands(l);
        addMotionCommands(l);
        addTuningCommands(l);
        addPatternCommands(l);
        addRecipeCommands(l);
        addScanCommands(l);
        addStitchCommands(l);
        addCameraCommands(l);
        addAccuracyCommands(l);
        addGridMapCommands(l);
        addCompensationCommands(l);
        addCompletionCommand(l);  // last: it lists the others
        return l;
    }();
    return list;
}

} // namespace app::cli
