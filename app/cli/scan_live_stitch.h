#pragma once
// `scan run --camera …` stitches as the tiles come (docs/stitching.md, "Live during a
// scan"): the same live stitch as the Scan screen's Mosaic tab (dev::jobs::StitchJob::
// follow), its progress printed as lines (a line a registered pair; --json: an object a
// pair), and after the last tile the files the Mosaic tab writes — mosaic.ome.tif,
// TileConfiguration.registered.txt, mosaic.stitch.json and quality-map.png — with a
// summary. A stop drops it and writes nothing; the same command again continues the
// scan and reads the tiles taken before back from the folder, or, when every tile was
// taken and the mosaic is not there, stitches the folder.
#include "device/jobs/stitch_job.h"
#include "widgets/report/stitch_quality_drawing.h"

#include <QStringList>

namespace dev::jobs {
class ScanRunner;
}

namespace app::cli {

class Invocation;

class ScanLiveStitch {
public:
    /// Follows `runner` from now on; call before the scan starts.
    ScanLiveStitch(Invocation& inv, dev::jobs::ScanRunner* runner);

    /// After a scan that finished: waits for the placement and the files, prints the
    /// summary (text) or one object naming the files and the quality (--json). Ok, or the
    /// exit code after saying why the stitch failed (the scan's own files are whole).
    int finish();
    /// A scan whose every tile was taken before (run again after a kill that came between
    /// its last tile and its mosaic): stitches the folder as Stitch does, then as finish().
    int stitchFolder(const motion::scan::ScanPlan& plan, const QString& folder);

private:
    void onPair(const imaging::TilePair& pair);
    QString tileFile(int tile) const;

    Invocation& m_inv;
    dev::jobs::ScanRunner* m_runner;
    dev::jobs::StitchJob m_job;
    ui::StitchQualityDrawing m_drawing;  ///< the growing mosaic's thumbnails, then the quality map
    int m_pairs = 0;
    bool m_done = false;
    motion::msg::Problems m_problems;
};

} // namespace app::cli
