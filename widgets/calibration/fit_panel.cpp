#include "widgets/calibration/fit_panel.h"

#include "widgets/calibration/wheel_guard.h"

#include "device/client/compensation_client.h"
#include "device/files/accuracy/error_curve_csv.h"
#include "widgets/wording/wording.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <qcustomplot.h>

#include <cmath>

namespace ui {

FitPanel::FitPanel(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_orderLabel = new QLabel;
    m_order = new QComboBox;
    m_order->setObjectName(QStringLiteral("fitOrder"));
    WheelGuard::guard(m_order);
    m_order->addItems({QString(), QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"), QStringLiteral("4"), QStringLiteral("5")});
    connect(m_order, qOverload<int>(&QComboBox::currentIndexChanged), this, &FitPanel::refit);
    top->addWidget(m_orderLabel);
    top->addWidget(m_order);
    top->addStretch(1);
    v->addLayout(top);
    m_table = new QTableWidget(5, 4);
    m_table->setObjectName(QStringLiteral("fitTable"));
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->setMaximumHeight(170);
    v->addWidget(m_table);
    m_curve = new QLabel;
    m_curve->setObjectName(QStringLiteral("fitCurve"));
    m_curve->setWordWrap(true);
    m_curve->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(m_curve);
    m_residualsLabel = new QLabel;
    v->addWidget(m_residualsLabel);
    m_residuals = new QCustomPlot;
    m_residuals->setMinimumHeight(110);
    m_residualGraph = m_residuals->addGraph();
    m_residualGraph->setLineStyle(QCPGraph::lsImpulse);
    m_residualGraph->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(0x60, 0x30, 0xa0), 6));
    m_residualGraph->setPen(QPen(QColor(0x60, 0x30, 0xa0), 1.5));
    m_residuals->yAxis->grid()->setZeroLinePen(QPen(QColor(0x90, 0x90, 0x90), 1));
    v->addWidget(m_residuals, 1);
    m_device = new QLabel;
    m_device->setObjectName(QStringLiteral("fitDevice"));
    m_device->setWordWrap(true);
    v->addWidget(m_device);
    auto* buttons = new QHBoxLayout;
    m_upload = new QPushButton;
    m_upload->setObjectName(QStringLiteral("fitUpload"));
    m_enable = new QPushButton;
    m_enable->setObjectName(QStringLiteral("fitEnable"));
    m_disable = new QPushButton;
    m_disable->setObjectName(QStringLiteral("fitDisable"));
    m_keep = new QCheckBox;
    m_keep->setObjectName(QStringLiteral("fitKeep"));
    buttons->addWidget(m_upload);
    buttons->addWidget(m_enable);
    buttons->addWidget(m_disable);
    buttons->addWidget(m_keep);
    buttons->addStretch(1);
    v->addLayout(buttons);
    connect(m_upload, &QPushButton::clicked, this, &FitPanel::upload);
    connect(m_enable, &QPushButton::clicked, this, [this] { setEnabledOnDevice(true); });
    connect(m_disable, &QPushButton::clicked, this, [this] { setEnabledOnDevice(false); });
    retranslateUi();
}

void FitPanel::retranslateUi()
{
    m_orderLabel->setText(tr("Order"));
    m_order->setItemText(0, tr("auto (adjusted R²)"));
    m_order->setToolTip(tr("The order chosen by adjusted R² with a significance margin, or the one you pick"));
    m_table->setHorizontalHeaderLabels({tr("order"), tr("SSE (µm²)"), tr("R²"), tr("adjusted R²")});
    m_residualsLabel->setText(tr("Residuals of the chosen fit: mean deviation − curve (µm)"));
    m_residuals->xAxis->setLabel(tr("target (mm)"));
    m_residuals->yAxis->setLabel(tr("residual (µm)"));
    m_upload->setText(tr("Upload to instrument"));
    m_enable->setText(tr("Enable"));
    m_disable->setText(tr("Disable"));
    m_keep->setText(tr("keep for power-up"));
    m_keep->setToolTip(tr("Also saves the compensation and this state in the instrument, so it powers up with it"));
    refit();
    updateButtons();
}

void FitPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void FitPanel::setInstrument(dev::Instrument* instrument)
{
    m_instrument = instrument;
    if (instrument) {
        connect(instrument, &dev::Instrument::stateChanged, this, [this] { refreshDevice(); });
        connect(instrument, &dev::Instrument::partsReplaced, this, [this] { refreshDevice(); });
    }
    refreshDevice();
}

void FitPanel::setEvaluation(const std::string& axis, const std::optional<motion::metrology::Evaluation>& evaluation)
{
    const bool axisChanged = axis != m_axis;
    m_axis = axis;
    m_evaluation = evaluation && evaluation->ok() ? evaluation : std::nullopt;
    refit();
    if (axisChanged)
        refreshDevice();
    updateButtons();
}

void FitPanel::refit()
{
    m_fit = {};
    m_residualGraph->data()->clear();
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 4; ++c)
            m_table->setItem(r, c, new QTableWidgetItem(c == 0 ? QString::number(r + 1) : QString()));
    if (!m_evaluation) {
        m_curve->setText(tr("Run an axis test to fit its error curve."));
        m_residuals->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    std::optional<int> order;
    if (m_order->currentIndex() > 0)
        order = m_order->currentIndex();
    m_fit = motion::metrology::fitPolynomials(dev::files::accuracy::fitPointsOf(*m_evaluation), order);
    for (const auto& f : m_fit.orders) {
        const int r = f.order - 1;
        if (r < 0 || r >= 5)
            continue;
        if (!f.available) {
            m_table->item(r, 1)->setText(tr("not enough points"));
            continue;
        }
        m_table->item(r, 1)->setText(QLocale().toString(f.sseUm2, 'g', 5));
        m_table->item(r, 2)->setText(QLocale().toString(f.r2, 'f', 5));
        m_table->item(r, 3)->setText(QLocale().toString(f.adjustedR2, 'f', 5));
        for (int c = 0; c < 4; ++c) {
            QFont font = m_table->item(r, c)->font();
            font.setBold(f.order == m_fit.chosenOrder);
            m_table->item(r, c)->setFont(font);
        }
    }
    const auto* chosen = m_fit.chosen();
    if (!chosen) {
        m_curve->setText(ui::words::problems(m_fit.problems).join(QLatin1Char('\n')));
    } else {
        QStringList terms;
        for (std::size_t k = 0; k < chosen->polynomial.coefficientsUm.size(); ++k)
            terms << QStringLiteral("%1·x%2").arg(QLocale().toString(chosen->polynomial.coefficientsUm[k], 'g', 6),
                                                k == 0 ? QString() : QStringLiteral("^%1").arg(k));
        m_curve->setText(tr("Order %1%2: e(x) = %3 µm (x in mm); backlash %4")
                             .arg(chosen->order)
                             .arg(m_fit.chosenByOperator ? tr(" (your choice)") : tr(" (adjusted R²)"))
                             .arg(terms.join(QStringLiteral(" + ")))
                             .arg(ui::words::number(motion::metrology::backlashUmFrom(*m_evaluation), motion::msg::Unit::Um)));
        double lo = 0, hi = 0;
        for (const auto& t : m_evaluation->targets) {
            const double res = t.meanMm * 1e3 - chosen->polynomial.errorUm(t.targetMm);
            m_residualGraph->addData(t.targetMm, res);
            lo = std::min(lo, res);
            hi = std::max(hi, res);
        }
        m_residuals->xAxis->rescale();
        const double pad = std::max(0.1, (hi - lo) * 0.15);
        m_residuals->yAxis->setRange(lo - pad, hi + pad);
        m_residuals->xAxis->scaleRange(1.1);
    }
    m_residuals->replot(QCustomPlot::rpQueuedReplot);
    updateButtons();
}

std::optional<motion::metrology::CompensationModel> FitPanel::model() const
{
    const auto* chosen = m_fit.chosen();
    if (!chosen || !m_evaluation || m_evaluation->targets.empty())
        return std::nullopt;
    return motion::metrology::polynomialModel(m_axis, chosen->polynomial, m_evaluation->targets.front().targetMm,
                                             m_evaluation->targets.back().targetMm, motion::metrology::backlashUmFrom(*m_evaluation));
}

int FitPanel::axisIndex() const
{
    if (!m_instrument || m_axis.size() != 1)
        return -1;
    return m_instrument->identity().axisIndex(QChar::fromLatin1(m_axis[0]));
}

void FitPanel::refreshDevice()
{
    m_deviceHasModel.reset();
    m_deviceEnabled.reset();
    m_deviceApplied.reset();
    m_deviceSaved.reset();
    updateButtons();
    if (!m_instrument || !m_instrument->can(dev::Capability::Compensation) || !m_instrument->compensation() || axisIndex() < 0)
        return;
    const QPointer<FitPanel> self(this);
    m_instrument->compensation()->read(axisIndex(), [self](const std::optional<dev::RequestError>& e, const dev::AxisCompensation& c) {
        if (!self || e)
            return;
        self->m_deviceHasModel = c.model.has_value();
        self->m_deviceEnabled = c.enabled;
        self->m_deviceApplied = c.applied;
        self->m_deviceSaved = c.saved;
        self->updateButtons();
    });
}

QString FitPanel::deviceText() const { return m_device->text(); }

void FitPanel::updateButtons()
{
    const bool can = m_instrument && m_instrument->can(dev::Capability::Compensation) && m_instrument->compensation() && axisIndex() >= 0;
    const QString why = !m_instrument ? tr("No instrument.")
        : !m_instrument->can(dev::Capability::Compensation) ? ui::words::text(m_instrument->whyNot(dev::Capability::Compensation))
        : axisIndex() < 0 ? tr("The instrument has no axis %1.").arg(QString::fromStdString(m_axis))
                          : QString();
    QString state;
    if (!can)
        state = why;
    else if (!m_deviceHasModel)
        state = tr("Reading the instrument's compensation of %1…").arg(QString::fromStdString(m_axis));
    else if (!*m_deviceHasModel)
        state = tr("The instrument holds no compensation for %1.").arg(QString::fromStdString(m_axis));
    else
        state = tr("The instrument holds a compensation for %1: %2%3%4.")
                    .arg(QString::fromStdString(m_axis))
                    .arg(*m_deviceEnabled ? tr("enabled") : tr("disabled"))
                    .arg(*m_deviceEnabled && !m_deviceApplied.value_or(false) ? tr(", applied once the axis is homed") : QString())
                    .arg(m_deviceSaved.value_or(false) ? tr(", kept for power-up") : QString());
    m_device->setText(state);
    const bool haveModel = model().has_value();
    m_upload->setEnabled(can && haveModel && !m_busy);
    m_upload->setToolTip(!can ? why : !haveModel ? tr("Run an axis test first: the fit of its mean deviations is what is uploaded")
                                                 : tr("Sends the chosen fit to the instrument (installed disabled)"));
    m_enable->setEnabled(can && m_deviceHasModel.value_or(false) && !m_deviceEnabled.value_or(true) && !m_busy);
    m_enable->setToolTip(!can ? why : !m_deviceHasModel.value_or(false) ? tr("Upload a compensation first")
                                                                        : tr("The instrument compensates every target from now on"));
    m_disable->setEnabled(can && m_deviceEnabled.value_or(false) && !m_busy);
    m_disable->setToolTip(!can ? why : tr("The instrument stops compensating (it keeps the compensation)"));
    m_keep->setEnabled(can);
}

void FitPanel::upload()
{
    const auto m = model();
    if (!m || !m_instrument || !m_instrument->compensation())
        return;
    m_busy = true;
    updateButtons();
    const QPointer<FitPanel> self(this);
    m_instrument->compensation()->upload(axisIndex(), *m, [self](const std::optional<dev::RequestError>& e) {
        if (!self)
            return;
        self->m_busy = false;
        if (e)
            emit self->problem(tr("The instrument refused the compensation: %1").arg(ui::words::text(e->message)));
        else
            emit self->notice(tr("Compensation of %1 uploaded (disabled until you enable it).").arg(QString::fromStdString(self->m_axis)));
        self->refreshDevice();
        emit self->deviceChanged();
    });
}

void FitPanel::setEnabledOnDevice(bool on)
{
    if (!m_instrument || !m_instrument->compensation())
        return;
    m_busy = true;
    updateButtons();
    const QPointer<FitPanel> self(this);
    m_instrument->compensation()->setEnabled(axisIndex(), on, m_keep->isChecked(), [self](const std::optional<dev::RequestError>& e) {
        if (!self)
            return;
        self->m_busy = false;
        if (e)
            emit self->problem(tr("The instrument refused: %1").arg(ui::words::text(e->message)));
        self->refreshDevice();
        emit self->deviceChanged();
    });
}

} // namespace ui
