#include "widgets/scan/mosaic_viewer.h"

#include "imaging/pyramid_reader.h"
#include "widgets/scan/mosaic_canvas.h"
#include "widgets/wording/wording.h"

#include <QAction>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

namespace {
QString mm3(double v) { return QString::number(v, 'f', 3); }
} // namespace

MosaicViewer::MosaicViewer(QWidget* parent) : QWidget(parent), m_canvas(new MosaicCanvas)
{
    m_canvas->setObjectName(QStringLiteral("mosaicCanvas"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QHBoxLayout;
    auto makeAction = [this](const QList<QKeySequence>& keys, bool checkable) {
        auto* a = new QAction(this);
        a->setShortcuts(keys);
        // Only while the viewer has the focus: T, Q, F and + are plain keys elsewhere.
        a->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        a->setCheckable(checkable);
        if (checkable)
            a->setChecked(true);
        addAction(a);
        return a;
    };
    m_open = makeAction({QKeySequence(Qt::Key_O)}, false);
    m_fit = makeAction({QKeySequence(Qt::Key_F), QKeySequence(Qt::Key_Home)}, false);
    m_zoomIn = makeAction({QKeySequence(Qt::Key_Plus), QKeySequence(Qt::Key_Equal)}, false);
    m_zoomOut = makeAction({QKeySequence(Qt::Key_Minus)}, false);
    m_tiles = makeAction({QKeySequence(Qt::Key_T)}, true);
    m_quality = makeAction({QKeySequence(Qt::Key_Q)}, true);
    auto button = [bar](QAction* a, const char* name) {
        auto* b = new QToolButton;
        b->setObjectName(QLatin1String(name));
        b->setDefaultAction(a);
        b->setToolButtonStyle(Qt::ToolButtonTextOnly);
        bar->addWidget(b);
        return b;
    };
    m_openButton = button(m_open, "mosaicOpen");
    m_fitButton = button(m_fit, "mosaicFit");
    m_inButton = button(m_zoomIn, "mosaicZoomIn");
    m_outButton = button(m_zoomOut, "mosaicZoomOut");
    m_tilesButton = button(m_tiles, "mosaicTiles");
    m_qualityButton = button(m_quality, "mosaicQuality");
    m_status = new QLabel;
    m_status->setObjectName(QStringLiteral("mosaicStatus"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Its text changes as the mouse moves: it must never widen the screen.
    m_status->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_status->setMinimumWidth(0);
    bar->addStretch(1);
    layout->addLayout(bar);
    layout->addWidget(m_canvas, 1);
    layout->addWidget(m_status);

    connect(m_open, &QAction::triggered, this, &MosaicViewer::openRequested);
    connect(m_fit, &QAction::triggered, m_canvas, &MosaicCanvas::fit);
    connect(m_zoomIn, &QAction::triggered, m_canvas, [this] { m_canvas->zoomBy(1.5); });
    connect(m_zoomOut, &QAction::triggered, m_canvas, [this] { m_canvas->zoomBy(1 / 1.5); });
    connect(m_tiles, &QAction::toggled, m_canvas, &MosaicCanvas::setShowTiles);
    connect(m_quality, &QAction::toggled, m_canvas, &MosaicCanvas::setShowQuality);
    connect(m_canvas, &MosaicCanvas::viewChanged, this, &MosaicViewer::updateStatus);
    connect(m_canvas, &MosaicCanvas::cursorMoved, this, [this](const std::optional<QPointF>& m) {
        m_cursor = m;
        updateStatus();
    });
    connect(m_canvas, &MosaicCanvas::doubleClicked, this, [this](const QPointF& m) { goTo(m); });
    connect(m_canvas, &MosaicCanvas::problem, this, [this](const motion::msg::Problems& problems) {
        emit problem(tr("The mosaic %1 cannot be shown: %2").arg(QDir::toNativeSeparators(m_file), words::problems(problems).join(QLatin1Char(' '))));
    });
    retranslateUi();
}

void MosaicViewer::setStage(dev::Instrument* stage)
{
    if (m_stage)
        disconnect(m_stage, nullptr, this, nullptr);
    m_stage = stage;
    if (m_stage) {
        connect(m_stage, &dev::Instrument::statusChanged, this, &MosaicViewer::updateStage);
        connect(m_stage, &dev::Instrument::stateChanged, this, &MosaicViewer::updateStage);
    }
    updateStage();
}

bool MosaicViewer::showStitch(const imaging::StitchResult& result, const motion::scan::Camera& camera, const QString& mosaicPath)
{
    m_file = mosaicPath;
    auto reader = imaging::PyramidReader::open(mosaicPath.toStdString(), QFileInfo(mosaicPath).fileName().toStdString());
    if (!reader) {
        m_canvas->setMosaic(nullptr, {});
        emit problem(tr("The mosaic %1 cannot be shown: %2")
                         .arg(QDir::toNativeSeparators(mosaicPath), words::problems(reader.problems()).join(QLatin1Char(' '))));
        updateStatus();
        return false;
    }
    m_canvas->setMosaic(reader.take(), MosaicStageFrame(result, camera));
    updateStage();
    updateStatus();
    return true;
}

void MosaicViewer::clear()
{
    m_canvas->setMosaic(nullptr, {});
    m_cursor.reset();
    updateStatus();
}

bool MosaicViewer::hasMosaic() const { return m_canvas->hasMosaic(); }
const MosaicStageFrame& MosaicViewer::frame() const { return m_canvas->frame(); }

void MosaicViewer::updateStage()
{
    std::optional<QPointF> at;
    if (m_stage && m_stage->isReady()) {
        const int ix = m_stage->identity().axisIndex(QLatin1Char('X')), iy = m_stage->identity().axisIndex(QLatin1Char('Y'));
        const auto& axes = m_stage->status().axes;
        // Where the grating says the stage is; unknown until homed.
        if (ix >= 0 && iy >= 0 && ix < axes.size() && iy < axes.size() && axes[ix].homed && axes[iy].homed)
            at = QPointF(axes[ix].measured, axes[iy].measured);
    }
    m_canvas->setStageMm(m_canvas->hasMosaic() ? at : std::nullopt);
}

bool MosaicViewer::goTo(const QPointF& mosaicPx)
{
    if (!m_canvas->hasMosaic() || frame().isEmpty())
        return false;
    const Eigen::Vector2d target = frame().stageMmAt({mosaicPx.x(), mosaicPx.y()});
    const QString where = tr("(%1, %2) mm").arg(mm3(target.x()), mm3(target.y()));
    if (!m_stage || !m_stage->isReady()) {
        emit problem(tr("The stage is not connected: it cannot go to %1.").arg(where));
        return false;
    }
    const int ix = m_stage->identity().axisIndex(QLatin1Char('X')), iy = m_stage->identity().axisIndex(QLatin1Char('Y'));
    const auto& axes = m_stage->status().axes;
    if (ix < 0 || iy < 0 || ix >= axes.size() || iy >= axes.size())
        return false;
    if (!axes[ix].homed || !axes[iy].homed) {
        emit problem(tr("Home the stage first: going to %1 in the mosaic is a move to an absolute position.").arg(where));
        return false;
    }
    if (m_scanRunning) {
        emit problem(tr("A scan is running: the stage goes to %1 once it has finished.").arg(where));
        return false;
    }
    const auto& limits = m_stage->softLimits();
    auto outside = [&](int axis, double v) {
        return axis < limits.size() && limits[axis].max > limits[axis].min && (v < limits[axis].min || v > limits[axis].max);
    };
    if (outside(ix, target.x()) || outside(iy, target.y())) {
        // An axis the device gave no limits for is shown with its travel.
        auto range = [&](int axis) {
            const auto& d = m_stage->identity().axes[axis];
            return axis < limits.size() ? std::pair(limits[axis].min, limits[axis].max) : std::pair(d.travelMin, d.travelMax);
        };
        emit problem(tr("%1 is outside the stage's soft limits (X %2 to %3 mm, Y %4 to %5 mm): the stage stays where it is.")
                         .arg(where, mm3(range(ix).first), mm3(range(ix).second), mm3(range(iy).first), mm3(range(iy).second)));
        return false;
    }
    const double far = std::hypot(target.x() - axes[ix].commanded, target.y() - axes[iy].commanded);
    // Within one camera field the operator is nudging about what is already in view; beyond
    // it a mistaken double-click could send the objective over the slide's edge, so it asks.
    if (far > frame().fieldMm() && m_confirm
        && !m_confirm(tr("Move the stage to %1? That is %2 mm from where it is, farther than one camera field (%3 mm).")
                          .arg(where, QString::number(far, 'f', 2), QString::number(frame().fieldMm(), 'f', 2))))
        return false;
    m_stage->move({{ix, target.x()}, {iy, target.y()}}, false);
    emit notice(tr("The stage goes to %1, the point double-clicked in the mosaic.").arg(where));
    return true;
}

QString MosaicViewer::statusText() const { return m_status->text(); }

void MosaicViewer::updateStatus()
{
    if (!m_canvas->hasMosaic()) {
        m_status->clear();
        return;
    }
    QStringList parts;
    if (m_cursor && !frame().isEmpty()) {
        const Eigen::Vector2d mm = frame().stageMmAt({m_cursor->x(), m_cursor->y()});
        parts << tr("X %1  Y %2 mm under the cursor").arg(mm3(mm.x()), mm3(mm.y()));
    }
    const int level = m_canvas->level();
    parts << tr("zoom %1 %, pyramid level %2 (1:%3)").arg(m_canvas->zoom() * 100, 0, 'f', m_canvas->zoom() < 0.1 ? 1 : 0).arg(level).arg(1 << level);
    m_status->setText(parts.join(QStringLiteral(" · ")));
}

void MosaicViewer::retranslateUi()
{
    m_open->setText(tr("Open"));
    m_open->setToolTip(tr("Show the mosaic stitched earlier in the output folder: its .stitch.json report and the mosaic it names (O)"));
    m_fit->setText(tr("Fit"));
    m_fit->setToolTip(tr("Show the whole mosaic (F)"));
    m_zoomIn->setText(tr("+"));
    m_zoomIn->setToolTip(tr("Zoom in (+; or the mouse wheel, about the cursor)"));
    m_zoomOut->setText(tr("−"));
    m_zoomOut->setToolTip(tr("Zoom out (−)"));
    m_tiles->setText(tr("Tiles"));
    m_tiles->setToolTip(tr("Show each tile's outline where registration put it (T)"));
    m_quality->setText(tr("Quality"));
    m_quality->setToolTip(tr("Show each tile's correction from its stage position as an arrow, and the tiles placed by the stage hatched (Q)"));
    m_canvas->setToolTip(tr("Drag or use the arrow keys to pan; double-click to move the stage to that point"));
    updateStatus();
}

void MosaicViewer::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace ui
