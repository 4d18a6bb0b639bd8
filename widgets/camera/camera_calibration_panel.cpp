#include "widgets/camera/camera_calibration_panel.h"

#include "widgets/camera/camera_session.h"
#include "widgets/wording/wording.h"

#include <QDateTime>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include <cmath>

namespace ui {

CameraCalibrationPanel::CameraCalibrationPanel(CameraSession* session, dev::Instrument* stage, QWidget* parent)
    : QWidget(parent), m_session(session), m_stage(stage)
{
    m_calibrate = new QPushButton;
    m_calibrate->setObjectName(QStringLiteral("cameraCalibrate"));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("cameraCalibrationState"));
    m_state->setWordWrap(true);
    m_state->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("cameraCalibrationProgress"));
    m_progress->setMaximumWidth(160);
    m_stop = new QPushButton;
    m_stop->setObjectName(QStringLiteral("cameraCalibrationStop"));
    m_save = new QPushButton;
    m_save->setObjectName(QStringLiteral("cameraCalibrationSave"));
    m_dismiss = new QPushButton;
    m_dismiss->setObjectName(QStringLiteral("cameraCalibrationDismiss"));
    row->addWidget(m_state, 1);
    row->addWidget(m_progress);
    row->addWidget(m_stop);
    row->addWidget(m_save);
    row->addWidget(m_dismiss);
    connect(m_calibrate, &QPushButton::clicked, this, [this] { start(); });
    connect(m_stop, &QPushButton::clicked, this, &CameraCalibrationPanel::stop);
    connect(m_dismiss, &QPushButton::clicked, this, [this] { setVisible(false); });
    connect(m_save, &QPushButton::clicked, this, [this] {
        if (!m_chooser)
            return;
        const QString path = m_chooser(tr("Save the camera profile"), tr("Camera profiles (*.camera-profile.json);;JSON (*.json)"));
        if (!path.isEmpty())
            saveTo(path);
    });
    if (m_session)
        connect(m_session, &CameraSession::stateChanged, this, &CameraCalibrationPanel::updateUi);
    retranslateUi();
    setVisible(false);
}

CameraCalibrationPanel::~CameraCalibrationPanel() = default;

bool CameraCalibrationPanel::start()
{
    if (isRunning())
        return false;
    dev::camera::Camera* camera = m_session ? m_session->camera() : nullptr;
    m_job = std::make_unique<dev::camera::CameraCalibration>(m_stage, camera);
    const dev::camera::CalibrationOptions options;
    const auto blockers = m_job->preflight(options);
    if (!blockers.empty()) {
        emit problem(tr("Camera calibration: %1").arg(ui::words::text(blockers.front())));
        m_job.reset();
        return false;
    }
    const int images = dev::camera::CameraCalibration::imagesFor(options);
    if (m_confirm
        && !m_confirm(tr("Calibrate the camera: the stage moves by steps of %1 px along X and Y around where it stands (%2 images) "
                         "and comes back. Nothing may touch the stage meanwhile. Start?")
                          .arg(options.stepPx)
                          .arg(images))) {
        m_job.reset();
        return false;
    }
    connect(m_job.get(), &dev::camera::CameraCalibration::progress, this, [this](int taken, int total) {
        m_progress->setRange(0, total);
        m_progress->setValue(taken);
        m_state->setText(tr("Calibrating the camera: image %1 of %2…").arg(taken).arg(total));
    });
    connect(m_job.get(), &dev::camera::CameraCalibration::finished, this, [this](const dev::camera::CalibrationResult& r) {
        m_result = r;
        m_when = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
        showResult();
        updateUi();
    });
    connect(m_job.get(), &dev::camera::CameraCalibration::failed, this, [this](const motion::msg::Message& why) {
        m_state->setText(tr("Camera calibration stopped: %1").arg(ui::words::text(why)));
        emit problem(m_state->text());
        updateUi();
    });
    motion::msg::Message error;
    m_result.reset();
    setVisible(true);
    if (!m_job->start(options, &error)) {
        m_state->setText(tr("Camera calibration: %1").arg(ui::words::text(error)));
        emit problem(m_state->text());
        updateUi();
        return false;
    }
    updateUi();
    return true;
}

void CameraCalibrationPanel::stop()
{
    if (m_job)
        m_job->stop();
}

void CameraCalibrationPanel::showResult()
{
    const imaging::CameraStageFit& f = m_result->fit;
    QString text = tr("Pixel %1 × %2 µm, rotation %3°, image y along stage %4; residual %5 px RMS (worst %6 px), back at the start within %7 px.")
                       .arg(f.pixelXUm, 0, 'f', 5)
                       .arg(f.pixelYUm, 0, 'f', 5)
                       .arg(f.rotationDeg, 0, 'f', 3)
                       .arg(f.imageYAlongPlusY ? tr("+Y (mirrored)") : tr("−Y"))
                       .arg(f.residualRmsPx, 0, 'f', 3)
                       .arg(f.residualMaxPx, 0, 'f', 3)
                       .arg(std::isfinite(m_result->returnPx) ? QString::number(m_result->returnPx, 'f', 2) : QStringLiteral("?"));
    text += QLatin1Char(' ') + tr("The pixel size comes from the stage's own steps: it carries the stage's scale error.");
    m_state->setText(text);
}

bool CameraCalibrationPanel::saveTo(const QString& path)
{
    if (!m_result)
        return false;
    motion::msg::Message error;
    if (!dev::files::camera::saveCameraProfileFile(path, dev::camera::profileOf(*m_result, m_when.toStdString()), &error)) {
        emit problem(ui::words::text(error));
        return false;
    }
    emit notice(tr("Camera profile saved to %1").arg(QFileInfo(path).fileName()));
    return true;
}

QString CameraCalibrationPanel::stateText() const { return m_state->text(); }

void CameraCalibrationPanel::updateUi()
{
    const bool running = isRunning();
    m_calibrate->setEnabled(!running && m_session && m_session->camera() && m_stage);
    m_progress->setVisible(running);
    m_stop->setVisible(running);
    m_save->setVisible(!running && m_result.has_value());
    m_save->setEnabled(static_cast<bool>(m_chooser));
    m_dismiss->setVisible(!running);
}

void CameraCalibrationPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void CameraCalibrationPanel::retranslateUi()
{
    m_calibrate->setText(tr("Calibrate camera…"));
    m_calibrate->setToolTip(tr("Move the stage by known steps, register the images and measure the camera's pixel size, rotation and mirror"));
    m_stop->setText(tr("Stop"));
    m_save->setText(tr("Save as profile…"));
    m_dismiss->setText(tr("Close"));
    if (m_result && !isRunning())
        showResult();
    updateUi();
}

} // namespace ui
