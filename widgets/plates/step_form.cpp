#include "widgets/plates/step_form.h"
#include "widgets/plates/step_texts.h"
#include "widgets/common/number_field.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

#include <utility>

namespace ui {

using motion::plates::StepType;

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

/// A number field for a step, with its unit after it in `row` (a spin box clamped a
/// file's 900 µL/s to 500 without a word; this shows 900, marked invalid).
NumberField* stepNumber(QWidget* row, double min, double max, const QString& name, const QString& unit)
{
    auto* lay = new QHBoxLayout(row);
    lay->setContentsMargins(0, 0, 0, 0);
    auto* f = new NumberField(row);
    f->setRange(min, max);
    f->setFieldName(name);
    f->setDisplay('g', 10);  // every digit the file has: a rounded display would be written back
    f->setMaximumWidth(120);
    lay->addWidget(f);
    if (!unit.isEmpty())
        lay->addWidget(new QLabel(unit, row));
    lay->addStretch();
    return f;
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
    // In the narrow tab a long label ("Touch-off after each well", or its translation)
    // puts its field on the next line rather than pushing the form wider than the tab.
    m_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_type = new QComboBox(this);
    for (int i = 0; i < motion::plates::kStepTypeCount; ++i)
        m_type->addItem(stepTypeTitle(static_cast<StepType>(i)), i);  // the id is the item data
    m_plate = new QComboBox(this);
    m_wells = new QLineEdit(this);
    m_wells->setPlaceholderText(tr("A1:H1, row B, column 3, all, or a list: A1, C4"));
    m_wells->setToolTip(tr("Wells: a well (A1), a range (A1:H1), \"row B\", \"column 3\", \"all\", or several separated by commas.\n"
                           "Select wells on the plate map and press \"Use selection\" to fill this in."));
    m_station = new QComboBox(this);
    m_volumeRow = new QWidget(this);
    m_volume = stepNumber(m_volumeRow, 0, 100000, tr("Volume"), tr(" µL").trimmed());
    m_volume->setHelp(tr("Per well (aspirate, dispense), per stroke (mix, wash), or the air gap"));
    m_speedRow = new QWidget(this);
    auto* sr = new QHBoxLayout(m_speedRow);
    sr->setContentsMargins(0, 0, 0, 0);
    m_speedSet = new QCheckBox(tr("set"), m_speedRow);
    sr->addWidget(m_speedSet);
    auto* speedHost = new QWidget(m_speedRow);
    m_speed = stepNumber(speedHost, 0.1, 500, tr("Pump speed"), tr(" µL/s").trimmed());
    sr->addWidget(speedHost, 1);
    m_cycles = new NumberField(this);
    m_cycles->setInteger(true);
    m_cycles->setRange(1, motion::plates::kMaxCycles);
    m_cycles->setFieldName(tr("Cycles"));
    m_cycles->setMaximumWidth(120);
    m_secondsRow = new QWidget(this);
    m_seconds = stepNumber(m_secondsRow, 0, motion::plates::kMaxWaitS, tr("Wait"), tr(" s").trimmed());
    m_offsetRow = new QWidget(this);
    m_offset = stepNumber(m_offsetRow, 0, 50, tr("Touch-off"), tr(" mm").trimmed());
    m_offset->setHelp(tr("Touch-off: how far from the well's centre toward its +x wall the tip goes"));
    m_sourceRow = new QWidget(this);
    // Two lines (a plate and its well, or a station): on one it was wider than the tab.
    auto* src = new QGridLayout(m_sourceRow);
    src->setContentsMargins(0, 0, 0, 0);
    m_sourcePlate = new QComboBox(m_sourceRow);
    m_sourceWell = new QLineEdit(m_sourceRow);
    m_sourceWell->setPlaceholderText(tr("well"));
    m_sourceWell->setMaximumWidth(70);
    m_sourceStation = new QComboBox(m_sourceRow);
    src->addWidget(new QLabel(tr("plate"), m_sourceRow), 0, 0);
    src->addWidget(m_sourcePlate, 0, 1);
    src->addWidget(m_sourceWell, 0, 2);
    src->addWidget(new QLabel(tr("or station"), m_sourceRow), 1, 0);
    src->addWidget(m_sourceStation, 1, 1);
    src->setColumnStretch(1, 1);
    m_sourceRow->setToolTip(tr("Refill from here before each round: a transfer bigger than the syringe runs in several rounds"));
    m_note = new QLineEdit(this);

    m_form->addRow(tr("Type"), m_type);
    m_form->addRow(tr("Plate"), m_plate);
    m_form->addRow(tr("Wells"), m_wells);
    m_form->addRow(tr("Station"), m_station);
    m_form->addRow(tr("Volume"), m_volumeRow);
    m_form->addRow(tr("Pump speed"), m_speedRow);
    m_form->addRow(tr("Cycles"), m_cycles);
    m_form->addRow(tr("Wait"), m_secondsRow);
    m_form->addRow(tr("Touch-off"), m_offsetRow);
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
    // A number changes the step once it is finished and valid; until then the step keeps
    // what it had (the file's value), and only a changed value is an edit.
    auto number = [this](NumberField* f, const char* field, auto set) {
        connect(f, &QLineEdit::editingFinished, this, [this, f, field, set] {
            if (const auto v = f->value(); v && set(*v))
                changed(QLatin1String(field));
        });
    };
    number(m_volume, "volume", [this](double v) { return std::exchange(m_step.volumeUl, v) != v; });
    number(m_cycles, "cycles", [this](double v) { return std::exchange(m_step.cycles, static_cast<int>(v)) != static_cast<int>(v); });
    number(m_seconds, "seconds", [this](double v) { return std::exchange(m_step.seconds, v) != v; });
    number(m_offset, "offset", [this](double v) { return std::exchange(m_step.offsetMm, v) != v; });
    number(m_speed, "speed", [this](double v) { return std::exchange(m_step.speedUlS, std::optional<double>(v)) != std::optional<double>(v); });
    connect(m_speedSet, &QCheckBox::toggled, this, [this](bool on) {
        m_speed->setEnabled(on);
        if (m_loading)
            return;
        // Ticked with an invalid entry: the step gets a speed once the entry is fixed.
        if (!on)
            m_step.speedUlS.reset();
        else if (m_speed->value())
            m_step.speedUlS = m_speed->value();
        changed(QStringLiteral("speed"));
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

void StepForm::setStep(const motion::plates::Step& step, int index)
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
    m_form->setRowVisible(m_volumeRow, takes(t, "volume"));
    m_form->setRowVisible(m_speedRow, takes(t, "speed"));
    m_form->setRowVisible(m_cycles, takes(t, "cycles"));
    m_form->setRowVisible(m_secondsRow, takes(t, "seconds"));
    m_form->setRowVisible(m_offsetRow, takes(t, "offset"));
    m_form->setRowVisible(m_sourceRow, takes(t, "source"));
    m_form->labelForField(m_offsetRow)->setProperty("text", t == StepType::Dispense ? tr("Touch-off after each well") : tr("Touch-off"));
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
    // Only a value that differs: the field being typed into keeps its text.
    auto show = [](NumberField* f, double v) {
        if (f->value() != std::optional<double>(v))
            f->setValue(v);
    };
    show(m_volume, m_step.volumeUl);
    m_speedSet->setChecked(m_step.speedUlS.has_value());
    m_speed->setEnabled(m_step.speedUlS.has_value());
    show(m_speed, m_step.speedUlS.value_or(100));
    show(m_cycles, m_step.cycles);
    show(m_seconds, m_step.seconds);
    show(m_offset, m_step.offsetMm);
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
