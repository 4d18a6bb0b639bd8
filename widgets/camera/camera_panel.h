#pragma once
// A camera on a screen: choose the source (sim, uvc:NAME, command:CMD, folder:DIR),
// open and close it, set the exposure, watch the live view with the stage's position,
// and snap one image to a file. The Scan screen and the stage's Jog screen each have
// one; both show the one camera of the CameraSession.
#include "device/camera/camera.h"

#include <QWidget>

#include <cstdint>
#include <functional>

class QComboBox;
class QLabel;
class QPushButton;

namespace dev {
class Instrument;
}

namespace ui {

class CameraCalibrationPanel;
class CameraSession;
class LiveView;
class NumberField;

class CameraPanel : public QWidget {
    Q_OBJECT
public:
    /// Asks for the file a snap goes to; "" = cancelled. The composition root supplies a dialog.
    using FileChooser = std::function<QString(const QString& title, const QString& filter)>;

    /// `stage` (may be null) gives the position shown and recorded with a snap.
    CameraPanel(CameraSession* session, dev::Instrument* stage, QWidget* parent = nullptr);
    void setFileChooser(FileChooser chooser);
    /// Asks before the stage moves for a camera calibration; unset: it moves without asking.
    void setConfirm(std::function<bool(const QString& question)> confirm);
    CameraCalibrationPanel* calibration() const { return m_calibration; }

    LiveView* liveView() const { return m_view; }
    QComboBox* sourceField() const { return m_source; }
    QString sourceText() const;
    /// Opens what the source field says (the Open button).
    void openTyped();
    /// Takes one image with the camera and writes it to `path` (a TIFF as a scan's tiles are,
    /// dev::camera::writeTileTiff: its own bit depth, the stage position in its description),
    /// off the GUI thread; false when no camera is open or one snap is pending.
    bool snapTo(const QString& path);
    bool snapPending() const { return m_snapId != 0; }

    static constexpr int kSnapKey = Qt::Key_F9;

signals:
    void problem(const QString& message);
    void notice(const QString& message);
    void snapWritten(const QString& path);

protected:
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    /// Asks the session for every source, the USB cameras found now among them.
    void refreshSources();
    void fillSources(const QStringList& sources);
    void updateUi();
    void retranslateUi();
    void onCaptured(std::uint64_t id, const dev::camera::Frame& frame);

    CameraSession* m_session;
    dev::Instrument* m_stage;
    LiveView* m_view;
    QComboBox* m_source;
    QPushButton* m_open;
    QPushButton* m_refresh;
    NumberField* m_exposure;
    QPushButton* m_snap;
    QLabel* m_sourceLabel;
    QLabel* m_exposureLabel;
    QLabel* m_state;
    CameraCalibrationPanel* m_calibration;
    FileChooser m_chooser;
    std::uint64_t m_snapId = 0;
    QMetaObject::Connection m_snapCaptured, m_snapFailed;
    QString m_snapPath;
    dev::camera::CaptureRequest m_snapRequest;
    bool m_snapPositionKnown = false;
};

} // namespace ui
