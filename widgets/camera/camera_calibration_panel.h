#pragma once
// Camera–stage calibration on a camera panel: "Calibrate camera…" asks before the stage
// moves, then shows the images taken (Stop stops the stage and the job), the result with
// its residual, and "Save as profile…" writes the camera profile file
// (docs/camera.md, "Calibrating the camera against the stage"). The job is
// dev::camera::CameraCalibration; this widget only words and shows it.
#include "device/camera/camera_calibration.h"

#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

class QLabel;
class QProgressBar;
class QPushButton;

namespace ui {

class CameraSession;

class CameraCalibrationPanel : public QWidget {
    Q_OBJECT
public:
    using Confirm = std::function<bool(const QString& question)>;
    using FileChooser = std::function<QString(const QString& title, const QString& filter)>;

    CameraCalibrationPanel(CameraSession* session, dev::Instrument* stage, QWidget* parent = nullptr);
    ~CameraCalibrationPanel() override;
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }
    void setFileChooser(FileChooser chooser)
    {
        m_chooser = std::move(chooser);
        updateUi();
    }

    /// The button the camera panel places in its bar.
    QPushButton* calibrateButton() const { return m_calibrate; }
    /// Asks (when a confirm is set), then starts; false when declined or refused (problem()).
    bool start();
    void stop();
    bool isRunning() const { return m_job && m_job->isRunning(); }
    const std::optional<dev::camera::CalibrationResult>& result() const { return m_result; }
    /// Writes the last result as a camera profile; false with problem() when it cannot.
    bool saveTo(const QString& path);
    QString stateText() const;

signals:
    void problem(const QString& message);
    void notice(const QString& message);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void updateUi();
    void showResult();

    CameraSession* m_session;
    dev::Instrument* m_stage;
    std::unique_ptr<dev::camera::CameraCalibration> m_job;
    std::optional<dev::camera::CalibrationResult> m_result;
    QString m_when;
    Confirm m_confirm;
    FileChooser m_chooser;
    QPushButton* m_calibrate;
    QLabel* m_state;
    QProgressBar* m_progress;
    QPushButton* m_stop;
    QPushButton* m_save;
    QPushButton* m_dismiss;
};

} // namespace ui
