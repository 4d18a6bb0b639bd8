#pragma once
// The Scan screen's Mosaic tab: stitches the scan's output folder (its run log and the
// images the camera took) into the mosaic with the plan's camera, off the GUI thread, and
// shows the mosaic in the mosaic viewer beside the quality map with its summary; a click
// on a tile of the map shows its pairs. Writes the quality map as quality-map.png beside
// the mosaic.
#include "device/jobs/stitch_job.h"

#include <QWidget>

#include <functional>

class QLabel;
class QProgressBar;
class QPushButton;

namespace ui {

class MosaicViewer;
class StitchQualityMap;

class StitchPanel : public QWidget {
    Q_OBJECT
public:
    /// What to stitch when asked: the scan's output folder and the plan whose camera took it.
    using Source = std::function<dev::jobs::StitchRequest()>;
    explicit StitchPanel(Source source, QWidget* parent = nullptr);

    /// Starts stitching (the Stitch button); false, with a problem signal, when it cannot.
    bool stitch();
    bool isRunning() const { return m_job->isRunning(); }
    StitchQualityMap* map() const { return m_map; }
    MosaicViewer* viewer() const { return m_viewer; }
    QString summaryText() const;
    QString tileText() const;
    /// Greyed while a scan runs: its folder is still being written.
    void setScanRunning(bool running);
    /// Stitches `runner`'s camera scans live: the map grows as tiles come, and the files
    /// and the summary follow the last tile (dev::jobs::StitchJob::follow).
    void followScan(dev::jobs::ScanRunner* runner);
    const dev::jobs::StitchJob* job() const { return m_job; }

signals:
    void problem(const QString& message);
    void notice(const QString& message);
    void finished();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void updateUi();
    void onFinished();
    void onLiveStarted();
    void showTile(int index);
    QStringList summaryLines() const;

    Source m_source;
    dev::jobs::StitchJob* m_job;
    QPushButton* m_stitch;
    QProgressBar* m_busy;
    QLabel* m_state;
    QLabel* m_summary;
    QLabel* m_tile;
    StitchQualityMap* m_map;
    MosaicViewer* m_viewer;
    motion::scan::Camera m_camera;  ///< the camera of the stitch running or shown
    bool m_scanRunning = false;
    QString m_folder;
};

} // namespace ui
