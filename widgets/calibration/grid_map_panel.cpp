#include "widgets/calibration/grid_map_panel.h"

#include "device/camera/dot_reading_source.h"
#include "device/client/compensation_2d_client.h"
#include "device/files/accuracy/accuracy_run_folders.h"
#include "motion/metrology/grid/compensation_table_2d.h"
#include "widgets/camera/camera_session.h"
#include "widgets/common/number_field.h"
#include "widgets/report/grid_map_painter.h"
#include "widgets/wording/wording.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace ui {

void GridMapView::setMaps(const std::optional<motion::metrology::GridMapResult>& before, const std::optional<motion::metrology::GridMapResult>& after)
{
    m_before = before;
    m_after = after;
    update();
}

void GridMapView::setVectors(ui::report::GridVectors kind)
{
    m_kind = kind;
    update();
}

void GridMapView::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    std::vector<const motion::metrology::GridMapResult*> maps;
    if (m_before)
        maps.push_back(&*m_before);
    if (m_after)
        maps.push_back(&*m_after);
    if (maps.empty()) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
                   tr("No map yet: put the grid plate under the camera, a dot near the image centre, and run a grid map."));
        return;
    }
    const bool reversal = m_kind == ui::report::GridVectors::Reversal;
    const double mag = ui::report::gridMagnification(maps, m_kind);
    const double colourMax = std::max(ui::report::gridLongestErrorUm(maps, m_kind), 1e-3);
    const int n = static_cast<int>(maps.size());
    const double w = width() / static_cast<double>(n);
    const int line = fontMetrics().height() + 2;
    for (int k = 0; k < n; ++k) {
        const bool isAfter = n == 1 ? m_after.has_value() : k == 1;
        p.setPen(palette().color(QPalette::WindowText));
        p.drawText(QRectF(k * w + 6, 4, w - 12, line), Qt::AlignLeft | Qt::AlignVCenter,
                   isAfter ? tr("After: 2D table on") : tr("Before: compensation off"));
        const auto& f = maps[static_cast<std::size_t>(k)]->figures;
        QString sub = tr("RMS %1 µm").arg(QLocale().toString(f.rmsErrorUm, 'f', 2));
        if (reversal)
            sub = f.meanReversalXUm && f.meanReversalYUm ? tr("mean reversal X %1 µm, Y %2 µm")
                                                               .arg(QLocale().toString(*f.meanReversalXUm, 'f', 2), QLocale().toString(*f.meanReversalYUm, 'f', 2))
                                                         : tr("read one way: no reversal");
        else if (f.maxReversalUm)
            sub = tr("RMS %1 µm, mean of both directions").arg(QLocale().toString(f.rmsErrorUm, 'f', 2));
        p.drawText(QRectF(k * w + 6, 4 + line, w - 12, line), Qt::AlignLeft | Qt::AlignVCenter, sub);
        ui::report::drawGridMap(p, QRectF(k * w + 6, 2 * line + 8, w - 12, height() - 4 * line - 20), *maps[static_cast<std::size_t>(k)], mag,
                                colourMax, m_kind);
    }
    const double barW = std::min(220.0, width() * 0.45);
    ui::report::drawGridColourBar(p, QRectF(6, height() - 2 * line - 2, barW + 110, line * 0.5), colourMax);
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRectF(6, height() - line - 2, width() - 12, line), Qt::AlignLeft | Qt::AlignVCenter,
               reversal ? tr("reversals (forward − reverse) magnified %1×; colour: their length").arg(QLocale().toString(mag * 1000, 'f', 0))
                        : tr("arrows magnified %1×; colour: the error's length").arg(QLocale().toString(mag * 1000, 'f', 0)));
}

GridMapPanel::GridMapPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("calibrationGridMap"));
    auto* h = new QHBoxLayout(this);
    auto* left = new QVBoxLayout;
    auto* form = new QFormLayout;
    // Typed values are kept as typed and refused with their reason, never clamped.
    auto field = [this](const char* name, double min, double max, double value, bool integer) {
        auto* f = new NumberField;
        f->setObjectName(QLatin1String(name));
        f->setRange(min, max);
        f->setInteger(integer);
        f->setDisplay('f', 0);
        f->setValue(value);
        connect(f, &NumberField::entryChanged, this, [this] { updateUi(); });
        return f;
    };
    m_pitch = field("gridMapPitch", 1, 100, 5, false);
    m_columns = field("gridMapColumns", 3, 101, 19, true);
    m_rows = field("gridMapRows", 3, 101, 19, true);
    auto* nodes = new QHBoxLayout;
    nodes->addWidget(m_columns);
    nodes->addWidget(new QLabel(QStringLiteral("×")));
    nodes->addWidget(m_rows);
    m_pitchLabel = new QLabel;
    m_nodesLabel = new QLabel;
    form->addRow(m_pitchLabel, m_pitch);
    form->addRow(m_nodesLabel, nodes);
    m_bidirectional = new QCheckBox;
    m_bidirectional->setObjectName(QStringLiteral("gridMapBidirectional"));
    form->addRow(m_bidirectional);
    m_show = new QComboBox;
    m_show->setObjectName(QStringLiteral("gridMapShow"));
    m_show->addItem(QString(), static_cast<int>(ui::report::GridVectors::Error));
    m_show->addItem(QString(), static_cast<int>(ui::report::GridVectors::Reversal));
    m_showLabel = new QLabel;
    form->addRow(m_showLabel, m_show);
    left->addLayout(form);
    m_run = new QPushButton;
    m_run->setObjectName(QStringLiteral("gridMapRun"));
    m_abort = new QPushButton;
    m_abort->setObjectName(QStringLiteral("gridMapAbort"));
    m_compensate = new QPushButton;
    m_compensate->setObjectName(QStringLiteral("gridMapCompensate"));
    m_disable = new QPushButton;
    m_disable->setObjectName(QStringLiteral("gridMapDisable"));
    for (QPushButton* b : {m_run, m_abort, m_compensate, m_disable})
        left->addWidget(b);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("gridMapState"));
    m_state->setWordWrap(true);
    left->addWidget(m_state);
    m_cannotKnow = new QLabel;
    m_cannotKnow->setWordWrap(true);
    m_cannotKnow->setStyleSheet(QStringLiteral("color: #555"));
    m_figures = new QTableWidget(11, 2);
    m_figures->setObjectName(QStringLiteral("gridMapFigures"));
    m_figures->verticalHeader()->setVisible(true);
    m_figures->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_figures->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_figures->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    left->addWidget(m_figures, 1);
    left->addWidget(m_cannotKnow);
    auto* leftBox = new QWidget;
    leftBox->setLayout(left);
    leftBox->setMaximumWidth(300);
    h->addWidget(leftBox);
    m_view = new GridMapView;
    m_view->setObjectName(QStringLiteral("gridMapView"));
    h->addWidget(m_view, 1);
    connect(m_run, &QPushButton::clicked, this, [this] { run(); });
    connect(m_abort, &QPushButton::clicked, this, &GridMapPanel::abort);
    connect(m_compensate, &QPushButton::clicked, this, [this] { compensate(); });
    connect(m_disable, &QPushButton::clicked, this, &GridMapPanel::disableTable);
    connect(m_show, qOverload<int>(&QComboBox::currentIndexChanged), this,
            [this] { m_view->setVectors(static_cast<ui::report::GridVectors>(m_show->currentData().toInt())); });
    retranslateUi();
    updateUi();
}

GridMapPanel::~GridMapPanel()
{
    if (m_runner)
        m_runner->abort();
}

void GridMapPanel::setInstrument(dev::Instrument* instrument)
{
    if (m_runner && m_runner->isActive())
        return;  // the run keeps its instrument
    m_instrument = instrument;
    updateUi();
}

void GridMapPanel::setBidirectional(bool both) { m_bidirectional->setChecked(both); }

void GridMapPanel::showVectors(ui::report::GridVectors kind)
{
    const int k = m_show->findData(static_cast<int>(kind));
    if (k >= 0)
        m_show->setCurrentIndex(k);
}

void GridMapPanel::setGrid(double pitchMm, int columns, int rows)
{
    m_pitch->setValue(pitchMm);
    m_columns->setValue(columns);
    m_rows->setValue(rows);
}

bool GridMapPanel::run()
{
    auto refuse = [this](const QString& why) {
        emit problem(why);
        updateUi();
        return false;
    };
    if (m_runner && m_runner->isActive())
        return refuse(tr("A grid map is running."));
    dev::camera::Camera* camera = m_camera ? m_camera->camera() : nullptr;
    if (!camera)
        return refuse(tr("Open a camera first, on the Scan or Jog screen's Camera tab, with the grid plate under it (on the simulator: the "
                         "sim camera, with benchpilot started with --specimen grid-plate)."));
    if (!m_instrument)
        return refuse(tr("No instrument to map."));
    motion::metrology::GridMapTest test;
    test.name = "grid-map";
    for (NumberField* f : {m_pitch, m_columns, m_rows})
        if (!f->isValid())
            return refuse(tr("%1: %2").arg(f->fieldName(), f->problem()));
    test.pitchXMm = test.pitchYMm = *m_pitch->value();
    test.columns = static_cast<int>(*m_columns->value());
    test.rows = static_cast<int>(*m_rows->value());
    test.bidirectional = m_bidirectional->isChecked();
    if (m_tableEnabled && m_beforeTest) {
        // The after map compares node by node only on the before map's grid, from its start.
        const motion::metrology::GridMapTest& b = *m_beforeTest;
        if (b.pitchXMm != test.pitchXMm || b.columns != test.columns || b.rows != test.rows)
            return refuse(tr("The after map reads the before map's grid: pitch %1 mm, %2 × %3 nodes. Set those, or disable the 2D table "
                             "to start a new before map.")
                              .arg(QLocale().toString(b.pitchXMm))
                              .arg(b.columns)
                              .arg(b.rows));
        test.startXMm = b.startXMm;
        test.startYMm = b.startYMm;
    }
    const QString base = QDir(m_folder ? m_folder() : QDir::homePath()).filePath(m_tableEnabled ? QStringLiteral("grid-map-after")
                                                                                              : QStringLiteral("grid-map"));
    const QString folder = dev::files::accuracy::nextRunFolder(base);
    dev::camera::DotReadingOptions options;
    options.failedImagesFolder = folder;
    options.platePitchMm = test.platePitchMm;
    if (m_runner)
        m_runner.reset();
    m_source = std::make_unique<dev::camera::DotReadingSource>(camera, options);
    m_runner = std::make_unique<dev::jobs::GridMapRunner>(m_instrument);
    motion::msg::Problems problems;
    if (!m_runner->prepare(test, m_source.get(), folder, false, &problems))
        return refuse(ui::words::problems(problems).join(QLatin1Char('\n')));
    connect(m_runner.get(), &dev::jobs::GridMapRunner::progress, this, [this] { updateUi(); });
    connect(m_runner.get(), &dev::jobs::GridMapRunner::problem, this, [this](const motion::msg::Message& m) { emit problem(ui::words::text(m)); });
    connect(m_runner.get(), &dev::jobs::GridMapRunner::nodeFailed, this,
            [this](int, const motion::msg::Message& m) { emit notice(ui::words::text(m)); });
    connect(m_runner.get(), &dev::jobs::GridMapRunner::finished, this, &GridMapPanel::onFinished);
    // The session's camera is open already (camera() gives only an open one).
    m_source->open([](const motion::msg::Message&) {});
    motion::msg::Message why;
    if (!m_runner->start(&why))
        return refuse(ui::words::text(why));
    m_runningTest = test;
    updateUi();
    return true;
}

void GridMapPanel::abort()
{
    if (m_runner)
        m_runner->abort();
    updateUi();
}

void GridMapPanel::onFinished()
{
    const auto map = m_runner ? m_runner->result() : std::nullopt;
    if (map) {
        if (m_tableEnabled) {
            m_after = map;
        } else {
            m_before = map;
            m_after.reset();
            m_beforeTest = m_runningTest;
            m_beforeTest->startXMm = m_runner->startXMm();
            m_beforeTest->startYMm = m_runner->startYMm();
        }
        emit notice(tr("Grid map written to %1.").arg(QDir::toNativeSeparators(m_runner->folder())));
    }
    showMaps();
    updateUi();
}

bool GridMapPanel::compensate()
{
    auto refuse = [this](const QString& why) {
        emit problem(why);
        updateUi();
        return false;
    };
    if (!m_before)
        return refuse(tr("Run a grid map first: the 2D table is fitted to it."));
    dev::Compensation2dClient* c = m_instrument ? m_instrument->compensation2d() : nullptr;
    if (!c || !c->available())
        return refuse(ui::words::text(motion::msg::make("compensation2d.not_supported")));
    const auto table = motion::metrology::compensationFromMap(*m_before);
    if (!table || motion::msg::hasErrors(motion::metrology::validate(*table)))
        return refuse(tr("This map's grid cannot be made into a 2D table the device keeps (2 to 41 nodes a side)."));
    m_busyCompensating = true;
    updateUi();
    const QPointer<GridMapPanel> self(this);
    const QPointer<dev::Instrument> instrument = m_instrument;
    c->upload(*table, [self, instrument](const std::optional<dev::RequestError>& e) {
        if (!self)
            return;
        if (e || !instrument || !instrument->compensation2d()) {
            self->m_busyCompensating = false;
            emit self->problem(e ? ui::words::text(e->message) : tr("The instrument went away."));
            self->updateUi();
            return;
        }
        instrument->compensation2d()->setEnabled(true, false, [self](const std::optional<dev::RequestError>& e2, const dev::Compensation2dState& s) {
            if (!self)
                return;
            self->m_busyCompensating = false;
            if (e2 || !s.enabled) {
                emit self->problem(e2 ? ui::words::text(e2->message) : tr("The device did not enable the 2D table."));
            } else {
                self->m_tableEnabled = true;
                emit self->notice(tr("2D table of %1 × %2 nodes uploaded and enabled: run the grid map again to see the after.")
                                      .arg(s.columns)
                                      .arg(s.rows));
            }
            self->updateUi();
        });
    });
    return true;
}

void GridMapPanel::disableTable()
{
    dev::Compensation2dClient* c = m_instrument ? m_instrument->compensation2d() : nullptr;
    if (!c || !c->available())
        return;
    const QPointer<GridMapPanel> self(this);
    c->setEnabled(false, false, [self](const std::optional<dev::RequestError>& e, const dev::Compensation2dState&) {
        if (!self)
            return;
        if (e) {
            emit self->problem(ui::words::text(e->message));
            return;
        }
        self->m_tableEnabled = false;
        self->updateUi();
    });
}

QString GridMapPanel::stateText() const
{
    if (m_busyCompensating)
        return tr("Uploading the 2D table…");
    if (!m_runner)
        return m_tableEnabled ? tr("2D table enabled.") : tr("Ready.");
    const int visited = m_runner->nodesRead() + m_runner->nodesFailed();
    switch (m_runner->state()) {
    case dev::jobs::GridMapRunner::State::Running:
        if (m_runner->test().bidirectional)
            return tr("Mapping both ways: %1 of %2 readings").arg(visited).arg(m_runner->totalNodes());
        return tr("Mapping: %1 of %2 nodes").arg(visited).arg(m_runner->totalNodes());
    case dev::jobs::GridMapRunner::State::Stopped:
        if (m_runner->test().bidirectional)
            return tr("Stopped after %1 of %2 readings (each node both ways).").arg(visited).arg(m_runner->totalNodes());
        return tr("Stopped after %1 of %2 nodes.").arg(visited).arg(m_runner->totalNodes());
    case dev::jobs::GridMapRunner::State::Finished:
        if (m_runner->nodesFailed() > 0)
            return m_runner->test().bidirectional
                       ? tr("Finished: %1 of %2 readings (each node both ways) failed.").arg(m_runner->nodesFailed()).arg(m_runner->totalNodes())
                       : tr("Finished: %1 of %2 nodes without a reading.").arg(m_runner->nodesFailed()).arg(m_runner->totalNodes());
        return m_runner->test().bidirectional ? tr("Finished: %1 nodes, each read both ways.").arg(m_runner->totalNodes() / 2)
                                              : tr("Finished: %1 nodes.").arg(m_runner->totalNodes());
    case dev::jobs::GridMapRunner::State::Idle: break;
    }
    return tr("Ready.");
}

void GridMapPanel::showMaps()
{
    m_view->setMaps(m_before, m_after);
    const bool both = m_after.has_value();
    m_figures->setColumnCount(both ? 2 : 1);
    m_figures->setHorizontalHeaderLabels(both ? QStringList{tr("before"), tr("after")} : QStringList{tr("value")});
    auto fill = [&](int column, const motion::metrology::GridMapFigures& f) {
        const double values[] = {f.scaleXPpm, f.scaleYPpm, f.squarenessUrad, f.straightnessXUm, f.straightnessYUm, f.rmsErrorUm, f.maxErrorUm, f.rmsResidualUm};
        for (int r = 0; r < 8; ++r)
            m_figures->setItem(r, column, new QTableWidgetItem(QLocale().toString(values[r], 'f', r == 2 ? 1 : 2)));
        const std::optional<double> reversal[] = {f.maxReversalUm, f.meanReversalXUm, f.meanReversalYUm};
        for (int r = 0; r < 3; ++r)
            m_figures->setItem(8 + r, column, new QTableWidgetItem(reversal[r] ? QLocale().toString(*reversal[r], 'f', 2) : QStringLiteral("—")));
    };
    if (m_before)
        fill(0, m_before->figures);
    if (m_after)
        fill(1, m_after->figures);
    // The reversal's rows and the choice of arrows only when a map shown was read both ways.
    const bool reversal = (m_before && m_before->figures.maxReversalUm) || (m_after && m_after->figures.maxReversalUm);
    for (int r = 8; r < 11; ++r)
        m_figures->setRowHidden(r, !reversal);
    if (!reversal)
        showVectors(ui::report::GridVectors::Error);
    m_show->setEnabled(reversal);
}

void GridMapPanel::updateUi()
{
    const bool running = m_runner && m_runner->isActive();
    m_run->setText(m_tableEnabled ? tr("Run the grid map again (after)") : tr("Run grid map"));
    m_run->setEnabled(!running && !m_busyCompensating && m_pitch->isValid() && m_columns->isValid() && m_rows->isValid());
    m_abort->setEnabled(running);
    m_compensate->setEnabled(!running && !m_busyCompensating && m_before && !m_tableEnabled);
    m_disable->setEnabled(!running && !m_busyCompensating && m_tableEnabled);
    for (QWidget* w : {static_cast<QWidget*>(m_pitch), static_cast<QWidget*>(m_columns), static_cast<QWidget*>(m_rows),
                       static_cast<QWidget*>(m_bidirectional)})
        w->setEnabled(!running);
    m_state->setText(stateText());
}

void GridMapPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void GridMapPanel::retranslateUi()
{
    m_pitchLabel->setText(tr("Pitch"));
    m_nodesLabel->setText(tr("Nodes"));
    m_pitch->setUnit(tr(" mm"));
    m_pitch->setFieldName(tr("Pitch"));
    m_pitch->setHelp(tr("Distance between the nodes visited, a whole multiple of the plate's dot pitch"));
    m_columns->setFieldName(tr("Columns"));
    m_rows->setFieldName(tr("Rows"));
    m_bidirectional->setText(tr("Both directions"));
    m_bidirectional->setToolTip(tr("Read every node twice: approached from −X −Y, then again in reverse order from +X +Y. The map is the "
                                   "mean of the two; each node gets its reversal (forward − reverse), whose mean along X and Y is the "
                                   "lost motion a 2D table cannot correct."));
    m_showLabel->setText(tr("Arrows"));
    m_show->setItemText(0, tr("errors"));
    m_show->setItemText(1, tr("reversals"));
    m_show->setToolTip(tr("What the map's arrows and colours show: each node's error, or its reversal (forward − reverse)"));
    m_abort->setText(tr("Abort"));
    m_compensate->setText(tr("Fit, upload and enable the 2D table"));
    m_disable->setText(tr("Disable the 2D table"));
    m_cannotKnow->setText(tr("What the camera cannot know by itself: a pixel size calibrated by moving this same stage carries the "
                             "stage's scale error into the image. The scales are those of the plate's certified pitch."));
    m_figures->setVerticalHeaderLabels({tr("scale X (ppm)"), tr("scale Y (ppm)"), tr("squareness (µrad)"), tr("straightness X (µm)"),
                                        tr("straightness Y (µm)"), tr("error RMS (µm)"), tr("error max (µm)"), tr("residual RMS (µm)"),
                                        tr("reversal max (µm)"), tr("mean reversal X (µm)"), tr("mean reversal Y (µm)")});
    showMaps();
    updateUi();
}

} // namespace ui
