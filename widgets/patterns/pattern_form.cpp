#include "widgets/patterns/pattern_form.h"

#include "widgets/common/number_field.h"
#include "widgets/wording/wording.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

using motion::plans::Pattern;
using motion::plans::PatternShape;

namespace {

QString shapeTitle(PatternShape s)
{
    switch (s) {
    case PatternShape::Line: return PatternForm::tr("Line");
    case PatternShape::Rectangle: return PatternForm::tr("Rectangle");
    case PatternShape::Circle: return PatternForm::tr("Circle");
    case PatternShape::Arc: return PatternForm::tr("Arc");
    case PatternShape::Sine: return PatternForm::tr("Sine (chords)");
    case PatternShape::Cosine: return PatternForm::tr("Cosine (chords)");
    case PatternShape::Spiral: return PatternForm::tr("Spiral");
    case PatternShape::Raster: return PatternForm::tr("Raster (serpentine)");
    }
    return {};
}

QString key(PatternShape s, const char* field) { return QString::fromLatin1(motion::plans::shapeName(s)) + QLatin1Char('.') + QLatin1String(field); }

}  // namespace

PatternForm::PatternForm(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* common = m_common = new QFormLayout;
    m_name = new QLineEdit(this);
    m_name->setPlaceholderText(tr("a name for the saved file"));
    m_shape = new QComboBox(this);
    m_shape->setObjectName(QStringLiteral("patternShape"));
    for (PatternShape s : motion::plans::kAllShapes)
        m_shape->addItem(shapeTitle(s), QString::fromLatin1(motion::plans::shapeName(s)));
    m_feed = new NumberField(this);
    m_feed->setObjectName(QStringLiteral("feed_mm_s"));
    m_feed->setRange(0.001, 1000);
    m_feed->setDisplay('g', 10);
    m_feed->setUnit(tr(" mm/s"));
    m_feed->setHelp(tr("Path speed (feed): how fast the pattern is run along its length"));
    m_fields.insert(QStringLiteral("feed_mm_s"), m_feed);
    common->addRow(tr("Name"), m_name);
    common->addRow(tr("Shape"), m_shape);
    common->addRow(tr("Feed"), m_feed);
    m_zRow = new QWidget(this);
    auto* zr = new QHBoxLayout(m_zRow);
    zr->setContentsMargins(0, 0, 0, 0);
    m_useZ = new QCheckBox(tr("work at Z"), m_zRow);
    m_useZ->setToolTip(tr("Z goes to this height once X and Y are at the start (seed 000: Z follows XY)"));
    m_z = new NumberField(m_zRow);
    m_z->setObjectName(QStringLiteral("z_mm"));
    m_z->setFieldName(tr("Z"));
    m_z->setRange(-10000, 10000);
    m_z->setDisplay('g', 10);
    m_z->setUnit(tr(" mm"));
    m_z->setEnabled(false);
    zr->addWidget(m_useZ);
    zr->addWidget(m_z, 1);
    common->addRow(tr("Z"), m_zRow);
    v->addLayout(common);

    m_pages = new QStackedWidget(this);
    for (PatternShape s : motion::plans::kAllShapes)
        m_pages->addWidget(page(s));
    v->addWidget(m_pages);
    m_problems = new QLabel(this);
    m_problems->setObjectName(QStringLiteral("patternProblems"));
    m_problems->setWordWrap(true);
    m_problems->setStyleSheet(QStringLiteral("color:#b71c1c;"));
    v->addWidget(m_problems);
    v->addStretch(1);

    connect(m_shape, &QComboBox::currentIndexChanged, this, [this](int i) {
        m_pages->setCurrentIndex(i);
        if (!m_loading) {
            showProblems();
            emit changed();
        }
    });
    connect(m_useZ, &QCheckBox::toggled, m_z, &QWidget::setEnabled);
    for (QCheckBox* c : {m_useZ})
        connect(c, &QCheckBox::toggled, this, [this] {
            if (!m_loading)
                emit changed();
        });
    for (NumberField* b : {m_feed, m_z})
        connect(b, &NumberField::entryChanged, this, [this] {
            if (!m_loading) {
                showProblems();
                emit changed();
            }
        });
    connect(m_name, &QLineEdit::textEdited, this, [this] { emit changed(); });
    setPattern(Pattern{});
}

// Kept as typed: "-5" in Radius is shown as invalid with its reason and nothing is planned
// from it, never turned into 5 by a spin box that cannot take the minus.
NumberField* PatternForm::number(const QString& name, double lo, double hi, int decimals, const QString& suffix,
                                 const QString& tip)
{
    auto* b = new NumberField(this);
    b->setObjectName(name);
    b->setRange(lo, hi);
    b->setDisplay('g', std::max(10, decimals + 6));  // every digit a pattern file has
    b->setUnit(suffix);
    b->setHelp(tip);
    m_fields.insert(name, b);
    connect(b, &NumberField::entryChanged, this, [this] {
        if (!m_loading) {
            showProblems();
            emit changed();
        }
    });
    return b;
}

QWidget* PatternForm::pointRow(const QString& name, const QString& tip)
{
    auto* w = new QWidget(this);
    auto* h = new QHBoxLayout(w);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(new QLabel(tr("X", "axis"), w));
    auto* x = number(name + QStringLiteral(".x"), -10000, 10000, 3, tr(" mm"), tip);
    auto* y = number(name + QStringLiteral(".y"), -10000, 10000, 3, tr(" mm"), tip);
    static_cast<QLabel*>(h->itemAt(0)->widget())->setBuddy(x);  // a reason names the axis typed in
    h->addWidget(x, 1);
    auto* yLabel = new QLabel(tr("Y", "axis"), w);
    yLabel->setBuddy(y);
    h->addWidget(yLabel);
    h->addWidget(y, 1);
    return w;
}

QWidget* PatternForm::page(PatternShape s)
{
    auto* w = new QWidget(this);
    auto* f = new QFormLayout(w);
    f->setContentsMargins(0, 6, 0, 0);
    const QString mm = tr(" mm"), deg = tr(" °");
    auto dir = [&](const QString& k) {
        auto* c = new QComboBox(w);
        c->addItem(tr("counter-clockwise"), false);
        c->addItem(tr("clockwise"), true);
        m_choices.insert(k, c);
        connect(c, &QComboBox::currentIndexChanged, this, [this] {
            if (!m_loading)
                emit changed();
        });
        return c;
    };
    switch (s) {
    case PatternShape::Line:
        f->addRow(tr("Start"), pointRow(key(s, "start_mm"), tr("Where the line begins")));
        f->addRow(tr("End"), pointRow(key(s, "end_mm"), tr("Where the line ends")));
        break;
    case PatternShape::Rectangle:
        f->addRow(tr("Corner"), pointRow(key(s, "corner_mm"), tr("Lower-left corner: the run starts and ends here")));
        f->addRow(tr("Width"), number(key(s, "width_mm"), 0, 10000, 3, mm));
        f->addRow(tr("Height"), number(key(s, "height_mm"), 0, 10000, 3, mm));
        f->addRow(tr("Direction"), dir(key(s, "direction")));
        break;
    case PatternShape::Circle:
        f->addRow(tr("Centre"), pointRow(key(s, "center_mm"), {}));
        f->addRow(tr("Radius"), number(key(s, "radius_mm"), 0, 10000, 4, mm));
        f->addRow(tr("Start angle"), number(key(s, "start_deg"), -360, 360, 2, deg, tr("0° is +X, 90° is +Y")));
        f->addRow(tr("Direction"), dir(key(s, "direction")));
        break;
    case PatternShape::Arc:
        f->addRow(tr("Centre"), pointRow(key(s, "center_mm"), {}));
        f->addRow(tr("Radius"), number(key(s, "radius_mm"), 0, 10000, 4, mm));
        f->addRow(tr("Start angle"), number(key(s, "start_deg"), -360, 360, 2, deg, tr("0° is +X, 90° is +Y")));
        f->addRow(tr("Sweep"), number(key(s, "sweep_deg"), 0, 360, 2, deg));
        f->addRow(tr("Direction"), dir(key(s, "direction")));
        break;
    case PatternShape::Sine:
    case PatternShape::Cosine:
        f->addRow(tr("Origin"), pointRow(key(s, "origin_mm"), tr("Start of the wave's axis")));
        f->addRow(tr("Amplitude"), number(key(s, "amplitude_mm"), 0, 10000, 3, mm));
        f->addRow(tr("Wavelength"), number(key(s, "wavelength_mm"), 0, 10000, 3, mm));
        f->addRow(tr("Length"), number(key(s, "length_mm"), 0, 10000, 3, mm, tr("Along the wave's axis")));
        f->addRow(tr("Axis angle"), number(key(s, "angle_deg"), -360, 360, 2, deg, tr("Direction of the wave's axis, 0° = +X")));
        f->addRow(tr("Chord tolerance"), number(key(s, "tolerance_mm"), 0, 1, 5, mm,
                                                tr("Largest gap between a chord and the curve (seed 002's equal parts)")));
        break;
    case PatternShape::Spiral:
        f->addRow(tr("Centre"), pointRow(key(s, "center_mm"), {}));
        f->addRow(tr("Start radius"), number(key(s, "start_radius_mm"), 0, 10000, 4, mm));
        f->addRow(tr("Pitch"), number(key(s, "pitch_mm"), 0, 10000, 4, mm, tr("Radius gained per turn")));
        f->addRow(tr("Turns"), number(key(s, "turns"), 0, 1000, 1, QString(), tr("Whole or half turns")));
        f->addRow(tr("Start angle"), number(key(s, "start_deg"), -360, 360, 2, deg));
        f->addRow(tr("Direction"), dir(key(s, "direction")));
        break;
    case PatternShape::Raster: {
        f->addRow(tr("Corner"), pointRow(key(s, "corner_mm"), tr("Lower-left corner: the first pass starts here")));
        f->addRow(tr("Width"), number(key(s, "width_mm"), 0, 10000, 3, mm));
        f->addRow(tr("Height"), number(key(s, "height_mm"), 0, 10000, 3, mm));
        f->addRow(tr("Pass spacing"), number(key(s, "spacing_mm"), 0, 10000, 4, mm));
        auto* along = new QComboBox(w);
        along->addItem(tr("along X"), false);
        along->addItem(tr("along Y"), true);
        m_choices.insert(key(s, "passes_along"), along);
        connect(along, &QComboBox::currentIndexChanged, this, [this] {
            if (!m_loading)
                emit changed();
        });
        f->addRow(tr("Passes"), along);
        break;
    }
    }
    return w;
}

void PatternForm::setZAvailable(bool available)
{
    m_zAvailable = available;
    m_common->setRowVisible(m_zRow, available);
    if (!available)
        m_useZ->setChecked(false);
}

Pattern PatternForm::pattern() const
{
    Pattern p;
    p.name = m_name->text().toStdString();
    p.shape = motion::plans::kAllShapes[std::max(0, m_shape->currentIndex())];
    // A field whose text is not a valid number gives NaN: the validator refuses it, so nothing
    // is planned, run or saved from a number nobody typed.
    const double nan = std::nan("");
    p.feedMmS = m_feed->valueOr(nan);
    if (m_useZ->isChecked() && m_zAvailable)
        p.zMm = m_z->valueOr(nan);
    auto n = [&](PatternShape s, const char* f) { return m_fields.value(key(s, f))->valueOr(nan); };
    auto pt = [&](PatternShape s, const char* f) {
        return motion::path::Vec2{m_fields.value(key(s, f) + QStringLiteral(".x"))->valueOr(nan),
                                  m_fields.value(key(s, f) + QStringLiteral(".y"))->valueOr(nan)};
    };
    auto cw = [&](PatternShape s, const char* f) { return m_choices.value(key(s, f))->currentData().toBool(); };
    using S = PatternShape;
    p.line = {pt(S::Line, "start_mm"), pt(S::Line, "end_mm")};
    p.rectangle = {pt(S::Rectangle, "corner_mm"), n(S::Rectangle, "width_mm"), n(S::Rectangle, "height_mm"), cw(S::Rectangle, "direction")};
    p.circle = {pt(S::Circle, "center_mm"), n(S::Circle, "radius_mm"), n(S::Circle, "start_deg"), cw(S::Circle, "direction")};
    p.arc = {pt(S::Arc, "center_mm"), n(S::Arc, "radius_mm"), n(S::Arc, "start_deg"), n(S::Arc, "sweep_deg"), cw(S::Arc, "direction")};
    const S wave = p.shape == S::Cosine ? S::Cosine : S::Sine;  // the shown page's values
    p.wave = {pt(wave, "origin_mm"), n(wave, "amplitude_mm"), n(wave, "wavelength_mm"), n(wave, "length_mm"),
              n(wave, "angle_deg"), n(wave, "tolerance_mm")};
    p.spiral = {pt(S::Spiral, "center_mm"), n(S::Spiral, "start_radius_mm"), n(S::Spiral, "pitch_mm"), n(S::Spiral, "turns"),
                n(S::Spiral, "start_deg"), cw(S::Spiral, "direction")};
    p.raster = {pt(S::Raster, "corner_mm"), n(S::Raster, "width_mm"), n(S::Raster, "height_mm"), n(S::Raster, "spacing_mm"),
                cw(S::Raster, "passes_along")};
    return p;
}

void PatternForm::setPattern(const Pattern& p)
{
    m_loading = true;
    m_name->setText(QString::fromStdString(p.name));
    m_feed->setValue(p.feedMmS);
    m_useZ->setChecked(p.zMm.has_value());
    if (p.zMm)
        m_z->setValue(*p.zMm);
    auto set = [&](PatternShape s, const char* f, double v) { m_fields.value(key(s, f))->setValue(v); };
    auto setPt = [&](PatternShape s, const char* f, motion::path::Vec2 v) {
        m_fields.value(key(s, f) + QStringLiteral(".x"))->setValue(v.x);
        m_fields.value(key(s, f) + QStringLiteral(".y"))->setValue(v.y);
    };
    auto setCw = [&](PatternShape s, const char* f, bool on) { m_choices.value(key(s, f))->setCurrentIndex(on ? 1 : 0); };
    using S = PatternShape;
    setPt(S::Line, "start_mm", p.line.startMm);
    setPt(S::Line, "end_mm", p.line.endMm);
    setPt(S::Rectangle, "corner_mm", p.rectangle.cornerMm);
    set(S::Rectangle, "width_mm", p.rectangle.widthMm);
    set(S::Rectangle, "height_mm", p.rectangle.heightMm);
    setCw(S::Rectangle, "direction", p.rectangle.clockwise);
    setPt(S::Circle, "center_mm", p.circle.centerMm);
    set(S::Circle, "radius_mm", p.circle.radiusMm);
    set(S::Circle, "start_deg", p.circle.startDeg);
    setCw(S::Circle, "direction", p.circle.clockwise);
    setPt(S::Arc, "center_mm", p.arc.centerMm);
    set(S::Arc, "radius_mm", p.arc.radiusMm);
    set(S::Arc, "start_deg", p.arc.startDeg);
    set(S::Arc, "sweep_deg", p.arc.sweepDeg);
    setCw(S::Arc, "direction", p.arc.clockwise);
    for (S w : {S::Sine, S::Cosine}) {
        setPt(w, "origin_mm", p.wave.originMm);
        set(w, "amplitude_mm", p.wave.amplitudeMm);
        set(w, "wavelength_mm", p.wave.wavelengthMm);
        set(w, "length_mm", p.wave.lengthMm);
        set(w, "angle_deg", p.wave.angleDeg);
        set(w, "tolerance_mm", p.wave.toleranceMm);
    }
    setPt(S::Spiral, "center_mm", p.spiral.centerMm);
    set(S::Spiral, "start_radius_mm", p.spiral.startRadiusMm);
    set(S::Spiral, "pitch_mm", p.spiral.pitchMm);
    set(S::Spiral, "turns", p.spiral.turns);
    set(S::Spiral, "start_deg", p.spiral.startDeg);
    setCw(S::Spiral, "direction", p.spiral.clockwise);
    setPt(S::Raster, "corner_mm", p.raster.cornerMm);
    set(S::Raster, "width_mm", p.raster.widthMm);
    set(S::Raster, "height_mm", p.raster.heightMm);
    set(S::Raster, "spacing_mm", p.raster.spacingMm);
    setCw(S::Raster, "passes_along", p.raster.alongY);
    int index = 0;
    for (int i = 0; i < 8; ++i)
        if (motion::plans::kAllShapes[i] == p.shape)
            index = i;
    m_shape->setCurrentIndex(index);
    m_pages->setCurrentIndex(index);
    m_loading = false;
    showProblems();
    emit changed();
}

QString PatternForm::entryProblem() const { return NumberField::firstProblemUnder(this); }

void PatternForm::showProblems()
{
    QStringList lines;
    if (const QString typed = entryProblem(); !typed.isEmpty())
        lines << typed;
    lines << ui::words::problems(motion::plans::validate(pattern()));
    m_problems->setText(lines.join(QLatin1Char('\n')));
}

} // namespace ui
