#pragma once
// A finished stitch read back from its output folder, so the mosaic viewer (and the
// quality map) can show a scan stitched earlier: the report NAME.stitch.json (tiles,
// pairs), the mosaic it names (its OME-XML gives the stage position of its top-left
// pixel, which puts the report's mosaic pixels back on the stage) and the first tile's
// size. docs/stitching.md, "The mosaic viewer".
#include "imaging/stitch.h"
#include "motion/plans/scan/scan_plan.h"

#include <QString>

#include <optional>

namespace ui {

struct StitchedFolder {
    imaging::StitchResult result;
    QString mosaicPath;
};

/// Reads `folder`'s mosaic.stitch.json (or the one *.stitch.json there); nothing, with
/// why (naming the file, and the line and column of a syntax error), when it cannot.
std::optional<StitchedFolder> loadStitchedFolder(const QString& folder, const motion::scan::Camera& camera, QString* error);

} // namespace ui
