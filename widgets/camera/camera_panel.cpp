#include "widgets/camera/camera_panel.h"

#include "widgets/camera/camera_calibration_panel.h"
#include "widgets/common/button_key.h"

#include "device/client/instrument.h"
#include "device/camera/tile_tiff.h"
#include "widgets/camera/camera_session.h"
#include "widgets/camera/live_view.h"
#include "widgets/common/number_field.h"
#include "widgets/retranslator.h"
#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QSaveFile>
#include <QThreadPool>
#include <QVBoxLayout>

#include <atomic>

namespace ui {

namespace {

std::uint64_t nextSnapId()
{
    // Snaps ask with ids far from a scan's, so a scan's capture answer is never taken for one.
    static std::atomic<std::uint64_t> next{std::uint64_t(1) << 62};
    return ++next;
}

/// What a snap is, for the TIFF's description: where the stage stood and which camera.
dev::camera::TileMetadata snapMetadata(const QString& path, const dev::camera::CaptureRequest& request, bool positionKnown,
                                       const QString& source)
{
    dev::camera::TileMetadata meta;
    meta.tile = -1;
    meta.label = QFileInfo(path).fileName().toStdString();
    if (positionKnown)
        meta.measuredMm = {request.xMm, request.yMm};
    meta.source = source.toStdString();
    return meta;
}

std::optional<QPointF> positionOf(const dev::Instrument* stage)
{
    if (!stage || !stage->isReady())
        return std::nullopt;
    const auto& axes = stage->status().axes;
    if (axes.size() < 2 || !axes[0].homed || !axes[1].homed)
        return std::nullopt;
    return QPointF(axes[0].measured, axes[1].measured);
}

/// The source choice: its list is filled just before it drops down, so the system is asked
/// for its USB cameras only when someone looks at them.
class SourceCombo : public QComboBox {
public:
    explicit SourceCombo(std::function<void()> beforePopup) : m_beforePopup(std::move(beforePopup)) {}
    void showPopup() override
    {
        if (m_beforePopup)
            m_beforePopup();
        QComboBox::showPopup();
    }

private:
    std::function<void()> m_beforePopup;
};

} // namespace

CameraPanel::CameraPanel(CameraSession* session, dev::Instrument* stage, QWidget* parent)
    : QWidget(parent), m_session(session), m_stage(stage)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* sourceRow = new QHBoxLayout;
    m_sourceLabel = new QLabel;
    m_source = new SourceCombo([this] { refreshSources(); });
    m_source->setObjectName(QStringLiteral("cameraSource"));
    m_source->setEditable(true);
    m_source->setInsertPolicy(QComboBox::NoInsert);
    m_source->setProperty(Retranslator::kItemsAreNames, true);  // sources are names, never reworded
    m_source->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    m_source->setMinimumContentsLength(16);
    m_refresh = new QPushButton(QStringLiteral("↻"));
    m_refresh->setObjectName(QStringLiteral("cameraRefresh"));
    m_refresh->setMaximumWidth(32);
    m_open = new QPushButton;
    m_open->setObjectName(QStringLiteral("cameraOpen"));
    sourceRow->addWidget(m_sourceLabel);
    sourceRow->addWidget(m_source, 1);
    sourceRow->addWidget(m_refresh);
    sourceRow->addWidget(m_open);
    v->addLayout(sourceRow);

    m_exposureLabel = new QLabel;
    m_exposure = new NumberField;
    m_exposure->setObjectName(QStringLiteral("cameraExposure"));
    m_exposure->setRange(0.01, 60000);
    m_exposure->setDisplay('g', 6);
    m_exposure->setMaximumWidth(110);
    m_exposure->setValue(m_session->exposureMs());
    m_snap = new QPushButton;
    m_snap->setObjectName(QStringLiteral("cameraSnap"));
    setButtonKey(m_snap, QKeySequence(kSnapKey));
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("cameraState"));
    sourceRow->addWidget(m_state);

    m_view = new LiveView;
    m_view->setAutoContrast(m_session->autoContrast());
    // Exposure and Snap share the view's row: every row less is picture on a small display.
    m_view->bar()->insertWidget(0, m_exposureLabel);
    m_view->bar()->insertWidget(1, m_exposure);
    m_view->bar()->insertWidget(2, m_snap);
    m_view->bar()->insertSpacing(3, 12);
    m_calibration = new CameraCalibrationPanel(m_session, m_stage);
    m_view->bar()->insertWidget(4, m_calibration->calibrateButton());
    v->addWidget(m_view, 1);
    v->addWidget(m_calibration);
    connect(m_calibration, &CameraCalibrationPanel::problem, this, &CameraPanel::problem);
    connect(m_calibration, &CameraCalibrationPanel::notice, this, &CameraPanel::notice);

    connect(m_refresh, &QPushButton::clicked, this, &CameraPanel::refreshSources);
    connect(m_open, &QPushButton::clicked, this, [this] {
        if (m_session->isOpen() || m_session->isOpening())
            m_session->close();
        else
            openTyped();
    });
    connect(m_source->lineEdit(), &QLineEdit::returnPressed, this, [this] {
        if (!m_session->isOpen())
            openTyped();
    });
    // Sent once the entry is finished and valid; a refused one says why on the field and sends nothing.
    connect(m_exposure, &QLineEdit::editingFinished, this, [this] {
        m_exposure->finishEntry();
        if (const auto ms = m_exposure->value())
            m_session->setExposureMs(*ms);
    });
    connect(m_snap, &QPushButton::clicked, this, [this] {
        if (!m_session->isOpen())
            return;
        const QString path = m_chooser ? m_chooser(tr("Save the snapped image"), tr("TIFF images (*.tif *.tiff)")) : QString();
        if (path.isEmpty())
            return;
        const bool tiff = path.endsWith(QLatin1String(".tif"), Qt::CaseInsensitive) || path.endsWith(QLatin1String(".tiff"), Qt::CaseInsensitive);
        snapTo(tiff ? path : path + QStringLiteral(".tif"));
    });
    connect(m_session, &CameraSession::stateChanged, this, &CameraPanel::updateUi);
    connect(m_session, &CameraSession::liveFrame, m_view, &LiveView::showFrame);
    connect(m_session, &CameraSession::autoContrastChanged, m_view, &LiveView::setAutoContrast);
    connect(m_view, &LiveView::autoContrastChanged, m_session, &CameraSession::setAutoContrast);
    if (m_stage)
        connect(m_stage, &dev::Instrument::statusChanged, this, [this] { m_view->setStagePosition(positionOf(m_stage)); });
    // Only what is known without asking the system for its cameras: the list of USB
    // cameras is asked for when the operator opens the choice (or presses Refresh).
    fillSources(m_session->knownSources());
    retranslateUi();
}

QString CameraPanel::sourceText() const { return m_source->currentText().trimmed(); }

void CameraPanel::openTyped()
{
    m_session->open(sourceText());
}

void CameraPanel::refreshSources() { fillSources(m_session->availableSources()); }

void CameraPanel::fillSources(const QStringList& sources)
{
    const QString typed = m_session->source().isEmpty() ? sourceText() : m_session->source();
    m_source->clear();
    m_source->addItems(sources);
    m_source->setCurrentText(typed.isEmpty() ? QStringLiteral("sim") : typed);
}

void CameraPanel::showEvent(QShowEvent* event)
{
    // The other screen's panel may have opened another source since this one was shown.
    if (!m_session->source().isEmpty() && m_session->source() != sourceText())
        m_source->setCurrentText(m_session->source());
    if (m_exposure->isValid() && m_exposure->value() != m_session->exposureMs() && !m_exposure->hasFocus())
        m_exposure->setValue(m_session->exposureMs());
    m_view->setStagePosition(positionOf(m_stage));
    QWidget::showEvent(event);
}

bool CameraPanel::snapTo(const QString& path)
{
    dev::camera::Camera* cam = m_session->camera();
    if (!cam) {
        emit problem(tr("Open a camera before snapping."));
        return false;
    }
    if (m_snapId != 0) {
        emit problem(tr("A snap is still being taken."));
        return false;
    }
    m_snapId = nextSnapId();
    m_snapPath = path;
    // Connected anew for each snap: the camera may have been swapped since the last one.
    disconnect(m_snapCaptured);
    disconnect(m_snapFailed);
    m_snapCaptured = connect(cam, &dev::camera::Camera::captured, this, &CameraPanel::onCaptured);
    m_snapFailed = connect(cam, &dev::camera::Camera::failed, this, [this](std::uint64_t id, const motion::msg::Problem& p) {
        if (id == 0 || id != m_snapId)
            return;
        m_snapId = 0;
        emit problem(tr("The snap was not taken: %1").arg(ui::words::problem(p)));
        updateUi();
    });
    dev::camera::CaptureRequest request;
    request.id = m_snapId;
    request.tile = -1;
    if (const auto at = positionOf(m_stage)) {
        request.xMm = at->x();
        request.yMm = at->y();
    }
    request.fileHint = path.toStdString();
    m_snapRequest = request;
    m_snapPositionKnown = positionOf(m_stage).has_value();
    updateUi();
    cam->capture(request);
    return true;
}

void CameraPanel::onCaptured(std::uint64_t id, const dev::camera::Frame& frame)
{
    if (id == 0 || id != m_snapId)
        return;
    m_snapId = 0;
    updateUi();
    m_view->showFrame(frame);  // the snap is what the person looks at next
    const QString path = m_snapPath;
    const dev::camera::TileMetadata meta = snapMetadata(path, m_snapRequest, m_snapPositionKnown, m_session->source());
    QPointer<CameraPanel> self(this);
    // Encoding a large image takes long enough to stutter the screen: a worker writes it.
    QThreadPool::globalInstance()->start([self, frame, path, meta] {
        motion::msg::Message problem;
        const bool ok = dev::camera::writeTileTiff(path.toStdString(), frame, meta, nullptr, &problem);
        QMetaObject::invokeMethod(qApp, [self, path, ok, problem] {
            const QString error = ok ? QString() : ui::words::text(problem);
            if (!self)
                return;
            if (!error.isEmpty()) {
                emit self->problem(tr("The snap was not saved to %1: %2").arg(path, error));
                return;
            }
            emit self->notice(tr("Snapped %1.").arg(QFileInfo(path).fileName()));
            emit self->snapWritten(path);
        }, Qt::QueuedConnection);
    });
}

void CameraPanel::updateUi()
{
    const bool open = m_session->isOpen();
    const bool opening = m_session->isOpening();
    dev::camera::Camera* cam = m_session->camera();
    if (!open)
        m_snapId = 0;  // a closed camera answers no snap
    m_open->setText(open || opening ? tr("Close") : tr("Open"));
    m_open->setEnabled(!m_session->inUse());
    m_source->setEnabled(!open && !opening);
    m_exposure->setEnabled(cam && cam->capabilities().exposure);
    m_snap->setEnabled(open && m_snapId == 0);
    if (open)
        m_state->setText(tr("Open: %1").arg(m_session->source()));
    else if (opening)
        m_state->setText(tr("Opening %1…").arg(m_session->source()));
    else
        m_state->setText(tr("Closed"));
    if (!open)
        m_view->clear(opening ? tr("Opening the camera…") : tr("No picture: open a camera."));
    else if (cam && !cam->capabilities().live && !m_view->hasPicture())
        m_view->clear(tr("This source gives no live picture: each snap is shown here."));
    else if (!m_session->liveProblem().isEmpty())
        m_view->clear(tr("No picture: %1").arg(m_session->liveProblem()));
    else if (!m_view->hasPicture())
        m_view->clear(tr("Waiting for the first picture…"));
}

void CameraPanel::retranslateUi()
{
    m_sourceLabel->setText(tr("Camera"));
    m_source->setToolTip(tr("sim: the simulated camera; sim:PATH: the one benchpilot-sim serves at PATH (--camera-socket); "
                            "uvc:NAME: a USB camera; command:CMD: runs CMD for each image "
                            "({file} is where it writes); folder:DIR: takes the next new file in DIR"));
    m_refresh->setToolTip(tr("List the cameras again"));
    m_exposureLabel->setText(tr("Exposure"));
    m_exposure->setUnit(tr(" ms"));
    m_exposure->setFieldName(tr("Exposure"));
    m_exposure->setHelp(tr("Exposure time, where the camera lets it be set"));
    m_snap->setText(tr("Snap"));
    m_snap->setToolTip(tr("Take one image and save it as a TIFF with the stage position in it (16-bit grey stays 16-bit) (%1)")
                           .arg(QKeySequence(kSnapKey).toString(QKeySequence::NativeText)));
    updateUi();
}

void CameraPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void CameraPanel::setFileChooser(FileChooser chooser)
{
    m_chooser = chooser;
    m_calibration->setFileChooser(std::move(chooser));
}

void CameraPanel::setConfirm(std::function<bool(const QString& question)> confirm) { m_calibration->setConfirm(std::move(confirm)); }

} // namespace ui
