#pragma once
// The Scan screen: plan a stitching scan on a to-scale map of the stage (draw or
// type the region), see the tiles in order, the path, the tile count and the time
// it takes; save and open plans; run, pause, resume and abort it on the stage with
// progress and time left; export the tile positions for Fiji and Micro-Manager.
#include "device/client/instrument.h"
#include "motion/plans/scan/scan_estimate.h"

#include <QWidget>

#include <functional>
#include <memory>

class QCheckBox;
class QLabel;
class QLineEdit;
class QTabWidget;
class QProgressBar;
class QPushButton;
class QTimer;

namespace dev::jobs {
class ScanLaunch;
class ScanRunner;
}

namespace dev::camera {
class Camera;
class ScanCamera;
}

namespace ui {

class CameraPanel;
class CameraSession;
class ScanPlanForm;
class ScanStageMap;
class StitchPanel;

class ScanScreen : public QWidget {
    Q_OBJECT
public:
    enum class FileAction { Open, Save, Folder };
    /// Asks for a file or folder; "" = cancelled. The composition root supplies dialogs.
    using FileChooser = std::function<QString(FileAction action, const QString& title, const QString& filter)>;
    /// Asked before a long run (dev::jobs::ScanLaunch says which) or before setting an old run
    /// aside; true = go ahead.
    using Confirm = std::function<bool(const QString& question)>;

    explicit ScanScreen(dev::Instrument* stage, QWidget* parent = nullptr);
    ~ScanScreen() override;
    void setFileChooser(FileChooser chooser) { m_chooser = std::move(chooser); }
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }
    /// Asked instead of Confirm when a long approach is the only reason to ask (app/ offers
    /// "don't ask again this session" there); unset: Confirm asks.
    void setConfirmLongMove(Confirm confirm) { m_confirmLongMove = std::move(confirm); }

    /// The plan as typed, and the plan file's text (kept between runs by the app).
    motion::scan::ScanPlan plan() const;
    QString planText() const;
    bool setPlanText(const QString& text, QString* error);
    void setPlan(const motion::scan::ScanPlan& plan);
    QString outputFolder() const;
    void setOutputFolder(const QString& folder);

    /// Gives the screen the GUI's camera: a Camera tab beside the stage map with the live
    /// view, and the run's "take an image at each tile" option.
    void setCameraSession(CameraSession* session);
    CameraPanel* cameraPanel() const { return m_cameraPanel; }
    /// The Mosaic tab (with a camera): stitches the output folder's images.
    StitchPanel* stitchPanel() const { return m_stitchPanel; }
    /// Whether a run takes an image at each tile (kept between runs by the app).
    bool takesImages() const;
    void setTakesImages(bool on);
    /// The camera a run is handed: the open one when images are asked for, else nullptr.
    dev::camera::Camera* runCamera() const;
    /// Shows the stage map (0), the camera (1) or the mosaic (2).
    void showTab(int index);

    bool openPlan(const QString& path);
    bool savePlan(const QString& path);
    /// Runs, or resumes, the scan; false (with a problem signal) when it cannot start.
    bool run();
    void pause();
    void abort();
    bool exportFiles();

    dev::jobs::ScanRunner* runner() const { return m_runner; }
    ScanStageMap* map() const { return m_map; }
    ScanPlanForm* form() const { return m_form; }
    const motion::scan::ScanLayout& layout() const { return m_layout; }
    const motion::scan::ScanEstimate& estimate() const { return m_estimate; }
    /// "42 tiles (7 × 6) …" as shown, and the plan's problems ("" when valid).
    QString summaryText() const;
    QString problemsText() const;

signals:
    void problem(const QString& message);
    void notice(const QString& message);

protected:
    void changeEvent(QEvent* event) override;

private:
    QWidget* buildRunPanel();
    QWidget* buildFileRow();  ///< New, Open, Save: held back while a scan runs
    void scheduleReplan();
    void replan();
    void updateRunUi();
    void onStatus(const dev::InstrumentStatus& status);
    void onStageIdentity();
    motion::scan::StageModel stageModel() const;
    bool confirm(const QString& question);
    void handCameraToRunner();  ///< the runner takes the tiles with runCamera(), or with none
    QString choose(FileAction action, const QString& title, const QString& filter);

    dev::Instrument* m_stage;
    dev::jobs::ScanRunner* m_runner;
    std::unique_ptr<dev::jobs::ScanLaunch> m_launch;  ///< what Run does, shared with the CLI
    ScanStageMap* m_map;
    ScanPlanForm* m_form;
    QTabWidget* m_leftTabs;
    CameraSession* m_camera = nullptr;
    CameraPanel* m_cameraPanel = nullptr;
    StitchPanel* m_stitchPanel = nullptr;
    std::unique_ptr<dev::camera::ScanCamera> m_scanCamera;  ///< the run's side of the camera, made for runCamera()
    QCheckBox* m_useCamera;
    QLabel* m_summary;
    QLabel* m_problems;
    QLabel* m_pointer;
    QWidget* m_fileRow;
    QLineEdit* m_folder;
    QPushButton *m_runButton, *m_pauseButton, *m_abortButton, *m_exportButton;
    QProgressBar* m_progress;
    QLabel* m_runState;
    QTimer* m_replanTimer;
    FileChooser m_chooser;
    Confirm m_confirm;
    Confirm m_confirmLongMove;
    motion::scan::ScanLayout m_layout;
    motion::scan::ScanEstimate m_estimate;
    bool m_valid = false;
    std::vector<char> m_taken;
};

} // namespace ui
