#include "widgets/tuning/step_test_panel.h"

#include "widgets/common/number_field.h"
#include "widgets/input_policy.h"
#include "widgets/wording/wording.h"
#include "widgets/tuning/response_plot.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
QString metricText(double v, int digits = 3) { return std::isfinite(v) ? QString::number(v, 'g', digits) : QStringLiteral("—"); }
} // namespace

StepTestPanel::StepTestPanel(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    row->addWidget(new QLabel(tr("Step"), this));
    // Kept as typed: "-5" is invalid with its reason (the direction is the combo beside it), not 5.
    auto* stepLabel = row->itemAt(row->count() - 1)->widget();
    m_size = new NumberField(this);
    m_size->setObjectName(QStringLiteral("stepSize"));
    m_size->setRange(0.001, 1e6);
    m_size->setDisplay('g', 6);
    m_size->setValue(20);
    static_cast<QLabel*>(stepLabel)->setBuddy(m_size);
    row->addWidget(m_size);
    m_direction = new QComboBox(this);
    m_direction->addItem(tr("positive"));
    m_direction->addItem(tr("negative"));
    row->addWidget(m_direction);
    m_run = new QPushButton(tr("Run step test"), this);
    m_run->setObjectName(QStringLiteral("runStepTest"));
    m_run->setToolTip(tr("The target steps by this much under the gains in force; the response is added to the plot"));
    row->addWidget(m_run);
    m_clear = new QPushButton(tr("Clear"), this);
    row->addWidget(m_clear);
    row->addStretch(1);
    v->addLayout(row);

    // The metrics beside the plot: one column per run (its number in the run's
    // colour, its gains in the tooltip), one row per metric.
    auto* split = new QSplitter(Qt::Horizontal, this);
    m_plot = new ResponsePlot(ResponsePlot::Mode::Overlay, split);
    m_table = new QTableWidget(9, 0, split);
    m_table->setObjectName(QStringLiteral("stepMetrics"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->setMaximumWidth(440);  // the plot keeps the room; many runs scroll
    split->addWidget(m_plot);
    split->addWidget(m_table);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    v->addWidget(split, 1);

    connect(m_run, &QPushButton::clicked, this, [this] {
        if (m_size->isValid())
            emit runRequested(step());
    });
    connect(m_size, &NumberField::entryChanged, this, [this] { refresh(); });
    connect(m_clear, &QPushButton::clicked, this, [this] {
        m_plot->clear();
        m_table->setColumnCount(0);
    });
    setUnit(QStringLiteral("mm"));
}

void StepTestPanel::setUnit(const QString& unit)
{
    const bool changed = unit != m_unit;
    m_unit = unit;
    const bool mm = unit == QLatin1String("mm");
    m_size->setUnit(mm ? tr(" µm") : QString());
    if (changed)
        m_size->setValue(mm ? 20 : 1);
    m_plot->setUnit(unit);
    const QString u = mm ? tr("µm") : tr("units");
    m_table->setVerticalHeaderLabels({tr("Rise 10–90 % [ms]"), tr("Overshoot [%]"), tr("Settling 2 % [ms]"),
                                      tr("Steady error [%1]").arg(u), tr("IAE [%1·s]").arg(u), tr("ISE [(%1)²·s]").arg(u),
                                      tr("Peak output [%1]").arg(u), mm ? tr("Inside ±5 µm from [ms]") : tr("Ended"),
                                      tr("Limit cycle at rest")});
}

double StepTestPanel::step() const
{
    const double typed = m_size->valueOr(std::nan(""));  // Run is held while the entry is invalid
    const double magnitude = m_unit == QLatin1String("mm") ? typed / 1000.0 : typed;
    return m_direction->currentIndex() == 0 ? magnitude : -magnitude;
}

void StepTestPanel::setStep(double magnitude, bool positive)
{
    m_size->setValue(m_unit == QLatin1String("mm") ? magnitude * 1000 : magnitude);
    m_direction->setCurrentIndex(positive ? 0 : 1);
}

int StepTestPanel::runs() const { return m_table->columnCount(); }

void StepTestPanel::addResult(const motion::control::Record& r, const motion::control::StepVerdict& verdict, const QString& legend)
{
    using motion::control::StepOutcome;
    const motion::control::StepMetrics& m = verdict.metrics;
    // Show where the response happens, not a second of it sitting still (zoom and drag for the rest).
    const double whole = static_cast<double>(r.size()) * r.periodS;
    const double busy = std::isfinite(m.settlingTimeS) ? 2 * m.settlingTimeS : (std::isfinite(m.riseTimeS) ? 20 * m.riseTimeS : whole);
    m_plot->addRun(r, legend, std::clamp(busy, std::min(whole, 0.02), whole));
    const bool mm = m_unit == QLatin1String("mm");
    const double k = mm ? 1000.0 : 1.0;
    const double in5 = verdict.insideTargetBandS;
    const int col = m_table->columnCount();
    m_table->insertColumn(col);
    auto* head = new QTableWidgetItem(QString::number(col + 1));
    head->setForeground(ResponsePlot::colour(col));
    head->setToolTip(legend);
    m_table->setHorizontalHeaderItem(col, head);
    // No final value, no figures read off it: the words say why. A limit cycle has a
    // centre to read them from, but it never settles.
    const QString unsettled = m.outcome == StepOutcome::Unstable ? tr("unstable") : tr("did not settle");
    const bool figures = m.outcome == StepOutcome::Settled || m.outcome == StepOutcome::LimitCycle;
    auto settled = [&](double v) { return figures ? metricText(v) : unsettled; };
    const auto& lc = verdict.limitCycle;
    const QString cycle = lc.found ? tr("±%1 %2 every %3 ms")
                                         .arg(mm ? QString::number(lc.amplitude * k, 'f', 1) : metricText(lc.amplitude), mm ? tr("µm") : tr("units"),
                                              metricText(lc.periodS * 1000))
                                   : (m.outcome == StepOutcome::Unstable ? unsettled : tr("none"));
    const QString cells[9] = {settled(m.riseTimeS * 1000),
                              settled(m.overshootPct),
                              m.outcome == StepOutcome::LimitCycle ? tr("never: limit cycle") : settled(m.settlingTimeS * 1000),
                              settled(m.steadyStateError * k),
                              metricText(m.iae * k),
                              metricText(m.ise * k * k),
                              metricText(m.peakOutput * k),
                              mm ? (std::isnan(in5) ? tr("never") : metricText(in5 * 1000)) : ui::words::term(motion::control::endReasonTerm(r.reason)),
                              cycle};
    for (int row = 0; row < 9; ++row) {
        auto* item = new QTableWidgetItem(cells[row]);
        item->setToolTip(legend);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        m_table->setItem(row, col, item);
    }
    m_table->scrollToItem(m_table->item(0, col));
}

void StepTestPanel::setBusy(bool busy)
{
    m_busy = busy;
    refresh();
}

void StepTestPanel::setReady(bool ready)
{
    m_ready = ready;
    refresh();
}

void StepTestPanel::refresh()
{
    setEnabledOr(m_run, m_size->problem());
    if (!m_ready || m_busy)
        m_run->setEnabled(false);
}

} // namespace ui
