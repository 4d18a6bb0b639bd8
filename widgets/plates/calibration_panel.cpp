#include "widgets/plates/calibration_panel.h"

#include "widgets/plates/jog_pad.h"

#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QEvent>
#include <QDateTime>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <memory>

namespace ui {

namespace {
QString mm(double v) { return QString::number(v, 'f', 2); }
/// Moves further than this ask first (a quarter of the analyzer's XY travel).
constexpr double kFarMm = 50;
} // namespace

CalibrationPanel::CalibrationPanel(dev::Instrument* client, QWidget* parent) : QWidget(parent), m_client(client)
{
    auto* v = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Slot"), this));
    m_slot = new QComboBox(this);
    top->addWidget(m_slot);
    top->addSpacing(12);
    top->addWidget(new QLabel(tr("Fit"), this));
    m_model = new QComboBox(this);
    m_model->addItem(tr("offset, rotation, scale"), static_cast<int>(motion::plates::FitModel::Similarity));
    m_model->addItem(tr("offset, rotation, scale per axis"), static_cast<int>(motion::plates::FitModel::ScaledAxes));
    m_model->setToolTip(tr("Three points fit any affine map exactly, so a restricted model is fitted by least squares: its residual "
                           "shows a well taught off centre. One scale (the default) leaves two checks; a scale per axis leaves one."));
    top->addWidget(m_model);
    top->addStretch();
    v->addLayout(top);
    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    v->addWidget(m_status);

    auto* steps = new QLabel(tr("For each well: <b>Go near</b> (the tip rises, then moves over the well's expected place), lower it and "
                                "centre it with the arrows, then <b>Record</b>."),
                             this);
    steps->setWordWrap(true);
    v->addWidget(steps);
    m_table = new QTableWidget(3, 6, this);
    m_table->setHorizontalHeaderLabels({tr("Well"), tr("Expected (mm)"), tr("Taught (mm)"), tr("Residual (mm)"), QString(), QString()});
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setMaximumHeight(130);
    v->addWidget(m_table);

    auto* padBox = new QGroupBox(tr("Jog"), this);
    auto* pv = new QVBoxLayout(padBox);
    m_pad = new JogPad(client, padBox);
    pv->addWidget(m_pad);
    v->addWidget(padBox);

    m_result = new QLabel(this);
    m_result->setWordWrap(true);
    m_warnings = new QLabel(this);
    m_warnings->setWordWrap(true);
    m_warnings->setStyleSheet(QStringLiteral("color:#b26a00;"));
    v->addWidget(m_result);
    v->addWidget(m_warnings);
    auto* bar = new QHBoxLayout;
    m_save = new QPushButton(tr("Save calibration"), this);
    m_save->setToolTip(tr("Keep this fit for the slot: recipes on it use the taught positions from now on, between runs too"));
    m_forget = new QPushButton(tr("Forget (use nominal)"), this);
    bar->addWidget(m_save);
    bar->addWidget(m_forget);
    bar->addStretch();
    v->addLayout(bar);
    v->addStretch();

    connect(m_slot, qOverload<int>(&QComboBox::activated), this, [this] { rebuild(); });
    connect(m_model, qOverload<int>(&QComboBox::activated), this, [this] { refit(); });
    connect(m_save, &QPushButton::clicked, this, [this] { saveSlot(); });
    connect(m_forget, &QPushButton::clicked, this, [this] {
        const std::string id = slotId().toStdString();
        const auto before = m_calibrations.size();
        m_calibrations.erase(std::remove_if(m_calibrations.begin(), m_calibrations.end(), [&](const auto& c) { return c.slot == id; }),
                             m_calibrations.end());
        if (m_calibrations.size() != before)
            emit calibrationsChanged();
        rebuild();
    });
    connect(m_client, &dev::Instrument::statusChanged, this, [this] {
        const bool ready = m_client->isReady();
        for (int r = 0; r < m_table->rowCount(); ++r)
            for (int c : {4, 5})
                if (auto* w = m_table->cellWidget(r, c))
                    w->setEnabled(ready);
    });
}

void CalibrationPanel::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() != QEvent::LanguageChange)
        return;
    for (int i = 0; i < m_slot->count(); ++i)
        for (const auto& s : m_deck.plateSlots)
            if (m_slot->itemData(i).toString() == QString::fromStdString(s.id))
                m_slot->setItemText(i, QStringLiteral("%1 (%2)").arg(QString::fromStdString(s.id), ui::words::shippedName(s.name)));
}

void CalibrationPanel::setDeck(const motion::plates::Deck& deck)
{
    m_deck = deck;
    const QString keep = slotId();
    m_slot->clear();
    for (const auto& s : deck.plateSlots)
        m_slot->addItem(QStringLiteral("%1 (%2)").arg(QString::fromStdString(s.id), ui::words::shippedName(s.name)), QString::fromStdString(s.id));
    setSlot(keep);
}

void CalibrationPanel::setSlotLabware(const std::map<std::string, motion::plates::Labware>& bySlot, const std::map<std::string, double>& safeZBySlot)
{
    // Every edit of the recipe comes here: keep the points taught so far unless
    // what stands in the slot being taught has changed.
    const std::string slot = slotId().toStdString();
    const auto before = m_bySlot.find(slot);
    const auto after = bySlot.find(slot);
    const bool same = (before == m_bySlot.end()) == (after == bySlot.end())
        && (before == m_bySlot.end() || (before->second.id == after->second.id && before->second.wells.size() == after->second.wells.size()));
    m_bySlot = bySlot;
    m_safeZ = safeZBySlot;
    if (!same || m_points.empty())
        rebuild();
}

void CalibrationPanel::setCalibrations(const std::vector<motion::plates::SlotCalibration>& calibrations)
{
    m_calibrations = calibrations;
    rebuild();
}

QString CalibrationPanel::slotId() const { return m_slot->currentData().toString(); }

void CalibrationPanel::setSlot(const QString& id)
{
    const int i = m_slot->findData(id);
    m_slot->setCurrentIndex(i >= 0 ? i : 0);
    rebuild();
}

const motion::plates::Labware* CalibrationPanel::labware() const
{
    static const motion::plates::Labware fallback = *motion::plates::findBuiltinLabware("sbs-96");
    const auto it = m_bySlot.find(slotId().toStdString());
    return it != m_bySlot.end() ? &it->second : &fallback;
}

motion::plates::PlateTransform CalibrationPanel::currentTransform() const
{
    for (const auto& c : m_calibrations)
        if (c.slot == slotId().toStdString())
            return c.fit.transform;
    const motion::plates::Slot* s = m_deck.slot(slotId().toStdString());
    return s ? s->nominal() : motion::plates::PlateTransform{};
}

void CalibrationPanel::rebuild()
{
    const motion::plates::Labware* lw = labware();
    m_points = motion::plates::teachWells(*lw);
    m_recorded.assign(m_points.size(), false);
    m_fit.reset();
    const motion::plates::SlotCalibration* kept = nullptr;
    for (const auto& c : m_calibrations)
        if (c.slot == slotId().toStdString())
            kept = &c;
    m_status->setText(kept ? tr("Slot %1 is calibrated (%2, taught on %3): largest residual %4 mm. Teach again to replace it.")
                                 .arg(slotId(), QString::fromStdString(kept->labware), QString::fromStdString(kept->taughtAt))
                                 .arg(mm(kept->fit.maxResidualMm))
                           : tr("Slot %1 is not calibrated: recipes use its nominal place. Teach it on a %2.")
                                 .arg(slotId(), QString::fromStdString(lw->describe())));
    m_table->setRowCount(static_cast<int>(m_points.size()));
    const motion::plates::PlateTransform t = currentTransform();
    for (int r = 0; r < static_cast<int>(m_points.size()); ++r) {
        const auto& p = m_points[static_cast<std::size_t>(r)];
        const motion::plates::PointMm e = t.apply(p.plateMm);
        m_table->setItem(r, 0, new QTableWidgetItem(QString::fromStdString(p.well)));
        m_table->setItem(r, 1, new QTableWidgetItem(QStringLiteral("%1, %2").arg(mm(e.x), mm(e.y))));
        m_table->setItem(r, 2, new QTableWidgetItem(tr("—")));
        m_table->setItem(r, 3, new QTableWidgetItem(QString()));
        auto* go = new QPushButton(tr("Go near"));
        go->setToolTip(tr("Raise the tip to the slot's safe height, then move over where %1 is expected").arg(QString::fromStdString(p.well)));
        connect(go, &QPushButton::clicked, this, [this, r] { goTo(r); });
        auto* rec = new QPushButton(tr("Record"));
        rec->setToolTip(tr("Take the tip's position now as the centre of %1").arg(QString::fromStdString(p.well)));
        connect(rec, &QPushButton::clicked, this, [this, r] { recordPoint(r); });
        m_table->setCellWidget(r, 4, go);
        m_table->setCellWidget(r, 5, rec);
    }
    m_result->setText(tr("Record all three wells to see the fit."));
    m_warnings->clear();
    m_save->setEnabled(false);
    m_forget->setEnabled(kept != nullptr);
}

void CalibrationPanel::goTo(int index)
{
    if (index < 0 || index >= static_cast<int>(m_points.size()))
        return;
    if (!m_client->isReady()) {
        emit problem(tr("the analyzer is not connected"));
        return;
    }
    const auto& id = m_client->identity();
    const int ix = id.axisIndex(QLatin1Char('X')), iy = id.axisIndex(QLatin1Char('Y')), iz = id.axisIndex(QLatin1Char('Z'));
    const auto& st = m_client->status();
    if (ix < 0 || iy < 0 || iz < 0 || iz >= st.axes.size() || !st.axes[ix].homed || !st.axes[iy].homed || !st.axes[iz].homed) {
        emit problem(tr("home the analyzer before teaching: the wells' places are absolute"));
        return;
    }
    const motion::plates::PointMm at = currentTransform().apply(m_points[static_cast<std::size_t>(index)].plateMm);
    const auto safe = m_safeZ.find(slotId().toStdString());
    const double z = std::min(st.axes[iz].commanded, safe != m_safeZ.end() ? safe->second : 0.0);
    const double far = std::hypot(at.x - st.axes[ix].commanded, at.y - st.axes[iy].commanded);
    if (far > kFarMm && m_confirm
        && !m_confirm(tr("Move the tip over %1 of slot %2 at (%3, %4) mm, %5 mm away? It rises to Z %6 mm first.")
                          .arg(QString::fromStdString(m_points[static_cast<std::size_t>(index)].well), slotId(), mm(at.x), mm(at.y), mm(far), mm(z))))
        return;
    // XY only once Z is up: its MotionDone (also sent at once when Z is already
    // there) releases the XY move, so the tip never crosses the plate low.
    auto conn = std::make_shared<QMetaObject::Connection>();
    *conn = connect(m_client, &dev::Instrument::eventReceived, this, [this, ix, iy, iz, at, conn](const dev::DeviceEvent& e) {
        if (e.axis != iz)
            return;
        disconnect(*conn);
        if (e.kind == dev::proto::EventKind::MotionDone)
            m_client->move({{ix, at.x}, {iy, at.y}}, false);
    });
    m_client->move({{iz, z}}, false, 0, [conn](const std::optional<dev::RequestError>& err) {
        if (err)
            QObject::disconnect(*conn);
    });
}

void CalibrationPanel::recordPoint(int index)
{
    if (index < 0 || index >= static_cast<int>(m_points.size()) || !m_client->isReady())
        return;
    const auto& id = m_client->identity();
    const int ix = id.axisIndex(QLatin1Char('X')), iy = id.axisIndex(QLatin1Char('Y'));
    const auto& st = m_client->status();
    if (ix < 0 || iy < 0 || iy >= st.axes.size())
        return;
    if (!st.axes[ix].homed || !st.axes[iy].homed) {
        emit problem(tr("home the analyzer before teaching"));
        return;
    }
    auto& p = m_points[static_cast<std::size_t>(index)];
    p.machineMm = {st.axes[ix].commanded, st.axes[iy].commanded};
    m_recorded[static_cast<std::size_t>(index)] = true;
    m_table->item(index, 2)->setText(QStringLiteral("%1, %2").arg(mm(p.machineMm.x), mm(p.machineMm.y)));
    refit();
}

void CalibrationPanel::refit()
{
    m_fit.reset();
    m_warnings->clear();
    m_save->setEnabled(false);
    for (bool r : m_recorded)
        if (!r)
            return;
    if (m_points.empty())
        return;
    motion::msg::Message error;
    const motion::plates::Slot* slot = m_deck.slot(slotId().toStdString());
    const auto model = static_cast<motion::plates::FitModel>(m_model->currentData().toInt());
    m_fit = motion::plates::fitCalibration(m_points, model, &error, slot ? slot->rotationDeg : 0);
    if (!m_fit) {
        m_result->setText(tr("No fit: %1").arg(ui::words::text(error)));
        return;
    }
    for (int r = 0; r < static_cast<int>(m_points.size()); ++r) {
        const double res = m_fit->residualMm[static_cast<std::size_t>(r)];
        m_table->item(r, 3)->setText(mm(res));
        m_table->item(r, 3)->setForeground(res > motion::plates::kResidualWarnMm ? QColor(0xc6, 0x28, 0x28) : QColor(0x2e, 0x7d, 0x32));
    }
    m_result->setText(tr("Offset (%1, %2) mm, rotation %3°, scale %4 × %5; residual largest %6 mm, rms %7 mm (warning above %8 mm).")
                          .arg(mm(m_fit->transform.txMm), mm(m_fit->transform.tyMm))
                          .arg(m_fit->rotationDeg, 0, 'f', 3)
                          .arg(m_fit->scaleX, 0, 'f', 5)
                          .arg(m_fit->scaleY, 0, 'f', 5)
                          .arg(m_fit->maxResidualMm, 0, 'f', 3)
                          .arg(m_fit->rmsResidualMm, 0, 'f', 3)
                          .arg(motion::plates::kResidualWarnMm));
    QStringList w;
    for (const auto& s : m_fit->warnings)
        w << ui::words::text(s);
    m_warnings->setText(w.join(QLatin1Char('\n')));
    m_save->setEnabled(true);
}

bool CalibrationPanel::saveSlot()
{
    if (!m_fit)
        return false;
    motion::plates::SlotCalibration c;
    c.slot = slotId().toStdString();
    c.labware = labware()->id;
    c.model = m_fit->model;
    c.points = m_points;
    c.taughtAt = QDateTime::currentDateTimeUtc().toString(Qt::ISODate).toStdString();
    c.fit = *m_fit;
    bool replaced = false;
    for (auto& k : m_calibrations)
        if (k.slot == c.slot) {
            k = c;
            replaced = true;
        }
    if (!replaced)
        m_calibrations.push_back(c);
    emit calibrationsChanged();
    const auto fit = m_fit;
    const auto points = m_points;
    rebuild();
    // Keep showing what was just saved.
    m_points = points;
    m_recorded.assign(points.size(), true);
    for (int r = 0; r < static_cast<int>(points.size()); ++r) {
        m_table->item(r, 2)->setText(QStringLiteral("%1, %2").arg(mm(points[static_cast<std::size_t>(r)].machineMm.x),
                                                                  mm(points[static_cast<std::size_t>(r)].machineMm.y)));
    }
    refit();
    m_save->setEnabled(false);
    return true;
}

} // namespace ui
