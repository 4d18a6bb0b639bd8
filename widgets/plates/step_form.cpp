#include "widgets/plates/step_form.h"
#include "widgets/plates/step_texts.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

namespace ui {

using plates::StepType;

namespace {
bool takes(StepType t, const char* field)
{
    const QString f = QLatin1String(field);
    switch (t) {
    case StepType::Aspirate: return f == "plate" || f == "wells" || f == "station" || f == "volume" || f == "speed";
    case StepType::Dispense:
        return f == "plate" || f == "wells" || f == "station" || f == "volume" || f == "speed" || f == "source" || f == "offset";
    case StepType::Mix: return f == "plate" || f == "wells" || f == "volume" || f == "cycles" || f == "speed";
    case StepType::Wash: return f == "station" || f == "volume" || f == "cycles" || f == "speed";
    case StepType::AirGap: return f == "volume" || f == "speed";
    case StepType::Wait: return f == "seconds";
    case StepType::TouchOff: return f == "plate" || f == "wells" || f == "offset";
    }
    return false;
}

QDoubleSpinBox* spin(QWidget* parent, double max, const QString& suffix, int decimals = 2)
{
    auto* s = new QDoubleSpinBox(parent);
    s->setRange(0, max);
    s->setDecimals(decimals);
    s->setSuffix(suffix);
    s->setKeyboardTracking(false);
    s->setMaximumWidth(160);
    return s;
}
} // namespace

StepForm::StepForm(QWidget* parent) : QWidget(parent)
{
    build();
    setStep({}, -1);
}

void StepForm::build()
{
    m_form = new QFormLayout(this);
    m_form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    m_type = new QComboBox(this);
    for (int i = 0; i < plates::kStepTypeCount; ++i)
        m_type->addItem(stepTypeTitle(static_cast<StepType>(i)), i);  // the id is the item data
    m_plate = new QComboBox(this);
    m_wells = new QLineEdit(this);
    m_wells->setPlaceholderText(tr("A1:H1, row B, column 3, all, or a list: A1, C4"));
    m_wells->setToolTip(tr("Wells: a well (A1), a range (A1:H1), \"row B\", \"column 3\", \"all\", or several separated by commas.\n"
                           "Select wells on the plate map and press \"Use selection\" to fill this in."));
    m_station = new QComboBox(this);
    m_volume = spin(this, 100000, tr(" µL"));
    m_volume->setToolTip(tr("Per well (aspirate, dispense), per stroke (mix, wash), or the air gap"));
    m_speedRow = new QWidget(this);
    auto* sr = new QHBoxLayout(m_speedRow);
    sr->setContentsMargins(0, 0, 0, 0);
    m_speedSet = new QCheckBox(tr("set"), m_speedRow);
    m_speed = spin(m_speedRow, 500, tr(" µL/s"), 1);
    m_speed->setMinimum(0.1);
    sr->addWidget(m_speedSet);
    sr->addWidget(m_speed);
    sr->addStretch();
    m_cycles = new QSpinBox(this);
    m_cycles->setRange(1, plates::kMaxCycles);
    m_cycles->setKeyboardTracking(false);
    m_seconds = spin(this, plates::kMaxWaitS, tr(" s"), 1);
    m_offset = spin(this, 50, tr(" mm"));
    m_offset->setToolTip(tr("Touch-off: how far from the well's centre toward its +x wall the tip goes"));
    m_sourceRow = new QWidget(this);
    auto* src = new QHBoxLayout(m_sourceRow);
    src->setContentsMargins(0, 0, 0, 0);
    m_sourcePlate = new QComboBox(m_sourceRow);
    m_sourceWell = new QLineEdit(m_sourceRow);
    m_sourceWell->setPlaceholderText(tr("well"));
    m_sourceWell->setMaximumWidth(70);
    m_sourceStation = new QComboBox(m_sourceRow);
    src->addWidget(new QLabel(tr("plate"), m_sourceRow));
    src->addWidget(m_sourcePlate, 1);
    src->addWidget(m_sourceWell);
    src->addWidget(new QLabel(tr("or station"), m_sourceRow));
    src->addWidget(m_sourceStation, 1);
    m_sourceRow->setToolTip(tr("Refill from here before each round: a transfer bigger than the syringe runs in several rounds"));
    m_note = new QLineEdit(this);

    m_form->addRow(tr("Type"), m_type);
    m_form->addRow(tr("Plate"), m_plate);
    m_form->addRow(tr("Wells"), m_wells);
    m_form->addRow(tr("Station"), m_station);
    m_form->addRow(tr("Volume"), m_volume);
    m_form->addRow(tr("Pump speed"), m_speedRow);
    m_form->addRow(tr("Cycles"), m_cycles);
    m_form->addRow(tr("Wait"), m_seconds);
    m_form->addRow(tr("Touch-off"), m_offset);
    m_form->addRow(tr("Source"), m_sourceRow);
    m_form->addRow(tr("Note"), m_note);

    connect(m_type, qOverload<int>(&QComboBox::activated), this, [this] {
        m_step.type = static_cast<StepType>(m_type->currentData().toInt());
        showFieldsOf(m_step.type);
        changed(QStringLiteral("type"));
    });
    connect(m_plate, qOverload<int>(&QComboBox::activated), this, [this] {
        m_step.plate = m_plate->currentData().toString().toStdString();
        changed(QStringLiteral("plate"));
    });
    connect(m_wells, &QLineEdit::editingFinished, this, [this] {
        const auto w = wellsFromText(m_wells->text());
        if (w == m_step.wells)
            return;
        m_step.wells = w;
        changed(QStringLiteral("wells"));
    });
    connect(m_station, qOverload<int>(&QComboBox::activated), this, [this] {
        m_step.station = m_station->currentData().toString().toStdString();
        changed(QStringLiteral("station"));
    });
    connect(m_volume, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        m_step.volumeUl = v;
        changed(QStringLiteral("volume"));
    });
    auto speedChanged = [this] {
        m_speed->setEnabled(m_speedSet->isChecked());
        m_step.speedUlS = m_speedSet->isChecked() ? std::optional<double>(m_speed->value()) : std::nullopt;
        changed(QStringLiteral("speed"));
    };
    connect(m_speedSet, &QCheckBox::toggled, this, speedChanged);
    connect(m_speed, qOverload<double>(&QDoubleSpinBox::valueChanged), this, speedChanged);
    connect(m_cycles, qOverload<int>(&QSpinBox::valueChanged), this, [this](int v) {
        m_step.cycles = v;
        changed(QStringLiteral("cycles"));
    });
    connect(m_seconds, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        m_step.seconds = v;
        changed(QStringLiteral("seconds"));
    });
    connect(m_offset, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        m_step.offsetMm = v;
        changed(QStringLiteral("offset"));
    });
    auto sourceChanged = [this] {
        m_step.source.plate = m_sourcePlate->currentData().toString().toStdString();
        m_step.source.well = m_sourceWell->text().trimmed().toStdString();
        m_step.source.station = m_sourceStation->currentData().toString().toStdString();
        changed(QStringLiteral("source"));
    };
    connect(m_sourcePlate, qOverload<int>(&QComboBox::activated), this, sourceChanged);
    connect(m_sourceWell, &QLineEdit::editingFinished, this, sourceChanged);
    connect(m_sourceStation, qOverload<int>(&QComboBox::activated), this, sourceChanged);
    connect(m_note, &QLineEdit::editingFinished, this, [this] {
        if (m_note->text().toStdString() == m_step.note)
            return;
        m_step.note = m_note->text().toStdString();
        changed(QStringLiteral("note"));
    });
}

void StepForm::setChoices(const QStringList& platesList, const QStringList& stations)
{
    const bool was = m_loading;
    m_loading = true;
    for (QComboBox* c : {m_plate, m_sourcePlate}) {
        c->clear();
        c->addItem(c == m_plate ? tr("(the only plate)") : tr("(none)"), QString());
        for (const QString& p : platesList)
            c->addItem(p, p);
    }
    for (QComboBox* c : {m_station, m_sourceStation}) {
        c->clear();
        c->addItem(tr("(none)"), QString());
        for (const QString& s : stations)
            c->addItem(s, s);
    }
    m_loading = was;
    load();
}

QString StepForm::wellsText(const std::vector<std::string>& specs)
{
    QStringList parts;
    for (const auto& s : specs)
        parts << QString::fromStdString(s);
    return parts.join(QStringLiteral(", "));
}

std::vector<std::string> StepForm::wellsFromText(const QString& text)
{
    const QString t = text.trimmed();
    if (t.isEmpty())
        return {};
    return {t.toStdString()};
}

void StepForm::setStep(const plates::Step& step, int index)
{
    m_step = step;
    m_index = index;
    setEnabled(index >= 0);
    load();
}

void StepForm::showFieldsOf(StepType t)
{
    m_form->setRowVisible(m_plate, takes(t, "plate"));
    m_form->setRowVisible(m_wells, takes(t, "wells"));
    m_form->setRowVisible(m_station, takes(t, "station"));
    m_form->setRowVisible(m_volume, takes(t, "volume"));
    m_form->setRowVisible(m_speedRow, takes(t, "speed"));
    m_form->setRowVisible(m_cycles, takes(t, "cycles"));
    m_form->setRowVisible(m_seconds, takes(t, "seconds"));
    m_form->setRowVisible(m_offset, takes(t, "offset"));
    m_form->setRowVisible(m_sourceRow, takes(t, "source"));
    m_form->labelForField(m_offset)->setProperty("text", t == StepType::Dispense ? tr("Touch-off after each well") : tr("Touch-off"));
}

void StepForm::load()
{
    const bool was = m_loading;
    m_loading = true;
    auto pick = [](QComboBox* c, const std::string& v) {
        const int i = c->findData(QString::fromStdString(v));
        c->setCurrentIndex(i >= 0 ? i : 0);
    };
    m_type->setCurrentIndex(m_type->findData(static_cast<int>(m_step.type)));
    pick(m_plate, m_step.plate);
    m_wells->setText(wellsText(m_step.wells));
    pick(m_station, m_step.station);
    m_volume->setValue(m_step.volumeUl);
    m_speedSet->setChecked(m_step.speedUlS.has_value());
    m_speed->setEnabled(m_step.speedUlS.has_value());
    m_speed->setValue(m_step.speedUlS.value_or(100));
    m_cycles->setValue(m_step.cycles);
    m_seconds->setValue(m_step.seconds);
    m_offset->setValue(m_step.offsetMm);
    pick(m_sourcePlate, m_step.source.plate);
    m_sourceWell->setText(QString::fromStdString(m_step.source.well));
    pick(m_sourceStation, m_step.source.station);
    m_note->setText(QString::fromStdString(m_step.note));
    showFieldsOf(m_step.type);
    m_loading = was;
}

void StepForm::changed(const QString& field)
{
    if (m_loading || m_index < 0)
        return;
    emit edited(m_step, field);
}

} // namespace ui
