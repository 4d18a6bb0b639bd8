#include "widgets/scan/scan_plan_form.h"

#include "widgets/common/number_field.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

using namespace motion::scan;

namespace {

QString polygonText(const std::vector<Point2>& vs)
{
    QStringList parts;
    for (const Point2& v : vs)
        parts << QStringLiteral("%1, %2").arg(v.xMm, 0, 'g', 8).arg(v.yMm, 0, 'g', 8);
    return parts.join(QStringLiteral("; "));
}

/// "x, y; x, y; …" → vertices, or an error naming the corner that does not read.
std::vector<Point2> parsePolygon(const QString& text, QString* error)
{
    std::vector<Point2> out;
    error->clear();
    const QStringList corners = text.split(QLatin1Char(';'), Qt::SkipEmptyParts);
    for (int i = 0; i < corners.size(); ++i) {
        const QStringList xy = corners[i].split(QRegularExpression(QStringLiteral("[,\\s]+")), Qt::SkipEmptyParts);
        bool okX = false, okY = false;
        const double x = xy.size() == 2 ? xy[0].toDouble(&okX) : 0, y = xy.size() == 2 ? xy[1].toDouble(&okY) : 0;
        if (!okX || !okY) {
            *error = QCoreApplication::translate("ui::ScanPlanForm", "corner %1 (\"%2\") is not \"x, y\" in mm")
                         .arg(i + 1)
                         .arg(corners[i].trimmed());
            return {};
        }
        out.push_back({x, y});
    }
    return out;
}

/// What plan() gives for a typed number that is not valid (entryProblem() says why).
const double kScanFormNaN = std::nan("");

QGroupBox* group(const QString& title, QLayout* layout)
{
    auto* g = new QGroupBox(title);
    g->setLayout(layout);
    return g;
}

} // namespace

ScanPlanForm::ScanPlanForm(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    v->addWidget(regionGroup());
    v->addWidget(cameraGroup());
    v->addWidget(gridGroup());
    v->addWidget(runGroup());
    v->addWidget(exportGroup());
    v->addStretch(1);
    setPlan(ScanPlan{});
}

// Kept as typed: "-5" in Speed is shown as invalid with its reason and nothing is planned
// from it, never turned into 5 by a spin box that cannot take the minus.
NumberField* ScanPlanForm::number(const QString& name, double min, double max, double value, int decimals,
                                  const QString& suffix, const QString& tip)
{
    auto* s = new NumberField;
    s->setObjectName(name);
    s->setRange(min, max);
    s->setDisplay('g', std::max(10, decimals + 6));  // every digit a plan file has: a rounded display would be saved back
    s->setValue(value);
    s->setUnit(suffix);
    s->setHelp(tip);
    s->setFieldName(tip);  // two fields share a row's label ("Corner X, Y"): the reason names which
    // Wide ranges would make the boxes as wide as their longest number; the panel is narrow.
    s->setMinimumWidth(70);
    s->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    connect(s, &NumberField::entryChanged, this, &ScanPlanForm::changed);  // the screen replans on a timer
    return s;
}

QString ScanPlanForm::entryProblem() const { return NumberField::firstProblemUnder(this); }

QWidget* ScanPlanForm::regionGroup()
{
    auto* form = new QFormLayout;
    m_name = new QLineEdit;
    m_name->setObjectName(QStringLiteral("scanName"));
    m_name->setToolTip(tr("What the scan is called in its files"));
    connect(m_name, &QLineEdit::editingFinished, this, &ScanPlanForm::changed);
    form->addRow(tr("Name"), m_name);
    m_regionKind = new QComboBox;
    m_regionKind->setObjectName(QStringLiteral("scanRegionKind"));
    m_regionKind->addItem(tr("Two corners"), int(RegionKind::Corners));
    m_regionKind->addItem(tr("Centre and size"), int(RegionKind::CentreSize));
    m_regionKind->addItem(tr("Polygon"), int(RegionKind::Polygon));
    m_regionKind->setToolTip(tr("Drag on the map to draw a rectangle; in Polygon mode click its corners and double-click to close"));
    form->addRow(tr("Region"), m_regionKind);
    m_regionPages = new QStackedWidget;
    const QString mm = tr(" mm");
    // Two corners
    auto* corners = new QWidget;
    auto* cg = new QFormLayout(corners);
    cg->setContentsMargins(0, 0, 0, 0);
    m_x0 = number(QStringLiteral("scanX0"), -100000, 100000, 10, 4, mm, tr("First corner, X"));
    m_y0 = number(QStringLiteral("scanY0"), -100000, 100000, 10, 4, mm, tr("First corner, Y"));
    m_x1 = number(QStringLiteral("scanX1"), -100000, 100000, 30, 4, mm, tr("Opposite corner, X"));
    m_y1 = number(QStringLiteral("scanY1"), -100000, 100000, 25, 4, mm, tr("Opposite corner, Y"));
    auto pair = [](QWidget* a, QWidget* b) {
        auto* w = new QWidget;
        auto* h = new QHBoxLayout(w);
        h->setContentsMargins(0, 0, 0, 0);
        h->addWidget(a);
        h->addWidget(b);
        return w;
    };
    cg->addRow(tr("Corner X, Y"), pair(m_x0, m_y0));
    cg->addRow(tr("Opposite X, Y"), pair(m_x1, m_y1));
    m_regionPages->addWidget(corners);
    // Centre and size
    auto* centre = new QWidget;
    auto* zg = new QFormLayout(centre);
    zg->setContentsMargins(0, 0, 0, 0);
    m_cx = number(QStringLiteral("scanCentreX"), -100000, 100000, 50, 4, mm, tr("Centre of the region, X"));
    m_cy = number(QStringLiteral("scanCentreY"), -100000, 100000, 50, 4, mm, tr("Centre of the region, Y"));
    m_w = number(QStringLiteral("scanWidth"), 0, 100000, 10, 4, mm, tr("Width of the region (X)"));
    m_h = number(QStringLiteral("scanHeight"), 0, 100000, 10, 4, mm, tr("Height of the region (Y)"));
    zg->addRow(tr("Centre X, Y"), pair(m_cx, m_cy));
    zg->addRow(tr("Width, height"), pair(m_w, m_h));
    m_regionPages->addWidget(centre);
    // Polygon
    m_vertices = new QLineEdit;
    m_vertices->setObjectName(QStringLiteral("scanVertices"));
    m_vertices->setPlaceholderText(tr("x, y; x, y; x, y …"));
    m_vertices->setToolTip(tr("The outline's corners in mm, in order; click them on the map instead"));
    connect(m_vertices, &QLineEdit::editingFinished, this, &ScanPlanForm::changed);
    auto* polygon = new QWidget;
    auto* pv = new QVBoxLayout(polygon);
    pv->setContentsMargins(0, 0, 0, 0);
    pv->addWidget(new QLabel(tr("Corners (x, y mm; …), or click them on the map:")));
    pv->addWidget(m_vertices);
    pv->addStretch(1);
    m_regionPages->addWidget(polygon);
    form->addRow(m_regionPages);
    connect(m_regionKind, &QComboBox::currentIndexChanged, this, [this](int i) {
        m_regionPages->setCurrentIndex(i);
        emit regionKindChanged(static_cast<RegionKind>(m_regionKind->itemData(i).toInt()));
        changed();
    });
    return group(tr("Scan and region"), form);
}

QWidget* ScanPlanForm::cameraGroup()
{
    auto* form = new QFormLayout;
    m_fovFrom = new QComboBox;
    m_fovFrom->setObjectName(QStringLiteral("scanFovFrom"));
    m_fovFrom->addItem(tr("Sensor and objective"), int(FieldSource::Sensor));
    m_fovFrom->addItem(tr("Field size"), int(FieldSource::Direct));
    form->addRow(tr("Field from"), m_fovFrom);
    m_cameraPages = new QStackedWidget;
    auto* sensor = new QWidget;
    auto* sg = new QFormLayout(sensor);
    sg->setContentsMargins(0, 0, 0, 0);
    auto pixels = [this](const QString& name, const QString& tip) {
        auto* s = new NumberField;
        s->setObjectName(name);
        s->setInteger(true);
        s->setRange(1, 100000);
        s->setUnit(tr(" px"));
        s->setHelp(tip);
        s->setFieldName(tip);
        connect(s, &NumberField::entryChanged, this, &ScanPlanForm::changed);
        return s;
    };
    m_sensorW = pixels(QStringLiteral("scanSensorW"), tr("Sensor width in pixels"));
    m_sensorH = pixels(QStringLiteral("scanSensorH"), tr("Sensor height in pixels"));
    auto* px = new QWidget;
    auto* ph = new QHBoxLayout(px);
    ph->setContentsMargins(0, 0, 0, 0);
    ph->addWidget(m_sensorW);
    ph->addWidget(new QLabel(QStringLiteral("×")));
    ph->addWidget(m_sensorH);
    sg->addRow(tr("Sensor"), px);
    m_sensorPixel = number(QStringLiteral("scanSensorPixel"), 0.001, 1000, 6.5, 4, tr(" µm"), tr("Pixel pitch on the sensor"));
    sg->addRow(tr("Pixel size"), m_sensorPixel);
    m_magnification = number(QStringLiteral("scanMagnification"), 0.01, 10000, 10, 3, tr(" ×"), tr("Objective times any relay lens"));
    sg->addRow(tr("Magnification"), m_magnification);
    m_cameraPages->addWidget(sensor);
    auto* direct = new QWidget;
    auto* dg = new QFormLayout(direct);
    dg->setContentsMargins(0, 0, 0, 0);
    m_fieldW = number(QStringLiteral("scanFieldW"), 0.001, 10000, 1, 5, tr(" mm"), tr("Field width at the sample"));
    m_fieldH = number(QStringLiteral("scanFieldH"), 0.001, 10000, 1, 5, tr(" mm"), tr("Field height at the sample"));
    auto* fw = new QWidget;
    auto* fh = new QHBoxLayout(fw);
    fh->setContentsMargins(0, 0, 0, 0);
    fh->addWidget(m_fieldW);
    fh->addWidget(new QLabel(QStringLiteral("×")));
    fh->addWidget(m_fieldH);
    dg->addRow(tr("Field"), fw);
    m_samplePixel = number(QStringLiteral("scanSamplePixel"), 0.001, 1000, 0.65, 4, tr(" µm"),
                           tr("One pixel at the sample: the exports give positions in pixels"));
    dg->addRow(tr("Pixel at sample"), m_samplePixel);
    m_cameraPages->addWidget(direct);
    form->addRow(m_cameraPages);
    m_rotation = number(QStringLiteral("scanRotation"), -180, 180, 0, 2, tr("°"),
                        tr("The image's x axis against stage +X, counter-clockwise (a small calibration angle)"));
    form->addRow(tr("Camera rotation"), m_rotation);
    m_imageY = new QComboBox;
    m_imageY->addItem(tr("down the image = stage −Y"), int(ImageY::StageMinusY));
    m_imageY->addItem(tr("down the image = stage +Y"), int(ImageY::StagePlusY));
    m_imageY->setToolTip(tr("Which way image rows run on the stage; flip it if the stitched mosaic comes out mirrored"));
    form->addRow(tr("Image rows"), m_imageY);
    m_cameraInfo = new QLabel;
    m_cameraInfo->setObjectName(QStringLiteral("scanCameraInfo"));
    form->addRow(m_cameraInfo);
    connect(m_fovFrom, &QComboBox::currentIndexChanged, this, [this](int i) {
        m_cameraPages->setCurrentIndex(i);
        changed();
    });
    connect(m_imageY, &QComboBox::currentIndexChanged, this, &ScanPlanForm::changed);
    return group(tr("Camera"), form);
}

QWidget* ScanPlanForm::gridGroup()
{
    auto* form = new QFormLayout;
    m_overlapX = number(QStringLiteral("scanOverlapX"), 0, 90, 10, 1, tr(" %"), tr("Share of the field neighbours overlap in X (0–90 %)"));
    m_overlapY = number(QStringLiteral("scanOverlapY"), 0, 90, 10, 1, tr(" %"), tr("Share of the field neighbours overlap in Y (0–90 %)"));
    auto* o = new QWidget;
    auto* oh = new QHBoxLayout(o);
    oh->setContentsMargins(0, 0, 0, 0);
    oh->addWidget(m_overlapX);
    oh->addWidget(m_overlapY);
    form->addRow(tr("Overlap X, Y"), o);
    m_order = new QComboBox;
    m_order->setObjectName(QStringLiteral("scanOrder"));
    m_order->addItem(tr("Snake by rows"), int(ScanOrder::SnakeRows));
    m_order->addItem(tr("Snake by columns"), int(ScanOrder::SnakeColumns));
    m_order->addItem(tr("Row by row"), int(ScanOrder::Rows));
    m_order->addItem(tr("Column by column"), int(ScanOrder::Columns));
    form->addRow(tr("Order"), m_order);
    m_start = new QComboBox;
    m_start->setObjectName(QStringLiteral("scanStart"));
    m_start->addItem(tr("Top left"), int(StartCorner::TopLeft));
    m_start->addItem(tr("Top right"), int(StartCorner::TopRight));
    m_start->addItem(tr("Bottom left"), int(StartCorner::BottomLeft));
    m_start->addItem(tr("Bottom right"), int(StartCorner::BottomRight));
    form->addRow(tr("Start corner"), m_start);
    m_unidirectional = new QCheckBox(tr("Approach every tile from the same side"));
    m_unidirectional->setObjectName(QStringLiteral("scanUnidirectional"));
    m_unidirectional->setToolTip(tr("Takes up screw backlash the same way at every tile: a move the other way first "
                                    "goes past the tile by the overtravel"));
    form->addRow(m_unidirectional);
    m_overtravel = number(QStringLiteral("scanOvertravel"), 0.001, 10, 0.2, 3, tr(" mm"), tr("How far before the tile the approach starts"));
    form->addRow(tr("Overtravel"), m_overtravel);
    for (QComboBox* c : {m_order, m_start})
        connect(c, &QComboBox::currentIndexChanged, this, &ScanPlanForm::changed);
    connect(m_unidirectional, &QCheckBox::toggled, this, [this](bool on) {
        m_overtravel->setEnabled(on);
        changed();
    });
    return group(tr("Tiles"), form);
}

QWidget* ScanPlanForm::runGroup()
{
    auto* form = new QFormLayout;
    m_speed = number(QStringLiteral("scanSpeed"), 0.01, 1000, 10, 2, tr(" mm/s"), tr("Path speed of the moves between tiles"));
    form->addRow(tr("Speed"), m_speed);
    m_settle = number(QStringLiteral("scanSettle"), 0, 60, 0.02, 3, tr(" s"), tr("Expected settling per tile, for the time estimate"));
    form->addRow(tr("Settle (estimate)"), m_settle);
    m_exposure = number(QStringLiteral("scanExposure"), 0, 3600, 0.05, 3, tr(" s"), tr("The stage dwells this long at each tile"));
    form->addRow(tr("Exposure"), m_exposure);
    m_tolerance = number(QStringLiteral("scanTolerance"), 0.1, 1000, 1, 2, tr(" µm"),
                         tr("A tile is taken once the grating reads this close to its target"));
    form->addRow(tr("Tolerance"), m_tolerance);
    m_settleTimeout = number(QStringLiteral("scanSettleTimeout"), 0.01, 600, 2, 2, tr(" s"),
                             tr("A tile not settled by then stops the run with the reason"));
    form->addRow(tr("Settle timeout"), m_settleTimeout);
    m_compensate = new QCheckBox(tr("Use the stage's own compensation"));
    m_compensate->setObjectName(QStringLiteral("scanCompensate"));
    m_compensate->setToolTip(tr("Runs only when the stage has its error compensation enabled on X and Y: the stage "
                                "moves each target so the work point lands on it. Measure and upload it on the "
                                "Calibration screen."));
    connect(m_compensate, &QCheckBox::toggled, this, &ScanPlanForm::changed);
    form->addRow(m_compensate);
    return group(tr("Run"), form);
}

QWidget* ScanPlanForm::exportGroup()
{
    auto* form = new QFormLayout;
    m_pattern = new QLineEdit;
    m_pattern->setObjectName(QStringLiteral("scanPattern"));
    m_pattern->setToolTip(tr("{i} the tile's number, {row} and {col} its place; {i:03} pads to three digits"));
    connect(m_pattern, &QLineEdit::editingFinished, this, &ScanPlanForm::changed);
    form->addRow(tr("File names"), m_pattern);
    m_firstIndex = new NumberField;
    m_firstIndex->setObjectName(QStringLiteral("scanFirstIndex"));
    m_firstIndex->setInteger(true);
    m_firstIndex->setRange(0, 1000000);
    connect(m_firstIndex, &NumberField::entryChanged, this, &ScanPlanForm::changed);
    form->addRow(tr("First number"), m_firstIndex);
    m_mmStage = new QLineEdit;
    m_mmStage->setToolTip(tr("The XY stage's device label in Micro-Manager (for the .pos position list)"));
    connect(m_mmStage, &QLineEdit::editingFinished, this, &ScanPlanForm::changed);
    form->addRow(tr("Micro-Manager stage"), m_mmStage);
    return group(tr("Export"), form);
}

void ScanPlanForm::changed()
{
    if (m_loading)
        return;
    updateCameraInfo();
    emit planChanged();
}

void ScanPlanForm::updateCameraInfo()
{
    const ScanPlan p = plan();
    if (!std::isfinite(fieldWidthMm(p.camera)) || !std::isfinite(fieldHeightMm(p.camera)) || !std::isfinite(pixelAtSampleUm(p.camera))) {
        m_cameraInfo->setText(tr("Field: — (a camera value above is not a number yet)"));
        return;
    }
    QString info = tr("Field %1 × %2 mm, %3 µm per pixel at the sample")
                       .arg(fieldWidthMm(p.camera), 0, 'f', 4)
                       .arg(fieldHeightMm(p.camera), 0, 'f', 4)
                       .arg(pixelAtSampleUm(p.camera), 0, 'g', 4);
    // The profile's geometry replaces the fields above each time the plan is opened.
    if (!m_cameraProfile.empty())
        info += QLatin1Char('\n') + tr("Pixel size, rotation and image rows come from the camera profile %1 when the plan is opened")
                                        .arg(QString::fromStdString(m_cameraProfile));
    m_cameraInfo->setText(info);
}

ScanPlan ScanPlanForm::plan() const
{
    ScanPlan p;
    p.name = m_name->text().toStdString();
    p.region.kind = static_cast<RegionKind>(m_regionKind->currentData().toInt());
    p.region.cornerA = {m_x0->valueOr(kScanFormNaN), m_y0->valueOr(kScanFormNaN)};
    p.region.cornerB = {m_x1->valueOr(kScanFormNaN), m_y1->valueOr(kScanFormNaN)};
    p.region.centre = {m_cx->valueOr(kScanFormNaN), m_cy->valueOr(kScanFormNaN)};
    p.region.widthMm = m_w->valueOr(kScanFormNaN);
    p.region.heightMm = m_h->valueOr(kScanFormNaN);
    QString error;
    p.region.vertices = parsePolygon(m_vertices->text(), &error);
    m_polygonError = p.region.kind == RegionKind::Polygon ? error : QString();
    p.camera.source = static_cast<FieldSource>(m_fovFrom->currentData().toInt());
    p.camera.sensorWidthPx = static_cast<int>(m_sensorW->valueOr(0));
    p.camera.sensorHeightPx = static_cast<int>(m_sensorH->valueOr(0));
    p.camera.sensorPixelUm = m_sensorPixel->valueOr(kScanFormNaN);
    p.camera.magnification = m_magnification->valueOr(kScanFormNaN);
    p.camera.fieldWidthMm = m_fieldW->valueOr(kScanFormNaN);
    p.camera.fieldHeightMm = m_fieldH->valueOr(kScanFormNaN);
    p.camera.samplePixelUm = m_samplePixel->valueOr(kScanFormNaN);
    p.camera.rotationDeg = m_rotation->valueOr(kScanFormNaN);
    p.camera.imageY = static_cast<ImageY>(m_imageY->currentData().toInt());
    p.camera.profile = m_cameraProfile;
    p.overlapX = m_overlapX->valueOr(kScanFormNaN) / 100.0;
    p.overlapY = m_overlapY->valueOr(kScanFormNaN) / 100.0;
    p.order = static_cast<ScanOrder>(m_order->currentData().toInt());
    p.start = static_cast<StartCorner>(m_start->currentData().toInt());
    p.approach.unidirectional = m_unidirectional->isChecked();
    p.approach.overtravelMm = m_overtravel->valueOr(kScanFormNaN);
    p.speedMmS = m_speed->valueOr(kScanFormNaN);
    p.settleS = m_settle->valueOr(kScanFormNaN);
    p.exposureS = m_exposure->valueOr(kScanFormNaN);
    p.toleranceUm = m_tolerance->valueOr(kScanFormNaN);
    p.settleTimeoutS = m_settleTimeout->valueOr(kScanFormNaN);
    p.compensation.enabled = m_compensate->isChecked();
    p.naming.filePattern = m_pattern->text().toStdString();
    p.naming.firstIndex = static_cast<int>(m_firstIndex->valueOr(0));
    p.naming.mmXyStage = m_mmStage->text().toStdString();
    return p;
}

void ScanPlanForm::setPlan(const ScanPlan& p)
{
    m_loading = true;
    m_name->setText(QString::fromStdString(p.name));
    m_regionKind->setCurrentIndex(m_regionKind->findData(int(p.region.kind)));
    m_regionPages->setCurrentIndex(m_regionKind->currentIndex());
    m_x0->setValue(p.region.cornerA.xMm);
    m_y0->setValue(p.region.cornerA.yMm);
    m_x1->setValue(p.region.cornerB.xMm);
    m_y1->setValue(p.region.cornerB.yMm);
    m_cx->setValue(p.region.centre.xMm);
    m_cy->setValue(p.region.centre.yMm);
    m_w->setValue(p.region.widthMm);
    m_h->setValue(p.region.heightMm);
    m_vertices->setText(polygonText(p.region.vertices));
    m_fovFrom->setCurrentIndex(m_fovFrom->findData(int(p.camera.source)));
    m_cameraPages->setCurrentIndex(m_fovFrom->currentIndex());
    m_sensorW->setValue(p.camera.sensorWidthPx);
    m_sensorH->setValue(p.camera.sensorHeightPx);
    m_sensorPixel->setValue(p.camera.sensorPixelUm);
    m_magnification->setValue(p.camera.magnification);
    m_fieldW->setValue(p.camera.fieldWidthMm);
    m_fieldH->setValue(p.camera.fieldHeightMm);
    m_samplePixel->setValue(p.camera.samplePixelUm);
    m_rotation->setValue(p.camera.rotationDeg);
    m_imageY->setCurrentIndex(m_imageY->findData(int(p.camera.imageY)));
    m_cameraProfile = p.camera.profile;
    m_overlapX->setValue(p.overlapX * 100);
    m_overlapY->setValue(p.overlapY * 100);
    m_order->setCurrentIndex(m_order->findData(int(p.order)));
    m_start->setCurrentIndex(m_start->findData(int(p.start)));
    m_unidirectional->setChecked(p.approach.unidirectional);
    m_overtravel->setValue(p.approach.overtravelMm);
    m_overtravel->setEnabled(p.approach.unidirectional);
    m_speed->setValue(p.speedMmS);
    m_settle->setValue(p.settleS);
    m_exposure->setValue(p.exposureS);
    m_tolerance->setValue(p.toleranceUm);
    m_settleTimeout->setValue(p.settleTimeoutS);
    m_compensate->setChecked(p.compensation.enabled);
    m_pattern->setText(QString::fromStdString(p.naming.filePattern));
    m_firstIndex->setValue(p.naming.firstIndex);
    m_mmStage->setText(QString::fromStdString(p.naming.mmXyStage));
    m_loading = false;
    updateCameraInfo();
    emit regionKindChanged(p.region.kind);
    emit planChanged();
}

} // namespace ui
